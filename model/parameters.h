// The parameter catalogue (docs/conventions.md §1 and §4) and a parameter set.
#ifndef RINGID_MODEL_PARAMETERS_H_
#define RINGID_MODEL_PARAMETERS_H_

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <ceres/jet.h>

#include "model/enum_names.h"

namespace ringid {

// How a parameter may vary. Estimation works in log space for kPositive.
// kAboveOne (the cam's c_e) is read only by obstacle conditions, which no fit
// takes yet.
enum class Domain { kPositive, kNonNegative, kReal, kAboveOne };

// Which part of the model a parameter belongs to. kEnvelope: the tandem cam
// of contract §11, read only where the tire rolls over an obstacle.
enum class Group { kInertia, kInPlane, kOutOfPlane, kEffect, kEnvelope };

// name, unit, domain, group, description. Order fixes the Param enum.
#define RINGID_PARAMETERS(X)                                                   \
  X(m_b, "kg", kPositive, kInertia, "belt (ring) mass")                        \
  X(I_ay, "kg m^2", kPositive, kInertia, "rim moment of inertia about y")      \
  X(I_by, "kg m^2", kPositive, kInertia, "belt moment of inertia about y")     \
  X(I_bx, "kg m^2", kPositive, kInertia, "belt moment of inertia about x")     \
  X(I_bz, "kg m^2", kPositive, kInertia, "belt moment of inertia about z")     \
  X(F_cz0, "N", kPositive, kInertia, "static vertical load")                   \
  X(c_bx, "N s/m", kPositive, kInPlane, "sidewall damping, longitudinal")      \
  X(c_bz, "N s/m", kPositive, kInPlane, "sidewall damping, vertical")          \
  X(c_btheta, "N m s/rad", kPositive, kInPlane, "sidewall damping, rotation")  \
  X(k_bx, "N/m", kPositive, kInPlane, "sidewall stiffness, longitudinal")      \
  X(k_bz, "N/m", kPositive, kInPlane, "sidewall stiffness, vertical")          \
  X(k_btheta, "N m/rad", kPositive, kInPlane, "sidewall stiffness, rotation")  \
  X(K_cx, "N", kPositive, kInPlane, "longitudinal slip stiffness of contact")  \
  X(sigma_cx, "m", kPositive, kInPlane, "longitudinal relaxation length")      \
  X(r_e0, "m", kPositive, kInPlane, "effective rolling radius")                \
  X(k_cz, "N/m", kPositive, kInPlane, "vertical residual stiffness")           \
  X(c_by, "N s/m", kPositive, kOutOfPlane, "sidewall damping, lateral")        \
  X(c_bgamma, "N m s/rad", kPositive, kOutOfPlane, "sidewall damping, camber") \
  X(c_bpsi, "N m s/rad", kPositive, kOutOfPlane, "sidewall damping, yaw")      \
  X(k_by, "N/m", kPositive, kOutOfPlane, "sidewall stiffness, lateral")        \
  X(k_bgamma, "N m/rad", kPositive, kOutOfPlane, "sidewall stiffness, camber") \
  X(k_bpsi, "N m/rad", kPositive, kOutOfPlane, "sidewall stiffness, yaw")      \
  X(K_cy, "N", kPositive, kOutOfPlane, "lateral slip stiffness of contact")    \
  X(sigma_cy, "m", kPositive, kOutOfPlane, "lateral relaxation length")        \
  X(r_l0, "m", kPositive, kOutOfPlane, "loaded radius")                        \
  X(t_0, "m", kPositive, kOutOfPlane, "pneumatic trail")                       \
  X(m_a, "kg", kPositive, kEffect, "hub mass (hub_compliance)")                \
  X(dk_bz, "N/m", kReal, kEffect, "k_bz - k_bx (anisotropic_sidewall)")        \
  X(dk_bpsi, "N m/rad", kReal, kEffect, "k_bpsi - k_bgamma (anisotropic_sidewall)") \
  X(s_h, "m/N", kNonNegative, kEffect, "hub compliance (hub_compliance)")      \
  X(k_cpsi, "N m/rad", kNonNegative, kEffect, "contact yaw stiffness")         \
  X(k_atheta, "N m/rad", kNonNegative, kEffect, "rim torsional restraint (axle_torsion)") \
  X(dm, "kg", kNonNegative, kEffect, "sensor mass on the tread (sensor_mass)") \
  X(k_xy, "N/m", kReal, kEffect, "x_b-y_b coupling stiffness (lug_coupling)") \
  X(a_e, "m", kPositive, kEnvelope, "cam half-length (tandem cam)")            \
  X(b_e, "m", kPositive, kEnvelope, "cam half-height (tandem cam)")            \
  X(c_e, "", kAboveOne, kEnvelope, "cam super-ellipse exponent (tandem cam)") \
  X(l_s, "m", kPositive, kEnvelope, "distance between the tandem cams")

enum class Param : int {
#define RINGID_ENUM(name, unit, domain, group, text) name,
  RINGID_PARAMETERS(RINGID_ENUM)
#undef RINGID_ENUM
};

#define RINGID_COUNT(name, unit, domain, group, text) +1
inline constexpr int kNumParams = 0 RINGID_PARAMETERS(RINGID_COUNT);
#undef RINGID_COUNT

struct ParameterInfo {
  const char* unit;
  Domain domain;
  Group group;
  const char* description;
};

const ParameterInfo& Info(Param p);
// A typical magnitude of a parameter that may be zero or negative (effect
// parameters); estimation moves such a parameter in units of it. 1 for the
// positive ones, which move in log space.
double TypicalScale(Param p);
template <>
struct EnumNames<Param> {
#define RINGID_NAME(name, unit, domain, group, text) #name,
  static constexpr std::array<const char*, kNumParams> kNames = {RINGID_PARAMETERS(RINGID_NAME)};
#undef RINGID_NAME
};
inline const char* ParamName(Param p) { return ToString(p); }
inline std::optional<Param> ParseParam(const std::string& name) { return FromString<Param>(name); }
inline Param ParamAt(int i) { return static_cast<Param>(i); }

// Each sidewall spring of the belt, its damper and the belt inertia they carry
// (docs/model.md): one degree of freedom of the belt on a held rim without
// road contact. The one pairing that the plausibility rules, a .tir's FREQ_*
// and DAMP_* keys (datasets/tir_parameters.cc) and the example tire use.
struct SidewallElement {
  const char* direction;  // the belt's coordinate
  Param stiffness;
  Param damper;
  Param inertia;
};
inline constexpr std::array<SidewallElement, 6> kSidewallElements = {{
    {"x", Param::k_bx, Param::c_bx, Param::m_b},
    {"z", Param::k_bz, Param::c_bz, Param::m_b},
    {"theta", Param::k_btheta, Param::c_btheta, Param::I_by},
    {"y", Param::k_by, Param::c_by, Param::m_b},
    {"gamma", Param::k_bgamma, Param::c_bgamma, Param::I_bx},
    {"psi", Param::k_bpsi, Param::c_bpsi, Param::I_bz},
}};
// The element whose stiffness or damper `p` is; nullptr for any other parameter.
inline const SidewallElement* SidewallOf(Param p) {
  for (const SidewallElement& e : kSidewallElements) {
    if (e.stiffness == p || e.damper == p) return &e;
  }
  return nullptr;
}
// The sidewall dampers c_b* (the rest are stiffnesses, inertias and lengths).
inline bool IsDamping(Param p) {
  const SidewallElement* e = SidewallOf(p);
  return e && e->damper == p;
}

// The parameters the baseline model reads wherever the tire is: neither an
// effect's nor the tandem cam's.
inline bool IsBaseline(Param p) {
  return Info(p).group != Group::kEffect && Info(p).group != Group::kEnvelope;
}

// The tandem cam's parameters (Group::kEnvelope), in catalogue order.
const std::vector<Param>& CamParameters();

// The belt's mass and the belt's and rim's inertias: what a force-calibrated
// FRF weighs and modes cannot (they carry no scale).
inline bool IsMassOrInertia(Param p) {
  return p == Param::m_b || p == Param::I_ay || p == Param::I_by || p == Param::I_bx ||
         p == Param::I_bz;
}

// The positive stiffnesses of springs and contact slips (k_b*, k_cz, K_c*):
// a mode's squared frequency grows with the stiffness of its element.
inline bool IsStiffness(Param p) {
  switch (p) {
    case Param::k_bx: case Param::k_bz: case Param::k_btheta: case Param::k_cz:
    case Param::K_cx: case Param::k_by: case Param::k_bgamma: case Param::k_bpsi:
    case Param::K_cy: return true;
    default: return false;
  }
}

// A value for every parameter of the catalogue; effect parameters default to
// their baseline value 0, everything else to NaN (unset).
class Parameters {
 public:
  Parameters();
  double operator[](Param p) const { return v_[static_cast<int>(p)]; }
  double& operator[](Param p) { return v_[static_cast<int>(p)]; }
  bool IsSet(Param p) const;

