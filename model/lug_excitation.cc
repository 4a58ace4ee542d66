#include "model/lug_excitation.h"

#include <cmath>

#include <Eigen/Dense>

namespace ringid {

bool LugExcitationOf(const RigidRingModel& model, const Parameters& p,
                     const ObstacleProfile& lugs, double speed_m_s, int max_order,
                     LugExcitation* out, std::string* why) {
  *out = LugExcitation{};
  if (lugs.kind != ProfileKind::kLugs) return *why = "profile: must be lugs", false;
  if (const std::string bad = lugs.Invalid(); !bad.empty()) return *why = "profile: " + bad, false;
  const TandemCam cam = CamOf(p);
  if (const std::string bad = cam.Invalid(); !bad.empty()) return *why = bad, false;
  if (!(speed_m_s >= kSlowestRoll && speed_m_s <= kFastestRoll)) {
    return *why = "speed_m_s: the lugs roll at 0.001 to 200 m/s", false;
  }
  if (max_order < 1 || max_order > kMaxOrders) return *why = "max_order: 1 to 200", false;
  StateSpace s;
  if (!RollingStateSpace(model, p, speed_m_s, &s, why)) return false;
  const double P = lugs.pitch_m;
  const int n = std::max(kLugSamples, static_cast<int>(std::ceil(4 * P / kTravelStep)));  // P <= 10 m
  if (const double work = n * PieceEvaluations(lugs, cam); work > kMostPieceEvaluations) {
    *why = "profile: the cam would visit " + std::to_string(static_cast<long long>(work)) +
           " pieces of it over a pitch, more than 2e8: fewer lanes or a longer pitch";
    return false;
  }
  const std::vector<Lane> lanes = LanesOf(lugs);
  // u(X) at n points over one pitch; the series by the periodic trapezoid rule.
  Eigen::MatrixXd u(3, n);
  for (int j = 0; j < n; ++j) {
    const EffectiveInput e = Effective(lugs, cam, lanes, P * j / n);
    u.col(j) << -p[Param::F_cz0] * e.beta, -p[Param::k_cz] * e.w, -p[Param::F_cz0] * e.beta_x;
  }
  out->speed_m_s = speed_m_s;
  const Eigen::Vector3d mean = u.rowwise().mean();
  for (int i = 0; i < 3; ++i) out->mean_force[i] = mean[i];
  const Eigen::Index m = s.A.rows();
  for (int k = 1; k <= max_order; ++k) {
    LugOrderExcitation o;
    o.order = k;
    o.frequency_hz = k * speed_m_s / P;
    Eigen::Vector3cd f = Eigen::Vector3cd::Zero();
    for (int j = 0; j < n; ++j) {
      f += u.col(j).cast<std::complex<double>>() * std::polar(2.0 / n, -2 * M_PI * k * j / n);
    }
    const std::complex<double> iw(0, 2 * M_PI * o.frequency_hz);
    const Eigen::MatrixXcd Z = iw * Eigen::MatrixXcd::Identity(m, m) - s.A.cast<std::complex<double>>();
    const Eigen::VectorXcd y =
        s.C.cast<std::complex<double>>() * Z.partialPivLu().solve(s.B.cast<std::complex<double>>() * f);
    for (int i = 0; i < 3; ++i) o.force[i] = f[i];
    for (int c = 0; c < kNumTimeOutputs; ++c) o.response[c] = y[c];
    out->orders.push_back(o);
  }
  return true;
}

}  // namespace ringid
