#include "model/static_stiffness.h"

#include <array>
#include <cmath>
#include <vector>

#include <Eigen/LU>

namespace ringid {

StaticStiffnessResult StaticStiffness(const ModalModel& model, const Parameters& p,
                                      StaticDirection direction, bool derivatives) {
  using Jet = ParameterJet;
  using JetMatrix = Eigen::Matrix<Jet, Eigen::Dynamic, Eigen::Dynamic>;
  using JetVector = Eigen::Matrix<Jet, Eigen::Dynamic, 1>;
  StaticStiffnessResult r;
  const std::string what = std::string("the static ") + ToString(direction) + " stiffness";
  for (Param q : model.parameters()) {
    if (!std::isfinite(p[q])) {
      r.error = std::string("parameter ") + ParamName(q) + " is not finite";
      return r;
    }
  }
  const BasicSystem<Jet> s = model.Assemble(Seeded(p), 0);
  // The axle held in translation (inactive hub dofs stay out), the rim
  // locked in rotation: every active dof but theta_a (contract §10).
  std::array<int, kNumDofs> at;
  at.fill(-1);
  int n = 0;
  for (int d = 0; d < kNumDofs; ++d) {
    if (s.active(static_cast<Dof>(d)) && static_cast<Dof>(d) != Dof::kThetaA) at[d] = n++;
  }
  JetMatrix K(n, n);
  for (int a = 0; a < kNumDofs; ++a) {
    for (int b = 0; b < kNumDofs; ++b) {
      if (at[a] >= 0 && at[b] >= 0) K(at[a], at[b]) = s.K()(a, b);
    }
  }
  // The road moved by delta: each contact element i of the direction puts
  // k_i f_i delta on q and carries k_i (delta - d_i^T q), so with
  // g = sum k_i f_i, h = sum k_i d_i the road's force per unit delta is
  // sum k_i - h^T K^-1 g (K holds every k_i f_i d_i^T).
  JetVector g = JetVector::Constant(n, Jet(0.0)), h = JetVector::Constant(n, Jet(0.0));
  Jet k(0.0);
  bool found = false;
  for (const auto& c : s.contacts()) {
    if (c.direction != direction) continue;
    found = true;
    k += c.stiffness;
    for (const auto& [dof, coef] : c.force) {
      if (at[static_cast<int>(dof)] >= 0) g(at[static_cast<int>(dof)]) += c.stiffness * coef;
    }
    for (const auto& [dof, coef] : c.displacement) {
      if (at[static_cast<int>(dof)] >= 0) h(at[static_cast<int>(dof)]) += c.stiffness * coef;
    }
  }
  if (!found) {
    r.error = what + ": the model has no contact element in that direction";
    return r;
  }
  Eigen::MatrixXd values(n, n);
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) values(a, b) = K(a, b).a;
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(values);  // rank-revealing, unlike PartialPivLU
  if (!lu.isInvertible() || !(lu.rcond() > 1e-14)) {
    r.error = what + ": the standing stiffness matrix with the rim locked (theta_a = 0) is "
                     "singular";
    return r;
  }
  const Jet F = k - h.dot(Eigen::PartialPivLU<JetMatrix>(K).solve(g));
  if (!std::isfinite(F.a) || (derivatives && !F.v.allFinite())) {
    r.error = what + " is not finite";
    return r;
  }
  r.ok = true;
  r.value = F.a;
  if (derivatives) r.derivative = F.v.transpose();
  return r;
}

}  // namespace ringid
