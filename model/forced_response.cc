#include "model/forced_response.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>

namespace ringid {

Eigen::Matrix<double, kNumDofs, kNumLugForces> LugForceColumns(const Parameters& p) {
  Eigen::Matrix<double, kNumDofs, kNumLugForces> B = decltype(B)::Zero();
  auto at = [&](Dof d, LugForce f) -> double& { return B(static_cast<int>(d), static_cast<int>(f)); };
  at(Dof::kXb, LugForce::kFx) = 1;
  at(Dof::kThetaB, LugForce::kFx) = -p[Param::r_e0];
  at(Dof::kZb, LugForce::kFz) = 1;
  at(Dof::kYb, LugForce::kFy) = 1;
  at(Dof::kGammaB, LugForce::kFy) = -p[Param::r_l0];
  at(Dof::kPsiB, LugForce::kFy) = -p[Param::t_0];
  return B;
}

std::vector<int> ActiveDofs(const MechanicalSystem& s) {
  std::vector<int> dofs;
  for (int d = 0; d < kNumDofs; ++d) {
    if (s.active(static_cast<Dof>(d))) dofs.push_back(d);
  }
  return dofs;
}

Eigen::MatrixXcd DynamicStiffness(const MechanicalSystem& s, const std::vector<int>& dofs,
                                  Complex lambda) {
  const int k = static_cast<int>(dofs.size());
  Eigen::MatrixXcd D(k, k);
  for (int a = 0; a < k; ++a) {
    for (int b = 0; b < k; ++b) {
      D(a, b) = lambda * lambda * s.M()(dofs[a], dofs[b]) + lambda * s.C()(dofs[a], dofs[b]) +
                s.K()(dofs[a], dofs[b]);
    }
  }
  if (!(s.speed() > 0)) return D;  // K holds each lag's standstill stiffness
  // Rolling, eq. (R8): sigma zeta' + V zeta = -d^T q' + V e^T q gives
  // zeta = (V e - lambda d)^T q / (sigma lambda + V), whose force K_c zeta f
  // replaces the standstill stiffness (K_c / sigma) f d^T that K holds.
  auto index = [&](Dof d) {
    for (int a = 0; a < k; ++a) {
      if (dofs[a] == static_cast<int>(d)) return a;
    }
    return -1;
  };
  const double V = s.speed();
  for (const auto& lag : s.lags()) {
    const Complex lag_gain = lag.stiffness / (lag.relaxation_length * lambda + V);
    for (const auto& [row_dof, f] : lag.force) {
      const int a = index(row_dof);
      if (a < 0) continue;
      for (const auto& [col_dof, d] : lag.velocity) {
        const int b = index(col_dof);
        if (b < 0) continue;
        D(a, b) -= lag.stiffness / lag.relaxation_length * f * d;  // the standstill term out
        D(a, b) -= lag_gain * f * (-lambda * d);
      }
      for (const auto& [col_dof, e] : lag.heading) {
        const int b = index(col_dof);
        if (b >= 0) D(a, b) -= lag_gain * f * (V * e);
      }
    }
  }
  return D;
}

bool AxleResponse(const RigidRingModel& model, const Parameters& p, double speed_m_s,
                  double frequency_hz, AxleResponseMatrix* H, std::string* why) {
  if (!(frequency_hz > 0) || !std::isfinite(frequency_hz)) {
    *why = "the frequency must be positive";
    return false;
  }
  if (!(speed_m_s >= 0) || !std::isfinite(speed_m_s)) {
    *why = "the speed must be finite and not negative";
    return false;
  }
  for (Param q : model.parameters()) {
    if (!std::isfinite(p[q])) {
      *why = std::string("parameter ") + ParamName(q) + " is not finite";
      return false;
    }
  }
  const MechanicalSystem s = model.Assemble(p, speed_m_s);
  const std::vector<int> dofs = ActiveDofs(s);
  const int k = static_cast<int>(dofs.size());
  const Complex lambda(0, 2 * M_PI * frequency_hz);
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(DynamicStiffness(s, dofs, lambda));
  // A singular D: the response is unbounded (or the solve meaningless).
  const double rcond = lu.rcond();
  if (!(rcond > 1e-14)) {
    *why = "the dynamic stiffness is singular there (an undamped resonance)";
    return false;
  }
  const auto B_all = LugForceColumns(p);
  Eigen::MatrixXcd B(k, kNumLugForces);
  for (int a = 0; a < k; ++a) B.row(a) = B_all.row(dofs[a]).cast<Complex>();
  const Eigen::MatrixXcd q = lu.solve(B);  // k x 3 receptance times B
  const auto G_d = s.axle_displacement();
  const auto G_v = s.axle_velocity();
  Eigen::MatrixXcd G(kNumAxleChannels, k);
  for (int a = 0; a < k; ++a) {
    G.col(a) = G_d.col(dofs[a]).cast<Complex>() + lambda * G_v.col(dofs[a]).cast<Complex>();
  }
  *H = G * q;
  if (!H->allFinite()) {
    *why = "the response is not finite";
    return false;
  }
  return true;
}

double ModelValidBelowHz(const RigidRingModel& model, const Parameters& p) {
  const ModalSolution s = model.Solve(p);
  double highest = 0;
  for (const Mode& m : s.modes) {
    if (LabelPlane(m.label) != Plane::kHub) highest = std::max(highest, m.frequency_hz);
  }
  return s.ok && highest > 0 ? kModelRangeFactor * highest : NAN;
}

}  // namespace ringid
