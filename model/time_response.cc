#include "model/time_response.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <Eigen/LU>
#include <Eigen/QR>
#include <unsupported/Eigen/MatrixFunctions>

namespace ringid {
namespace {

constexpr int kInputs = 3;  // F_x on x_b, F_z on z_b, F_y on y_b
constexpr Dof kInputDofs[kInputs] = {Dof::kXb, Dof::kZb, Dof::kYb};

// The exact first-order-hold step of one length dt: x_{k+1} = Phi x_k +
// G0 u_k + G1 (u_{k+1} - u_k) / dt, the three side by side in `step`.
struct HeldStep {
  double dt = 0;
  Eigen::MatrixXd step;  // [Phi, G0, G1]: the top rows of exp(F dt)
};

HeldStep Discretise(const StateSpace& s, double dt) {
  const Eigen::Index n = s.A.rows(), m = s.B.cols();
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(n + 2 * m, n + 2 * m);
  F.topLeftCorner(n, n) = s.A;
  F.block(0, n, n, m) = s.B;
  F.block(n, n + m, m, m).setIdentity();
  const Eigen::MatrixXd E = (F * dt).exp();
  return {dt, E.topRows(n)};
}

}  // namespace

bool RollingStateSpace(const RigidRingModel& model, const Parameters& p, double speed_m_s,
                       StateSpace* out, std::string* why) {
  const MechanicalSystem s = model.Assemble(p, speed_m_s);
  std::vector<int> dofs;
  std::array<int, kNumDofs> row;
  row.fill(-1);
  for (int d = 0; d < kNumDofs; ++d) {
    if (!s.active(static_cast<Dof>(d))) continue;
    row[d] = static_cast<int>(dofs.size());
    dofs.push_back(d);
  }
  const int n = static_cast<int>(dofs.size());
  const bool rolling = speed_m_s > 0;
  const int lags = rolling ? static_cast<int>(s.lags().size()) : 0;
  const auto on = [&](const MechanicalSystem::Matrix& full) {
    Eigen::MatrixXd m(n, n);
    for (int a = 0; a < n; ++a) {
      for (int b = 0; b < n; ++b) m(a, b) = full(dofs[a], dofs[b]);
    }
    return m;
  };
  const Eigen::MatrixXd M = on(s.M()), C = on(s.C());
  Eigen::MatrixXd K = on(s.K());
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(M);
  if (!lu.isInvertible()) {
    *why = "the mass matrix is singular: the response over time needs a mass on every coordinate";
    return false;
  }
  const Eigen::MatrixXd Minv = lu.inverse();
  // The lags' rows over the active coordinates: f, d, e (docs/rolling.md).
  const auto vector_of = [&](const MechanicalSystem::Combination& c) {
    Eigen::VectorXd v = Eigen::VectorXd::Zero(n);
    for (const auto& term : c) {
      if (row[static_cast<int>(term.dof)] >= 0) v[row[static_cast<int>(term.dof)]] += term.coef;
    }
    return v;
  };
  StateSpace& ss = *out;
  const int states = 2 * n + lags;
  ss.A = Eigen::MatrixXd::Zero(states, states);
  Eigen::MatrixXd coupling = Eigen::MatrixXd::Zero(n, lags);  // sum K f zeta
  for (int l = 0; l < lags; ++l) {
    const auto& lag = s.lags()[l];
    const Eigen::VectorXd f = vector_of(lag.force), d = vector_of(lag.velocity),
                          e = vector_of(lag.heading);
    K -= lag.stiffness / lag.relaxation_length * f * d.transpose();  // the standstill stand-in
    coupling.col(l) = lag.stiffness * f;
    const int z = 2 * n + l;
    ss.A.block(z, 0, 1, n) = speed_m_s / lag.relaxation_length * e.transpose();
    ss.A.block(z, n, 1, n) = -d.transpose() / lag.relaxation_length;
    ss.A(z, z) = -speed_m_s / lag.relaxation_length;
  }
  ss.A.block(0, n, n, n).setIdentity();
  ss.A.block(n, 0, n, n) = -Minv * K;
  ss.A.block(n, n, n, n) = -Minv * C;
  if (lags > 0) ss.A.block(n, 2 * n, n, lags) = Minv * coupling;
  ss.B = Eigen::MatrixXd::Zero(states, kInputs);
  for (int i = 0; i < kInputs; ++i) {
    const int a = row[static_cast<int>(kInputDofs[i])];
    if (a >= 0) ss.B.block(n, i, n, 1) = Minv.col(a);
  }
  ss.C = Eigen::MatrixXd::Zero(kNumTimeOutputs, states);
  const auto G_d = s.axle_displacement();
  const auto G_v = s.axle_velocity();
  for (int c = 0; c < kNumAxleChannels; ++c) {
    for (int a = 0; a < n; ++a) {
      ss.C(c, a) = G_d(c, dofs[a]);
      ss.C(c, n + a) = G_v(c, dofs[a]);
    }
  }
  ss.C(kRimSpeedOutput, n + row[static_cast<int>(Dof::kThetaA)]) = 1;
  ss.z_b = Eigen::RowVectorXd::Zero(states);
  ss.z_b(row[static_cast<int>(Dof::kZb)]) = 1;
  return true;
}

Eigen::MatrixXd SimulateHeld(const StateSpace& s, const std::vector<double>& t,
                             const Eigen::MatrixXd& u, const Eigen::VectorXd& x0) {
  const Eigen::Index T = static_cast<Eigen::Index>(t.size());
  Eigen::MatrixXd y(s.C.rows(), T);
  const Eigen::Index n = s.A.rows(), m = s.B.cols();
  Eigen::VectorXd z(n + 2 * m);  // [x_k, u_k, (u_{k+1} - u_k) / dt]
  z.head(n) = x0.size() ? x0 : Eigen::VectorXd::Zero(n);
  Eigen::VectorXd next(n);
  std::optional<HeldStep> step;
  for (Eigen::Index k = 0; k < T; ++k) {
    y.col(k).noalias() = s.C * z.head(n);
    if (k + 1 == T) break;
    const double dt = t[k + 1] - t[k];
    // Steps equal to 1e-9 of their length (a grid's rounding) share one.
    if (!step || std::abs(dt - step->dt) > 1e-9 * dt) step = Discretise(s, dt);
    z.segment(n, m) = u.col(k);
    z.tail(m) = (u.col(k + 1) - u.col(k)) / dt;
    next.noalias() = step->step * z;
    z.head(n) = next;
  }
  return y;
}

namespace {

// The grid through 0 and the sample times, no step longer than kTravelStep
// of travel where X = x0 + V t lies within `reach` (Reach: elsewhere the
// forces are 0 and a step of any length is exact); `sample` the grid index
// of each sample time.
std::vector<double> TravelGrid(const std::vector<double>& times, double speed, double x0,
                               std::pair<double, double> reach, std::vector<size_t>* sample) {
  std::vector<double> grid = {0.0};
  const auto fine = [&](double from, double to) {  // (from, to] in <= kTravelStep steps
    // (a step of exactly kTravelStep, to rounding, is one)
    const long steps =
        std::max(1L, static_cast<long>(std::ceil(speed * (to - from) / kTravelStep - 1e-9)));
    for (long k = 1; k <= steps; ++k) {
      grid.push_back(k == steps ? to : from + (to - from) * static_cast<double>(k) / steps);
    }
  };
  // The times at which X enters and leaves the reach, a step early and late:
  // at its edge H may jump (a cam's tip on an obstacle above b_e), and the
  // held forces must ramp to it over one fine step from a point where they
  // are 0.
  const double enter = (reach.first - kTravelStep - x0) / speed,
               leave = (reach.second + kTravelStep - x0) / speed;
  for (double t : times) {
    const double from = grid.back();
    if (t > from) {
      const double a = std::clamp(enter, from, t), b = std::clamp(leave, from, t);
      if (a > from) grid.push_back(a);  // flat before: one step
      if (b > a) fine(a, b);
      if (t > grid.back()) grid.push_back(t);  // flat after: one step
    }
    sample->push_back(grid.size() - 1);
  }
  return grid;
}

// The forces of §11 on the grid.
Eigen::MatrixXd Forces(const Parameters& p, const ObstacleRun& run,
                       const std::vector<double>& grid) {
  Eigen::MatrixXd u(kInputs, grid.size());
  const std::vector<Lane> lanes = LanesOf(run.profile);
  for (size_t k = 0; k < grid.size(); ++k) {
    const EffectiveInput e =
        Effective(run.profile, run.cam, lanes, run.position_at_t0_m + run.speed_m_s * grid[k]);
    u.col(k) << -p[Param::F_cz0] * e.beta, -p[Param::k_cz] * e.w, -p[Param::F_cz0] * e.beta_x;
  }
  return u;
}

// The state at t = 0 of the periodic steady state under the lugs' forces
// less their mean (subtracted from u): one pitch of travel on a grid of
// equal steps, x(T) = Phi_T x(0) + x_forced solved by least squares (the
// rim's free angle makes I - Phi_T singular; it reaches no output).
Eigen::VectorXd PeriodicStart(const StateSpace& s, const Parameters& p, const ObstacleRun& run,
                              Eigen::MatrixXd* u_mean) {
  const double period = run.profile.pitch_m / run.speed_m_s;
  const int steps =
      std::max(8, static_cast<int>(std::ceil(run.profile.pitch_m / kTravelStep - 1e-9)));
  std::vector<double> grid;
  for (int k = 0; k <= steps; ++k) grid.push_back(period * k / steps);
  Eigen::MatrixXd u = Forces(p, run, grid);
  *u_mean = u.leftCols(steps).rowwise().mean();  // the periodic trapezoid rule
  u.colwise() -= u_mean->col(0);
  const Eigen::Index n = s.A.rows();
  StateSpace whole = s;  // the state itself as the output
  whole.C = Eigen::MatrixXd::Identity(n, n);
  const Eigen::VectorXd x = SimulateHeld(whole, grid, u).col(steps);
  const Eigen::MatrixXd Phi_T = (s.A * period).exp();
  return (Eigen::MatrixXd::Identity(n, n) - Phi_T).completeOrthogonalDecomposition().solve(x);
}

}  // namespace

const char* TimeOutputName(int output) {
  return output == kRimSpeedOutput ? "rim_speed" : ToString(static_cast<AxleChannel>(output));
}

std::optional<int> ParseTimeOutput(const std::string& name) {
  for (int o = 0; o < kNumTimeOutputs; ++o) {
    if (name == TimeOutputName(o)) return o;
  }
  return std::nullopt;
}

std::string TimeOutputChoices() {
  std::string out;
  for (int o = 0; o < kNumTimeOutputs; ++o) out += (o ? ", " : "") + std::string(TimeOutputName(o));
  return out;
}

TandemCam CamOf(const Parameters& p) {
  return {p[Param::a_e], p[Param::b_e], p[Param::c_e], p[Param::l_s]};
}

bool ObstacleResponse(const RigidRingModel& model, const Parameters& p, const ObstacleRun& run,
                      ObstacleResult* r, std::string* why) {
  if (!(run.speed_m_s >= kSlowestRoll && run.speed_m_s <= kFastestRoll)) {
    *why = "speed_m_s: rolling over an obstacle needs a speed of 0.001 to 200 m/s";
    return false;
  }
  if (!(std::abs(run.position_at_t0_m) <= kFarthestX)) {
    *why = "position_at_t0_m: must lie within 10000 m of 0";
    return false;
  }
  if (!(p[Param::F_cz0] > 0) || !(p[Param::k_cz] > 0)) {
    *why = "F_cz0, k_cz: the load and the contact stiffness must be positive";
    return false;
  }
  if (const std::string bad = run.profile.Invalid(); !bad.empty()) {
    *why = "profile: " + bad;
    return false;
  }
  if (const std::string bad = run.cam.Invalid(); !bad.empty()) {
    *why = bad;
    return false;
  }
  for (size_t k = 0; k < run.times_s.size(); ++k) {
    if (!(run.times_s[k] >= 0) || !std::isfinite(run.times_s[k]) ||
        (k > 0 && !(run.times_s[k] > run.times_s[k - 1]))) {
      *why = "time_s: times must be finite, at least 0 and increasing";
      return false;
    }
  }
  if (!run.times_s.empty() && run.speed_m_s * run.times_s.back() / kTravelStep > kMostSteps) {
    *why = "time_s: the run rolls more than 10 km (10 million steps of 1 mm)";
    return false;
  }
  StateSpace s;
  if (!RollingStateSpace(model, p, run.speed_m_s, &s, why)) return false;
  std::vector<size_t> sample;
  const std::vector<double> grid = TravelGrid(run.times_s, run.speed_m_s, run.position_at_t0_m,
                                              Reach(run.profile, run.cam), &sample);
  const double work = PieceEvaluations(run.profile, run.cam) *
                      (static_cast<double>(grid.size()) +
                       (run.profile.kind == ProfileKind::kLugs ? run.profile.pitch_m / kTravelStep : 0));
  if (work > kMostPieceEvaluations) {
    *why = "profile: the cam would visit " + std::to_string(static_cast<long long>(work)) +
           " pieces of it over the run, more than 2e8: fewer lanes or points, a shorter run or "
           "a longer pitch";
    return false;
  }
  Eigen::MatrixXd u = Forces(p, run, grid);
  Eigen::RowVectorXd w = u.row(1) / -p[Param::k_cz];
  Eigen::VectorXd x0;
  const bool lugs = run.profile.kind == ProfileKind::kLugs;
  r->reaches_at_t0 = !lugs && run.position_at_t0_m > FirstContact(run.profile, run.cam);
  if (lugs) {
    Eigen::MatrixXd mean;
    x0 = PeriodicStart(s, p, run, &mean);
    u.colwise() -= mean.col(0);
    w.array() -= mean(1, 0) / -p[Param::k_cz];  // about the mean, as the response
  }
  StateSpace with_z_b = s;  // the outputs and z_b
  with_z_b.C.conservativeResize(kNumTimeOutputs + 1, Eigen::NoChange);
  with_z_b.C.row(kNumTimeOutputs) = s.z_b;
  const Eigen::MatrixXd all = SimulateHeld(with_z_b, grid, u, x0);
  r->y.resize(kNumTimeOutputs, static_cast<Eigen::Index>(sample.size()));
  for (size_t k = 0; k < sample.size(); ++k) {
    r->y.col(static_cast<Eigen::Index>(k)) = all.col(sample[k]).head(kNumTimeOutputs);
  }
  r->lowest_contact_force_n = INFINITY;
  r->largest_load_change = -1;
  for (size_t k = 0; k < grid.size(); ++k) {
    const double change = p[Param::k_cz] * (all(kNumTimeOutputs, k) + w[k]);
    if (p[Param::F_cz0] + change < r->lowest_contact_force_n) {
      r->lowest_contact_force_n = p[Param::F_cz0] + change;
      r->lowest_at_s = grid[k];
    }
    if (std::abs(change) / p[Param::F_cz0] > r->largest_load_change) {
      r->largest_load_change = std::abs(change) / p[Param::F_cz0];
      r->largest_at_s = grid[k];
    }
  }
  return true;
}

}  // namespace ringid
