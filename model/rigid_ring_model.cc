#include "model/rigid_ring_model.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace ringid {

RigidRingModel::RigidRingModel(std::vector<const Effect*> effects)
    : effects_(std::move(effects)) {
  for (int i = 0; i < kNumParams; ++i) {
    if (Info(ParamAt(i)).group != Group::kEffect) used_.push_back(ParamAt(i));
  }
  for (const Effect* e : effects_) {
    for (Param p : e->parameters()) used_.push_back(p);
  }
  std::sort(used_.begin(), used_.end());
  used_.erase(std::unique(used_.begin(), used_.end()), used_.end());
}

std::vector<Param> RigidRingModel::parameters() const { return used_; }

MechanicalSystem RigidRingModel::Assemble(const Parameters& p) const {
  using L = ModeLabel;
  using P = Param;
  MechanicalSystem s;
  // In-plane, eq. (12): q = [x_b, z_b, theta_a, theta_b]. The sidewall acts
  // on belt minus hub (eqs. 1, 3); the hub is rigid unless an effect frees it.
  s.AddMass(Dof::kXb, p[P::m_b]);
  s.AddMass(Dof::kZb, p[P::m_b]);
  s.AddMass(Dof::kThetaA, p[P::I_ay]);
  s.AddMass(Dof::kThetaB, p[P::I_by]);
  s.AddDamper(p[P::c_bx], {{Dof::kXb, 1}, {Dof::kXa, -1}});
  s.AddDamper(p[P::c_bz], {{Dof::kZb, 1}, {Dof::kZa, -1}});
  s.AddDamper(p[P::c_btheta], {{Dof::kThetaB, 1}, {Dof::kThetaA, -1}});
  // Each spring is owned by the mode named after the element it deforms: the
  // in-phase rotation rolls the belt on its contact, shearing the sidewall.
  s.AddSpring(L::kRotationInPhase, p[P::k_bx], {{Dof::kXb, 1}, {Dof::kXa, -1}});
  s.AddSpring(L::kVertical, p[P::k_bz], {{Dof::kZb, 1}, {Dof::kZa, -1}});
  s.AddSpring(L::kVertical, p[P::k_cz], {{Dof::kZb, 1}});
  s.AddSpring(L::kRotationAntiPhase, p[P::k_btheta],
              {{Dof::kThetaB, 1}, {Dof::kThetaA, -1}});
  // Contact slip, eqs. (6), (8): K_cx / sigma_cx on x_b - r_e0 theta_b.
  s.AddSpring(L::kLongitudinal, p[P::K_cx] / p[P::sigma_cx],
              {{Dof::kXb, 1}, {Dof::kThetaB, -p[P::r_e0]}});

  // Out-of-plane, eq. (15) as corrected in docs/model.md: q = [y_b, gamma_b, psi_b].
  s.AddMass(Dof::kYb, p[P::m_b]);
  s.AddMass(Dof::kGammaB, p[P::I_bx]);
  s.AddMass(Dof::kPsiB, p[P::I_bz]);
  s.AddDamper(p[P::c_by], {{Dof::kYb, 1}, {Dof::kYa, -1}});
  s.AddDamper(p[P::c_bgamma], {{Dof::kGammaB, 1}});
  s.AddDamper(p[P::c_bpsi], {{Dof::kPsiB, 1}});
  const double kcy = p[P::K_cy] / p[P::sigma_cy];
  const double r_l0 = p[P::r_l0];
  const double t_0 = p[P::t_0];
  s.AddSpring(L::kLateral, p[P::k_by], {{Dof::kYb, 1}, {Dof::kYa, -1}});
  s.AddSpring(L::kLateral, kcy, {{Dof::kYb, 1}, {Dof::kGammaB, -r_l0}});
  s.AddSpring(L::kCamber, p[P::k_bgamma] + r_l0 * p[P::F_cz0],
              {{Dof::kGammaB, 1}});
  s.AddSpring(L::kYaw, p[P::k_bpsi], {{Dof::kPsiB, 1}});
  // The trail t_0 carries the lateral contact force onto yaw, one way only.
  s.AddStiffness(L::kLateral, Dof::kPsiB, Dof::kYb, -t_0 * kcy);
  s.AddStiffness(L::kLateral, Dof::kPsiB, Dof::kGammaB, r_l0 * t_0 * kcy);

  for (const Effect* e : effects_) e->Apply(p, &s);
  return s;
}

ModalSolution RigidRingModel::Solve(const Parameters& p) const {
  for (Param q : used_) {
    if (!std::isfinite(p[q])) {
      ModalSolution bad;
      bad.error = std::string("parameter ") + ParamName(q) + " is not finite";
      return bad;
    }
  }
  return SolveModes(Assemble(p));
}

bool RigidRingModel::Has(const Effect* effect) const {
  return std::find(effects_.begin(), effects_.end(), effect) != effects_.end();
}

RigidRingModel RigidRingModel::With(const Effect* effect) const {
  std::vector<const Effect*> effects = effects_;
  effects.push_back(effect);
  return RigidRingModel(effects);
}

}  // namespace ringid
