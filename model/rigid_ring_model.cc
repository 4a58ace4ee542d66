#include "model/rigid_ring_model.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>

namespace ringid {
namespace {

// The terms of steady rotation at Omega (docs/rolling.md, eqs. R3-R5): the
// sidewall damping turns with the wheel (circulatory stiffness), and the
// spinning belt is a gyroscope of polar inertia M(theta_b, theta_b), which
// includes what effects add to it.
template <class T>
void AddRolling(const T& c_bx, const T& c_bz, const T& c_bgamma, const T& c_bpsi,
                const T& omega, BasicSystem<T>* s) {
  // On the sidewall deformation (belt minus hub), eqs. (1), (3).
  auto circulate = [&](Dof row_b, Dof row_a, Dof col_b, Dof col_a, const T& v) {
    s->AddStiffness(std::nullopt, row_b, col_b, v);
    s->AddStiffness(std::nullopt, row_b, col_a, -v);
    s->AddStiffness(std::nullopt, row_a, col_b, -v);
    s->AddStiffness(std::nullopt, row_a, col_a, v);
  };
  circulate(Dof::kXb, Dof::kXa, Dof::kZb, Dof::kZa, c_bz * omega);
  circulate(Dof::kZb, Dof::kZa, Dof::kXb, Dof::kXa, -c_bx * omega);
  s->AddStiffness(std::nullopt, Dof::kGammaB, Dof::kPsiB, c_bpsi * omega);
  s->AddStiffness(std::nullopt, Dof::kPsiB, Dof::kGammaB, -c_bgamma * omega);
  // What the axle carries of them (contract §8).
  s->AddToAxle(AxleChannel::kForceX, c_bz * omega, {{Dof::kZb, 1}, {Dof::kZa, -1}});
  s->AddToAxle(AxleChannel::kForceZ, -c_bx * omega, {{Dof::kXb, 1}, {Dof::kXa, -1}});
  s->AddToAxle(AxleChannel::kMomentX, c_bpsi * omega, {{Dof::kPsiB, 1}});
  s->AddToAxle(AxleChannel::kMomentZ, -c_bgamma * omega, {{Dof::kGammaB, 1}});
  const T spin = s->M()(static_cast<int>(Dof::kThetaB), static_cast<int>(Dof::kThetaB));
  s->AddVelocityCoupling(Dof::kGammaB, Dof::kPsiB, spin * omega);
  s->AddVelocityCoupling(Dof::kPsiB, Dof::kGammaB, -spin * omega);
}

// p with every value rounded to `bits` bits of mantissa: nearby points share
// it, and it depends on p alone (docs/rolling.md §5).
Parameters Anchor(const Parameters& p, int bits) {
  Parameters a = p;
  for (int i = 0; i < kNumParams; ++i) {
    if (!std::isfinite(p[ParamAt(i)])) continue;  // unset (NaN), or refused by Solve
    int exponent = 0;
    const double mantissa = std::frexp(p[ParamAt(i)], &exponent);
    a[ParamAt(i)] = std::ldexp(std::round(std::ldexp(mantissa, bits)), exponent - bits);
  }
  return a;
}

// Eqs. (12) and (15) as corrected in docs/model.md, then each effect, then
// the terms of rolling (docs/rolling.md); P is Parameters or a ParameterArray.
template <class T, class P>
BasicSystem<T> AssembleAny(const std::vector<const Effect*>& effects, const P& p, double speed) {
  using L = ModeLabel;
  using Q = Param;
  BasicSystem<T> s;
  // In-plane, eq. (12): q = [x_b, z_b, theta_a, theta_b]. The sidewall acts
  // on belt minus hub (eqs. 1, 3); the hub is rigid unless an effect frees it.
  s.AddMass(Dof::kXb, p[Q::m_b]);
  s.AddMass(Dof::kZb, p[Q::m_b]);
  s.AddMass(Dof::kThetaA, p[Q::I_ay]);
  s.AddMass(Dof::kThetaB, p[Q::I_by]);
  s.AddDamper(p[Q::c_bx], {{Dof::kXb, 1}, {Dof::kXa, -1}});
  s.AddDamper(p[Q::c_bz], {{Dof::kZb, 1}, {Dof::kZa, -1}});
  s.AddDamper(p[Q::c_btheta], {{Dof::kThetaB, 1}, {Dof::kThetaA, -1}});
  // Each spring is owned by the mode named after the element it deforms: the
  // in-phase rotation rolls the belt on its contact, shearing the sidewall.
  s.AddSpring(L::kRotationInPhase, p[Q::k_bx], {{Dof::kXb, 1}, {Dof::kXa, -1}});
  s.AddSpring(L::kVertical, p[Q::k_bz], {{Dof::kZb, 1}, {Dof::kZa, -1}});
  // The contact's residual stiffness k_cz on z_b, belt to road (eq. (12)).
  s.AddContact(L::kVertical, {StaticDirection::kVertical, p[Q::k_cz], {{Dof::kZb, 1}},
                              {{Dof::kZb, 1}}});
  s.AddSpring(L::kRotationAntiPhase, p[Q::k_btheta],
              {{Dof::kThetaB, 1}, {Dof::kThetaA, -1}});
  // The sidewall joins belt and hub: what the held axle carries (contract §8).
  s.AddToAxle(AxleChannel::kForceX, p[Q::k_bx], {{Dof::kXb, 1}, {Dof::kXa, -1}});
  s.AddToAxle(AxleChannel::kForceZ, p[Q::k_bz], {{Dof::kZb, 1}, {Dof::kZa, -1}});
  s.AddToAxleDamping(AxleChannel::kForceX, p[Q::c_bx], {{Dof::kXb, 1}, {Dof::kXa, -1}});
  s.AddToAxleDamping(AxleChannel::kForceZ, p[Q::c_bz], {{Dof::kZb, 1}, {Dof::kZa, -1}});
  // Contact slip, eqs. (6), (8): K_cx / sigma_cx on x_b - r_e0 theta_b.
  const typename BasicSystem<T>::Combination slip_x = {{Dof::kXb, 1},
                                                       {Dof::kThetaB, -p[Q::r_e0]}};
  s.AddSlipLag({L::kLongitudinal, StaticDirection::kLongitudinal, p[Q::K_cx], p[Q::sigma_cx],
                slip_x, slip_x, {}});

  // Out-of-plane, eq. (15) as corrected in docs/model.md: q = [y_b, gamma_b, psi_b].
  s.AddMass(Dof::kYb, p[Q::m_b]);
  s.AddMass(Dof::kGammaB, p[Q::I_bx]);
  s.AddMass(Dof::kPsiB, p[Q::I_bz]);
  s.AddDamper(p[Q::c_by], {{Dof::kYb, 1}, {Dof::kYa, -1}});
  s.AddDamper(p[Q::c_bgamma], {{Dof::kGammaB, 1}});
  s.AddDamper(p[Q::c_bpsi], {{Dof::kPsiB, 1}});
  const T r_l0 = p[Q::r_l0];
  s.AddSpring(L::kLateral, p[Q::k_by], {{Dof::kYb, 1}, {Dof::kYa, -1}});
  s.AddSpring(L::kCamber, p[Q::k_bgamma] + r_l0 * p[Q::F_cz0], {{Dof::kGammaB, 1}});
  s.AddSpring(L::kYaw, p[Q::k_bpsi], {{Dof::kPsiB, 1}});
  s.AddToAxle(AxleChannel::kForceY, p[Q::k_by], {{Dof::kYb, 1}, {Dof::kYa, -1}});
  s.AddToAxle(AxleChannel::kMomentX, p[Q::k_bgamma], {{Dof::kGammaB, 1}});  // not r_l0 F_cz0: the contact's
  s.AddToAxle(AxleChannel::kMomentZ, p[Q::k_bpsi], {{Dof::kPsiB, 1}});
  s.AddToAxleDamping(AxleChannel::kForceY, p[Q::c_by], {{Dof::kYb, 1}, {Dof::kYa, -1}});
  s.AddToAxleDamping(AxleChannel::kMomentX, p[Q::c_bgamma], {{Dof::kGammaB, 1}});
  s.AddToAxleDamping(AxleChannel::kMomentZ, p[Q::c_bpsi], {{Dof::kPsiB, 1}});
  // Lateral slip: F_cy acts on y_b, on camber through r_l0 and on yaw
  // through the trail t_0; the slip sees y_b - r_l0 gamma_b and, rolling,
  // the heading psi_b. At standstill this is S of docs/model.md.
  s.AddSlipLag({L::kLateral, StaticDirection::kLateral, p[Q::K_cy], p[Q::sigma_cy],
                {{Dof::kYb, 1}, {Dof::kGammaB, -r_l0}, {Dof::kPsiB, -p[Q::t_0]}},
                {{Dof::kYb, 1}, {Dof::kGammaB, -r_l0}},
                {{Dof::kPsiB, 1}}});

  for (const Effect* e : effects) e->Apply(p, &s);
  if (speed > 0) {
    AddRolling<T>(p[Q::c_bx], p[Q::c_bz], p[Q::c_bgamma], p[Q::c_bpsi], speed / p[Q::r_e0], &s);
  }
  s.set_speed(speed);
  return s;
}

}  // namespace

RigidRingModel::RigidRingModel(std::vector<const Effect*> effects)
    : effects_(std::move(effects)) {
  for (int i = 0; i < kNumParams; ++i) {
    if (IsBaseline(ParamAt(i))) used_.push_back(ParamAt(i));
  }
  for (const Effect* e : effects_) {
    for (Param p : e->parameters()) used_.push_back(p);
  }
  std::sort(used_.begin(), used_.end());
  used_.erase(std::unique(used_.begin(), used_.end()), used_.end());
}

std::vector<Param> RigidRingModel::parameters() const { return used_; }

MechanicalSystem RigidRingModel::Assemble(const Parameters& p, double speed) const {
  return AssembleAny<double>(effects_, p, speed);
}

BasicSystem<ParameterJet> RigidRingModel::Assemble(const ParameterArray<ParameterJet>& p,
                                                   double speed) const {
  return AssembleAny<ParameterJet>(effects_, p, speed);
}

ModalSolution RigidRingModel::Solve(const Parameters& p, double speed, bool derivatives) const {
  for (Param q : used_) {
    if (!std::isfinite(p[q])) {
      ModalSolution bad;
      bad.error = std::string("parameter ") + ParamName(q) + " is not finite";
      return bad;
    }
  }
  if (!(speed >= 0) || !std::isfinite(speed)) {
    ModalSolution bad;
    bad.error = "speed must be finite and not negative";
    return bad;
  }
  if (speed == 0) {
    if (!derivatives) return Standing(p);
    const BasicSystem<ParameterJet> s = Assemble(Seeded(p), 0);
    return SolveModes(Assemble(p), &s);
  }
  const Parameters anchor = Anchor(p, kAnchorBits);
  if (std::memcmp(&anchor, &p, sizeof(Parameters)) != 0 &&
      SameLabelsNear(Standing(anchor), Standing(p))) {
    // An anchor whose labels a finest step forced is not carried from.
    const ModalSolution at_anchor = anchors_.Get(anchor, speed, [&] {
      bool forced = false;
      ModalSolution s = SolveByContinuation(anchor, speed, false, &forced);
      if (forced) s.ok = false;
      return s;
    });
    std::optional<BasicSystem<ParameterJet>> jets;
    if (derivatives) jets = Assemble(Seeded(p), speed);
    if (std::optional<ModalSolution> near =
            SolveNear(at_anchor, Assemble(p, speed), jets ? &*jets : nullptr)) {
      return *std::move(near);
    }
  }
  return SolveByContinuation(p, speed, derivatives);
}

ModalSolution RigidRingModel::SolveFrom(const ModalSolution& near, const Parameters& p,
                                        double speed) const {
  // At standstill labels are by energy, a function of p alone.
  if (speed > 0 && near.ok) {
    const bool finite = std::all_of(used_.begin(), used_.end(),
                                    [&](Param q) { return std::isfinite(p[q]); });
    if (finite) {
      if (std::optional<ModalSolution> carried = SolveNear(near, Assemble(p, speed))) {
        return *std::move(carried);
      }
    }
  }
  return Solve(p, speed, false);
}

ModalSolution RigidRingModel::Standing(const Parameters& p) const {
  return standing_.Get(p, 0, [&] { return SolveModes(Assemble(p)); });
}

ModalSolution RigidRingModel::SolveByContinuation(const Parameters& p, double speed,
                                                  bool derivatives, bool* forced) const {
  const auto jets = [&](double v) { return Assemble(Seeded(p), v); };
  return SolveRolling([&](double v) { return Assemble(p, v); }, speed, Standing(p),
                      derivatives ? std::function<BasicSystem<ParameterJet>(double)>(jets)
                                  : nullptr,
                      forced);
}

ModalSolution RigidRingModel::SolutionCache::Get(
    const Parameters& p, double speed, const std::function<ModalSolution()>& solve) const {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& [key, solution] : entries_) {
      if (key.speed == speed && std::memcmp(&key.p, &p, sizeof(Parameters)) == 0) return *solution;
    }
  }
  auto solution = std::make_shared<const ModalSolution>(solve());
  std::lock_guard<std::mutex> lock(mutex_);
  if (static_cast<int>(entries_.size()) < kCapacity) {
    entries_.push_back({Key{p, speed}, solution});
  } else {
    entries_[next_] = {Key{p, speed}, solution};
    next_ = (next_ + 1) % kCapacity;
  }
  return *solution;
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