 private:
  std::array<double, kNumParams> v_;
};

// Sidewall element e of p alone: its undamped frequency sqrt(k / m) / (2 pi)
// (Hz) and damping ratio c / (2 sqrt(k m)); the stiffness that gives it
// frequency `hz` on its inertia, and the damper that gives it ratio `zeta` on
// its stiffness and inertia.
double SidewallFrequencyHz(const SidewallElement& e, const Parameters& p);
double SidewallDampingRatio(const SidewallElement& e, const Parameters& p);
double SidewallStiffness(const SidewallElement& e, double hz, const Parameters& p);
double SidewallDamper(const SidewallElement& e, double zeta, const Parameters& p);

// A scalar carrying the derivatives with respect to every parameter.
using ParameterJet = ceres::Jet<double, kNumParams>;

// Values of every parameter in another scalar type (a ceres::Jet for exact
// derivatives, model/structure.h), indexed as Parameters.
template <class T>
class ParameterArray {
 public:
  const T& operator[](Param p) const { return v_[static_cast<int>(p)]; }
  T& operator[](Param p) { return v_[static_cast<int>(p)]; }

 private:
  std::array<T, kNumParams> v_;
};

// p with each parameter carrying its own unit derivative.
ParameterArray<ParameterJet> Seeded(const Parameters& p);

}  // namespace ringid

#endif  // RINGID_MODEL_PARAMETERS_H_
