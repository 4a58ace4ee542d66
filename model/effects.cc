#include "model/effects.h"

#include <tuple>

namespace ringid {
namespace {

using L = ModeLabel;

// k_bz = k_bx + dk_bz and k_bpsi = k_bgamma + dk_bpsi when the ties hold.
class AnisotropicSidewall final : public EffectOf<AnisotropicSidewall> {
 public:
  const char* name() const override { return "anisotropic_sidewall"; }
  Param size() const override { return Param::dk_bpsi; }
  std::vector<Param> parameters() const override {
    return {Param::dk_bz, Param::dk_bpsi};
  }
  template <class P, class S>
  void ApplyTo(const P& p, S* s) const {
    s->AddSpring(L::kVertical, p[Param::dk_bz], {{Dof::kZb, 1}, {Dof::kZa, -1}});
    s->AddSpring(L::kYaw, p[Param::dk_bpsi], {{Dof::kPsiB, 1}});
    s->AddToAxle(AxleChannel::kForceZ, p[Param::dk_bz], {{Dof::kZb, 1}, {Dof::kZa, -1}});
    s->AddToAxle(AxleChannel::kMomentZ, p[Param::dk_bpsi], {{Dof::kPsiB, 1}});
  }
};

// The hub (mass m_a) on springs 1/s_h in x, z, y; the sidewall of eqs. (1),(3)
// already acts on x_b - x_a etc., so freeing the hub is all this needs.
class HubCompliance final : public EffectOf<HubCompliance> {
 public:
  const char* name() const override { return "hub_compliance"; }
  Param size() const override { return Param::s_h; }
  std::vector<Param> parameters() const override {
    return {Param::s_h, Param::m_a};
  }
  template <class P, class S>
  void ApplyTo(const P& p, S* s) const {
    const auto& s_h = p[Param::s_h];
    if (!(s_h > 0.0)) return;  // s_h = 0: the rigid hub of the baseline
    const std::tuple<Dof, L, AxleChannel> hub[] = {
        {Dof::kXa, L::kHubLongitudinal, AxleChannel::kForceX},
        {Dof::kZa, L::kHubVertical, AxleChannel::kForceZ},
        {Dof::kYa, L::kHubLateral, AxleChannel::kForceY}};
    for (const auto& [dof, label, channel] : hub) {
      s->Activate(dof);
      s->AddMass(dof, p[Param::m_a]);
      s->AddSpring(label, 1.0 / s_h, {{dof, 1}});
      s->HoldAxleBy(channel, 1.0 / s_h, dof);  // the axle carries the hub's spring
    }
  }
};

// S[psi_b, psi_b] += k_cpsi.
class ContactYawStiffness final : public EffectOf<ContactYawStiffness> {
 public:
  const char* name() const override { return "contact_yaw_stiffness"; }
  Param size() const override { return Param::k_cpsi; }
  std::vector<Param> parameters() const override { return {Param::k_cpsi}; }
  template <class P, class S>
  void ApplyTo(const P& p, S* s) const {
    s->AddSpring(L::kYaw, p[Param::k_cpsi], {{Dof::kPsiB, 1}});
  }
};

// K[theta_a, theta_a] += k_atheta.
class AxleTorsion final : public EffectOf<AxleTorsion> {
 public:
  const char* name() const override { return "axle_torsion"; }
  Param size() const override { return Param::k_atheta; }
  std::vector<Param> parameters() const override { return {Param::k_atheta}; }
  template <class P, class S>
  void ApplyTo(const P& p, S* s) const {
    s->AddSpring(L::kRotationInPhase, p[Param::k_atheta], {{Dof::kThetaA, 1}});
  }
};

// dm spread round the tread at r_e0: translation dm, spin dm r^2, tilt dm r^2/2.
class SensorMass final : public EffectOf<SensorMass> {
 public:
  const char* name() const override { return "sensor_mass"; }
  Param size() const override { return Param::dm; }
  std::vector<Param> parameters() const override { return {Param::dm}; }
  template <class P, class S>
  void ApplyTo(const P& p, S* s) const {
    const auto& dm = p[Param::dm];
    const auto r2 = p[Param::r_e0] * p[Param::r_e0];
    for (Dof d : {Dof::kXb, Dof::kZb, Dof::kYb}) s->AddMass(d, dm);
    s->AddMass(Dof::kThetaB, dm * r2);
    s->AddMass(Dof::kGammaB, dm * r2 / 2.0);
    s->AddMass(Dof::kPsiB, dm * r2 / 2.0);
  }
};

// K[x_b, y_b] = K[y_b, x_b] = k_xy: the planes become one coupled system.
class LugCoupling final : public EffectOf<LugCoupling> {
 public:
  const char* name() const override { return "lug_coupling"; }
  Param size() const override { return Param::k_xy; }
  std::vector<Param> parameters() const override { return {Param::k_xy}; }
  template <class P, class S>
  void ApplyTo(const P& p, S* s) const {
    s->AddStiffness(std::nullopt, Dof::kXb, Dof::kYb, p[Param::k_xy]);
    s->AddStiffness(std::nullopt, Dof::kYb, Dof::kXb, p[Param::k_xy]);
    // Between belt and rim, as the sidewall: the axle carries it (contract §8).
    s->AddToAxle(AxleChannel::kForceX, p[Param::k_xy], {{Dof::kYb, 1}});
    s->AddToAxle(AxleChannel::kForceY, p[Param::k_xy], {{Dof::kXb, 1}});
  }
};

}  // namespace

const std::vector<const Effect*>& EffectCatalogue() {
  static const AnisotropicSidewall anisotropic;
  static const HubCompliance hub;
  static const ContactYawStiffness yaw;
  static const AxleTorsion axle;
  static const SensorMass sensor;
  static const LugCoupling lug;
  static const std::vector<const Effect*> all = {&anisotropic, &hub, &yaw,
                                                 &axle, &sensor, &lug};
  return all;
}

const Effect* FindEffect(const std::string& name) {
  for (const Effect* e : EffectCatalogue()) {
    if (name == e->name()) return e;
  }
  return nullptr;
}

std::optional<const Effect*> PointerNames<Effect>::FromString(std::string_view name) {
  if (name == kNoEffect) return nullptr;
  const Effect* effect = FindEffect(std::string(name));
  if (!effect) return std::nullopt;
  return effect;
}

std::string PointerNames<Effect>::Choices() {
  std::string out = kNoEffect;
  for (const Effect* e : EffectCatalogue()) out += std::string(", ") + e->name();
  return out;
}

std::vector<std::string> EffectNames(const std::vector<const Effect*>& effects) {
  std::vector<std::string> names;
  for (const Effect* e : effects) names.push_back(EffectName(e));
  return names;
}

}  // namespace ringid
