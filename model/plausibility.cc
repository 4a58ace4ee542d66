#include "model/plausibility.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <utility>

namespace ringid {
namespace {

std::string Name(Param p) { return ParamName(p); }
// " m", or "" for a dimensionless parameter.
std::string Unit(Param p) { return *Info(p).unit ? std::string(" ") + Info(p).unit : ""; }
// "r_e0 = 0.319 m"
std::string Value(const Parameters& p, Param q) {
  return Name(q) + " = " + FormatSignificant3(p[q]) + Unit(q);
}
std::string Num(double x) { return FormatSignificant3(x); }

// ---- Rule families. Each builds the range text and the check from the same
// numbers, so the table and the check cannot disagree.

// lo <= p <= hi. `what` names the quantity in the reason ("the loaded radius").
PlausibilityRule Range(std::string id, Param q, double lo, double hi, std::string what,
                       std::string why) {
  const std::string range = Num(lo) + "–" + Num(hi) + Unit(q);
  auto check = [=](const Parameters& p) -> std::string {
    const double v = p[q];
    if (v >= lo && v <= hi) return "";
    return Value(p, q) + " is " + (v < lo ? "below " + Num(lo) : "above " + Num(hi)) +
           Unit(q) + "; " + what + " is typically within " + range;
  };
  return {std::move(id), {q}, range, std::move(why), check};
}

const char kRadiusWhy[] =
    "Car tires have radii of about 0.25–0.4 m; truck and agricultural tires reach about 1 m "
    "(Pacejka, Tire and Vehicle Dynamics). A value of millimetres is not a radius.";
const char kRelaxationWhy[] =
    "In the rigid-ring model the carcass compliance is in the sidewall springs, so sigma_c is "
    "the relaxation length of the contact patch alone, typically of the order of the contact "
    "half-length, some centimetres to a decimetre for car tires (Zegelaar 1998, Maurice 2000); "
    "a whole tire's relaxation length is below about 1 m (Pacejka). Millimetres are shorter "
    "than any contact patch.";

// The one-DOF damping ratio c / (2 sqrt(k m)) of a sidewall spring and damper
// on the inertia it carries must not exceed kMaxPlausibleDampingRatio: a
// warning on a plausible tire, not the (0, 1) a measured ratio must lie in
// (datasets/dataset.h).
constexpr double kMaxPlausibleDampingRatio = 0.5;
PlausibilityRule DampingRatio(const SidewallElement& e) {
  const Param c = e.damper, k = e.stiffness, m = e.inertia;
  const std::string ratio = Name(c) + " / (2 sqrt(" + Name(k) + " " + Name(m) + "))";
  auto check = [=](const Parameters& p) -> std::string {
    const double zeta = SidewallDampingRatio(e, p);
    // Signs are the loader's job.
    if (!std::isfinite(zeta) || zeta <= kMaxPlausibleDampingRatio) return "";
    return ratio + " = " + Num(zeta) + " (" + Value(p, c) + ", " + Value(p, k) + ", " +
           Value(p, m) + ") is above " + Num(kMaxPlausibleDampingRatio) +
           "; the sidewall modes of a tire are lightly damped";
  };
  return {std::string("damping_ratio_") + e.direction,
          {c, k, m},
          ratio + " ≤ " + Num(kMaxPlausibleDampingRatio),
          "The approximate modal damping ratio of this sidewall spring and damper on the inertia "
          "it carries (coupling and contact ignored). Modal tests of tires typically find damping "
          "ratios of a few per cent up to about 0.1 (e.g. Zegelaar 1998); above " +
              Num(kMaxPlausibleDampingRatio) +
              " a mode shows hardly any resonance peak, so a modal test would barely find it.",
          check};
}

// lo <= I / (m_b r_e0^2) <= hi.
PlausibilityRule RingInertia(std::string id, Param inertia, double lo, double hi,
                             std::string ring) {
  const std::string range = Num(lo) + "–" + Num(hi) + " m_b r_e0^2";
  auto check = [=](const Parameters& p) -> std::string {
    const double ratio = p[inertia] / (p[Param::m_b] * p[Param::r_e0] * p[Param::r_e0]);
    if (!std::isfinite(ratio) || (ratio >= lo && ratio <= hi)) return "";
    return Value(p, inertia) + " is " + Num(ratio) + " m_b r_e0^2 (" + Value(p, Param::m_b) +
           ", " + Value(p, Param::r_e0) + "), " + (ratio < lo ? "below " : "above ") +
           Num(ratio < lo ? lo : hi) + "; a belt's " + Name(inertia) + " is close to a ring's " +
           ring;
  };
  return {std::move(id),
          {inertia, Param::m_b, Param::r_e0},
          range,
          "A thin ring of mass m and radius r has I_y = m r^2 and I_x = I_z = m r^2/2. The belt's "
          "mass (tread and belt plies) sits at the tread, so its radius of gyration lies between "
          "the rim radius (about 0.7 r_e0 or more) and the tread radius; the margin above allows "
          "for the free radius exceeding r_e0 (Zegelaar 1998, Maurice 2000).",
          check};
}

// lo <= K / F_cz0 <= hi.
constexpr double kMinSlipPerLoad = 2, kMaxSlipPerLoad = 50;
PlausibilityRule SlipStiffnessVsLoad(std::string id, Param stiffness) {
  const std::string ratio = Name(stiffness) + " / F_cz0";
  auto check = [=](const Parameters& p) -> std::string {
    const double r = p[stiffness] / p[Param::F_cz0];
    if (!std::isfinite(r) || (r >= kMinSlipPerLoad && r <= kMaxSlipPerLoad)) return "";
    return ratio + " = " + Num(r) + " (" + Value(p, stiffness) + ", " + Value(p, Param::F_cz0) +
           ") is " + (r < kMinSlipPerLoad ? "below " + Num(kMinSlipPerLoad)
                                          : "above " + Num(kMaxSlipPerLoad)) +
           "; a tire's slip stiffness is typically 5–30 times its load";
  };
  return {std::move(id),
          {stiffness, Param::F_cz0},
          Num(kMinSlipPerLoad) + "–" + Num(kMaxSlipPerLoad) + " F_cz0",
          "At nominal load the longitudinal slip stiffness (N per unit slip) and the cornering "
          "stiffness (N per rad) of car tires are typically 5–30 times the vertical load, truck "
          "tires at the low end "
          "(Pacejka, Tire and Vehicle Dynamics). The contact patch's stiffness in the rigid-ring "
          "model may exceed the whole tire's, which includes the carcass (Maurice 2000): hence "
          "the wide margin.",
          check};
}

// 0.85 <= r_l0 / r_e0 <= 1.02.
constexpr double kMaxLoadedBelowRolling = 0.15, kMaxLoadedAboveRolling = 0.02;
PlausibilityRule LoadedVsRollingRadius() {
  auto check = [](const Parameters& p) -> std::string {
    const double r = p[Param::r_l0] / p[Param::r_e0] - 1;
    if (!std::isfinite(r) || (r >= -kMaxLoadedBelowRolling && r <= kMaxLoadedAboveRolling)) {
      return "";
    }
    return Value(p, Param::r_l0) + " is " + Num(100 * std::abs(r)) + " % " +
           (r < 0 ? "below " : "above ") + Value(p, Param::r_e0) +
           "; a loaded radius is at most " + Num(100 * kMaxLoadedBelowRolling) +
           " % below the rolling radius and not above it";
  };
  return {"loaded_radius_vs_rolling_radius",
          {Param::r_l0, Param::r_e0},
          Num(1 - kMaxLoadedBelowRolling) + "–" + Num(1 + kMaxLoadedAboveRolling) + " r_e0",
          "The effective rolling radius lies between the loaded and the free radius (Pacejka, "
          "Tire and Vehicle Dynamics), so r_l0 < r_e0 is normal. The static deflection of a car "
          "or truck tire is typically below 10 % of its radius; 15 % leaves room for soft "
          "tires, 2 % above for measurement error.",
          check};
}

// max(I_bx, I_bz) / min(I_bx, I_bz) <= 1.5.
constexpr double kMaxInertiaXZRatio = 1.5;
PlausibilityRule InertiaXVsZ() {
  auto check = [](const Parameters& p) -> std::string {
    const bool x_larger = p[Param::I_bx] >= p[Param::I_bz];
    const Param big = x_larger ? Param::I_bx : Param::I_bz;
    const Param small = x_larger ? Param::I_bz : Param::I_bx;
    const double r = p[big] / p[small];
    if (!std::isfinite(r) || r <= kMaxInertiaXZRatio) return "";
    return Value(p, big) + " is " + Num(r) + " times " + Value(p, small) + ", beyond " +
           Num(kMaxInertiaXZRatio) + "; a ring has I_bx = I_bz";
  };
  return {"belt_inertia_x_vs_z",
          {Param::I_bx, Param::I_bz},
          Num(1 / kMaxInertiaXZRatio) + "–" + Num(kMaxInertiaXZRatio) + " I_bx (for I_bz)",
          "The belt is axisymmetric about the wheel axis, so its moments of inertia about x "
          "(camber) and z (yaw) are equal; ground contact changes stiffness, not inertia. The "
          "factor 1.5 leaves room for fit uncertainty.",
          check};
}

// lo <= q / r_e0 <= hi, for the tandem cam's lengths.
PlausibilityRule CamVsRadius(std::string id, Param q, double lo, double hi, std::string what,
                             std::string why) {
  auto check = [=](const Parameters& p) -> std::string {
    const double r = p[q] / p[Param::r_e0];
    if (!std::isfinite(r) || (r >= lo && r <= hi)) return "";
    return Value(p, q) + " is " + Num(r) + " r_e0 (" + Value(p, Param::r_e0) + "), " +
           (r < lo ? "below " + Num(lo) : "above " + Num(hi)) + "; " + what +
           " is typically within " + Num(lo) + "–" + Num(hi) + " r_e0";
  };
  return {std::move(id), {q, Param::r_e0}, Num(lo) + "–" + Num(hi) + " r_e0", std::move(why),
          check};
}

const char kCamWhy[] =
    "The tandem cam (contract §11, Schmeitz 2004) stands for the tire's own outline: a_e and "
    "b_e are near the free radius (a circle of it is a_e = b_e = R0, c_e = 2). Fitted MF-Swift "
    "files hold ELLIPS_LENGTH 1.46–1.47 and ELLIPS_HEIGHT 0.955–0.962 times UNLOADED_RADIUS, "
    "the generic default 1 and 1 (the public .tir corpus); the ranges leave a wide margin.";

// Every rule, in the order of docs/plausibility.md.
std::vector<PlausibilityRule> MakeRules() {
  using P = Param;
  std::vector<PlausibilityRule> rules = {
      Range("belt_mass_range", P::m_b, 1, 100, "the belt mass of a car to truck tire",
            "A car tire's belt (tread and belt plies, without sidewalls and beads) is typically "
            "several kg, a truck tire's some tens of kg (Zegelaar 1998, Maurice 2000)."),
      Range("rolling_radius_range", P::r_e0, 0.15, 1.2,
            "the effective rolling radius of a car to truck tire", kRadiusWhy),
      Range("loaded_radius_range", P::r_l0, 0.15, 1.2, "the loaded radius of a car to truck tire",
            kRadiusWhy),
      LoadedVsRollingRadius(),
      Range("longitudinal_relaxation_length_range", P::sigma_cx, 0.02, 2,
            "a contact relaxation length", kRelaxationWhy),
      Range("lateral_relaxation_length_range", P::sigma_cy, 0.02, 2,
            "a contact relaxation length", kRelaxationWhy),
      Range("pneumatic_trail_range", P::t_0, 0, 0.1, "the pneumatic trail",
            "At small slip the pneumatic trail is a fraction of the contact length, typically "
            "a few centimetres for car tires and somewhat more for trucks (Pacejka, Tire and "
            "Vehicle Dynamics)."),
  };
  for (const SidewallElement& e : kSidewallElements) rules.push_back(DampingRatio(e));
  rules.push_back(RingInertia("belt_inertia_y_vs_ring", P::I_by, 0.5, 1.5, "m_b r_e0^2"));
  rules.push_back(RingInertia("belt_inertia_x_vs_ring", P::I_bx, 0.25, 0.75, "m_b r_e0^2 / 2"));
  rules.push_back(RingInertia("belt_inertia_z_vs_ring", P::I_bz, 0.25, 0.75, "m_b r_e0^2 / 2"));
  rules.push_back(InertiaXVsZ());
  rules.push_back(SlipStiffnessVsLoad("longitudinal_slip_stiffness_vs_load", P::K_cx));
  rules.push_back(SlipStiffnessVsLoad("lateral_slip_stiffness_vs_load", P::K_cy));
  rules.push_back(CamVsRadius("cam_length_vs_radius", P::a_e, 0.5, 3, "the cam's half-length",
                              kCamWhy));
  rules.push_back(CamVsRadius("cam_height_vs_radius", P::b_e, 0.3, 2, "the cam's half-height",
                              kCamWhy));
  rules.push_back(Range("cam_order_range", P::c_e, 1.2, 3, "the cam's exponent",
                        "c_e = 2 is an ellipse, a larger one flattens the cam's bottom. Fitted "
                        "MF-Swift files hold ELLIPS_ORDER 1.52–1.53, the generic default 1.8 "
                        "(the public .tir corpus); the range leaves a wide margin."));
  rules.push_back(CamVsRadius("cam_distance_vs_radius", P::l_s, 0.05, 1,
                              "the distance between the cams",
                              "The two cams stand near the ends of the contact patch: "
                              "docs/tir.md maps l_s from ELLIPS_SHIFT (0.8–0.83 in the public "
                              ".tir corpus) times the contact length, about 0.1–0.5 r_e0 for a "
                              "car tire."));
  return rules;
}

}  // namespace

const std::vector<PlausibilityRule>& PlausibilityRules() {
  static const std::vector<PlausibilityRule> kPlausibilityRules = MakeRules();
  return kPlausibilityRules;
}

namespace {

bool Contains(const std::vector<Param>& list, Param p) {
  return std::find(list.begin(), list.end(), p) != list.end();
}

}  // namespace

std::string FormatSignificant3(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  if (x == 0) return "0";
  char sci[32];
  std::snprintf(sci, sizeof sci, "%.2e", x);  // rounds: "-1.07e+05"
  const char* e = std::strchr(sci, 'e');
  const int exponent = std::atoi(e + 1);
  std::string out;
  if (exponent >= -3 && exponent <= 4) {
    char fixed[48];
    std::snprintf(fixed, sizeof fixed, "%.*f", std::max(0, 2 - exponent), std::strtod(sci, nullptr));
    out = fixed;
  } else {
    out.assign(sci, static_cast<size_t>(e - sci));  // the mantissa
  }
  if (out.find('.') != std::string::npos) {
    out.erase(out.find_last_not_of('0') + 1);
    if (out.back() == '.') out.pop_back();
  }
  if (exponent < -3 || exponent > 4) out += "e" + std::to_string(exponent);
  return out;
}

std::vector<PlausibilityFlag> CheckPlausibility(const Parameters& p,
                                                const std::vector<Param>& used) {
  std::vector<PlausibilityFlag> flags;
  for (const PlausibilityRule& rule : PlausibilityRules()) {
    const bool applies = std::all_of(rule.parameters.begin(), rule.parameters.end(),
                                     [&](Param q) { return Contains(used, q) && p.IsSet(q); });
    if (!applies) continue;
    std::string reason = rule.check(p);
    if (!reason.empty()) flags.push_back({rule.id, rule.parameters, std::move(reason)});
  }
  return flags;
}

std::string PlausibilityTableMarkdown() {
  std::string md = "| rule | parameters | range | why |\n| --- | --- | --- | --- |\n";
  for (const PlausibilityRule& rule : PlausibilityRules()) {
    std::string names;
    for (Param q : rule.parameters) names += (names.empty() ? "`" : ", `") + Name(q) + "`";
    md += "| `" + rule.id + "` | " + names + " | " + rule.range + " | " + rule.why + " |\n";
  }
  return md;
}

}  // namespace ringid
