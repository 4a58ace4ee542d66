#include "datasets/synthetic.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstdio>
#include <cmath>
#include <map>

#include <nlohmann/json.hpp>

#include "datasets/frf_spec.h"
#include "datasets/measurement.h"
#include "model/plausibility.h"
#include "model/time_response.h"

namespace ringid {

double SimulateOptions::Noise(Quantity q) const {
  const double noise[] = {frequency_noise, damping_noise, shape_noise, static_noise, frf_noise};
  static_assert(sizeof noise / sizeof noise[0] == EnumNames<Quantity>::kNames.size());
  return noise[static_cast<int>(q)];
}

bool Simulate(const ModalModel& model, const Parameters& truth,
              const SimulateOptions& o, std::mt19937_64* rng, Dataset* d,
              std::string* error) {
  std::normal_distribution<double> n(0, 1);
  d->modes.clear();
  d->statics.clear();
  const bool standing_statics = !o.statics.empty();
  bool frfs = false;
  for (const Condition& c : d->conditions) frfs |= c.frf.has_value();
  if (standing_statics || frfs) d->format = 3;  // what such a dataset reads back as
  for (int c = 0; c < static_cast<int>(d->conditions.size()); ++c) {
  const Condition& condition = d->conditions[c];
  Parameters p = truth;
  for (const auto& [q, v] : condition.known) p[q] = v;
  const ModalSolution s = model.Solve(p, condition.speed_m_s);
  const std::string where = d->conditions.size() > 1 ? " in condition " + condition.name : "";
  if (!s.ok) {
    *error = "the truth model cannot be solved" + where + ": " + s.error;
    return false;
  }
  for (int l = 0; l < 7 && o.modes; ++l) {
    const Mode* m = s.Find(static_cast<ModeLabel>(l));
    if (!m) {
      *error = std::string("the truth has no oscillating ") +
               LabelName(static_cast<ModeLabel>(l)) + " mode" + where;
      return false;
    }
    if (const std::string problem = ModeFrequencyProblem(m->frequency_hz); !problem.empty()) {
      *error = std::string("the truth's ") + LabelName(m->label) + " mode" + where + ": " + problem;
      return false;  // a dataset the loader would refuse
    }
    // What the test measures (the quantities and components asked for), then
    // its noise, quantity by quantity.
    MeasuredMode mm;
    mm.condition = c;
    mm.label = m->label;
    if (o.damping) mm.damping_ratio = 0;
    if (o.shapes) {
      const int dofs = o.hub_components ? kNumDofs : static_cast<int>(Dof::kXa);
      for (int i = 0; i < dofs; ++i) mm.shape.emplace_back(static_cast<Dof>(i), 0);
    }
    for (const ModeQuantity* unit : ModeQuantities()) {
      unit->Measure(*m, MeasurementOptions{}, &mm);
      unit->AddNoise(o.Noise(unit->quantity()), [&] { return n(*rng); }, &mm);
    }
    d->modes.push_back(mm);
  }
  // The static stiffnesses asked for, in a standing condition (contract §10).
  if (condition.speed_m_s == 0) {
    const Measurement& unit = MeasurementOf(Quantity::kStatic);
    const ModelAt at{&model, &p, &s, nullptr};
    for (StaticDirection direction : o.statics) {
      d->statics.push_back({direction, 0, std::nullopt, c});
      const int i = static_cast<int>(d->statics.size()) - 1;
      if (!unit.Measure(at, i, MeasurementOptions{}, d)) {
        *error = std::string("the truth's static ") + ToString(direction) + " stiffness" + where +
                 " cannot be solved";
        return false;
      }
      unit.AddNoise(o.Noise(Quantity::kStatic), [&] { return n(*rng); }, i, d);
    }
  }
  }
  // The FRFs each condition lays out (contract §9).
  const Measurement& frf = MeasurementOf(Quantity::kFrf);
  for (int i = 0; i < frf.records().Items(*d); ++i) {
    const int c = frf.records().ConditionOf(*d, i);
    Parameters p = truth;
    for (const auto& [q, v] : d->conditions[c].known) p[q] = v;
    const ModelAt at{&model, &p, nullptr, nullptr};
    if (!frf.Measure(at, i, MeasurementOptions{}, d)) {
      *error = "the truth's frequency response functions in condition " + d->conditions[c].name +
               " cannot be computed";
      return false;
    }
    frf.AddNoise(o.Noise(Quantity::kFrf), [&] { return n(*rng); }, i, d);
  }
  return true;
}

Frf HammerTest(double r, double low_hz, double high_hz, double step_hz) {
  struct Place {
    const char* name;
    FrfBody on;
    std::array<double, 3> point, direction;
  };
  const Place blows[] = {{"top_radial", FrfBody::kBelt, {0, 0, -r}, {0, 0, 1}},
                         {"top_tangential", FrfBody::kBelt, {0, 0, -r}, {1, 0, 0}},
                         {"top_lateral", FrfBody::kBelt, {0, 0.08, -r}, {0, 1, 0}},
                         {"front_oblique", FrfBody::kBelt, {r, 0.05, 0}, {-0.8, 0.5, 0.3}}};
  const Place sensors[] = {{"top_z", FrfBody::kBelt, {0, 0, -r}, {0, 0, 1}},
                           {"top_x", FrfBody::kBelt, {0, 0, -r}, {1, 0, 0}},
                           {"front_x", FrfBody::kBelt, {r, 0, 0}, {1, 0, 0}},
                           {"front_z", FrfBody::kBelt, {r, 0, 0}, {0, 0, 1}},
                           {"top_y", FrfBody::kBelt, {0, 0.09, -r}, {0, 1, 0}},
                           {"front_y", FrfBody::kBelt, {r, 0.09, 0}, {0, 1, 0}},
                           {"rim_x", FrfBody::kRim, {0, 0, -0.2}, {1, 0, 0}}};
  Frf frf;
  for (const Place& b : blows) {
    const FrfPoint point{b.on, b.point, b.direction};
    frf.inputs.push_back({b.name, point, std::nullopt, PointCombination(point)});
  }
  for (const Place& s : sensors) {
    const FrfPoint point{s.on, s.point, s.direction};
    frf.outputs.push_back(
        {s.name, point, std::nullopt, PointCombination(point), FrfQuantity::kAcceleration});
  }
  frf.frequencies_hz = EvenLines(low_hz, high_hz, step_hz);
  const size_t lines = frf.frequencies_hz.size();
  for (int o = 0; o < static_cast<int>(frf.outputs.size()); ++o) {
    for (int i = 0; i < static_cast<int>(frf.inputs.size()); ++i) {
      frf.functions.push_back({o, i, std::vector<std::complex<double>>(lines), std::vector<double>(lines, 1.0),
                               std::nullopt});
    }
  }
  return frf;
}

Frf DrumTest(double low_hz, double high_hz, double step_hz) {
  using F = LugForce;
  using A = AxleChannel;
  Frf frf;
  for (auto [name, f] : {std::pair{"contact_x", F::kFx}, {"contact_z", F::kFz}, {"contact_y", F::kFy}}) {
    frf.inputs.push_back({name, std::nullopt, f, {}});
  }
  for (auto [name, a] : {std::pair{"axle_x", A::kForceX}, {"axle_z", A::kForceZ}, {"axle_y", A::kForceY},
                         {"axle_mx", A::kMomentX}, {"axle_mz", A::kMomentZ}}) {
    frf.outputs.push_back({name, std::nullopt, a, {}, FrfQuantity::kDisplacement});
  }
  frf.frequencies_hz = EvenLines(low_hz, high_hz, step_hz);
  const size_t lines = frf.frequencies_hz.size();
  const std::pair<int, int> pairs[] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 2}, {3, 2}, {4, 2}};
  for (const auto& [o, i] : pairs) {
    frf.functions.push_back({o, i, std::vector<std::complex<double>>(lines),
                             std::vector<double>(lines, 1.0), std::nullopt});
  }
  return frf;
}

Parameters ExampleCarTire() {
  using P = Param;
  Parameters p;
  // Belt inertias and in-plane/out-of-plane belt frequencies of the public
  // TNO MF-Swift example 205/60R15 (BELT_MASS 7.698 kg, BELT_IXX 0.3519,
  // BELT_IYY 0.4889 kg m^2, FREQ_LONG 76.63, FREQ_LAT 41.47, FREQ_YAW 53.46,
  // FREQ_WINDUP 67.73 Hz), turned into stiffnesses k = m (2 pi f)^2; the
  // rest typical of a car tire at 4 kN: 5 % sidewall damping, slip
  // stiffness about 20 and 15 times the load, relaxation lengths of half a
  // contact length or more.
  p[P::m_b] = 7.698;
  p[P::I_by] = 0.4889;
  p[P::I_bx] = p[P::I_bz] = 0.3519;
  p[P::I_ay] = 0.35;
  p[P::F_cz0] = 4000;
  // One frequency for x and z (FREQ_LONG) and for camber and yaw (FREQ_YAW).
  const std::map<Param, double> hz = {{P::k_bx, 76.63},    {P::k_bz, 76.63},
                                      {P::k_btheta, 67.73}, {P::k_by, 41.47},
                                      {P::k_bgamma, 53.46}, {P::k_bpsi, 53.46}};
  for (const SidewallElement& e : kSidewallElements) {
    p[e.stiffness] = SidewallStiffness(e, hz.at(e.stiffness), p);
    p[e.damper] = SidewallDamper(e, 0.05, p);
  }
  p[P::K_cx] = 8e4;
  p[P::sigma_cx] = 0.1;
  p[P::K_cy] = 6e4;
  p[P::sigma_cy] = 0.15;
  p[P::r_e0] = 0.30;
  p[P::r_l0] = 0.28;
  p[P::t_0] = 0.03;
  p[P::k_cz] = 2e5;
  // The tandem cam: the same example's fitted [CONTACT_PATCH] (ELLIPS_LENGTH
  // 1.4634, ELLIPS_HEIGHT 0.9551, ELLIPS_ORDER 1.5257, ELLIPS_SHIFT 0.8328)
  // by docs/tir.md's mapping: a_e and b_e times UNLOADED_RADIUS 0.3135 m, l_s
  // times the contact length 2a at 4 kN, a = R0 (Q_RA2 rho/R0 + Q_RA1
  // sqrt(rho/R0)) with Q_RA1 0.6715, Q_RA2 0.7308 and the deflection rho =
  // F_z / VERTICAL_STIFFNESS 209651.5 N/m.
  const double r0 = 0.3135, rho = 4000 / 209651.5;
  const double a = r0 * (0.7308 * (rho / r0) + 0.6715 * std::sqrt(rho / r0));
  p[P::a_e] = 1.4634 * r0;
  p[P::b_e] = 0.9551 * r0;
  p[P::c_e] = 1.5257;
  p[P::l_s] = 0.8328 * 2 * a;
  return p;
}

void SetEngineerPriors(const Parameters& truth, double prior_spread,
                       std::mt19937_64* rng, Dataset* d) {
  std::normal_distribution<double> normal(0, 1);
  for (Param q : {Param::m_b, Param::I_ay, Param::I_by, Param::I_bx, Param::I_bz,
                  Param::F_cz0, Param::sigma_cx, Param::sigma_cy}) {
    d->known[q] = truth[q];
  }
  if (truth.IsSet(Param::m_a)) d->known[Param::m_a] = truth[Param::m_a];
  d->ties = {{Param::c_bz, Param::c_bx}, {Param::k_bz, Param::k_bx},
             {Param::c_bpsi, Param::c_bgamma}, {Param::k_bpsi, Param::k_bgamma}};
  for (int i = 0; i < kNumParams; ++i) {
    const Param q = ParamAt(i);
    if (!IsBaseline(q) || d->known.count(q) || d->ties.count(q)) continue;
    d->initial[q] = truth[q] * std::exp(prior_spread * normal(*rng));
  }
}

void FreeMasses(const Parameters& truth, double prior_spread, std::mt19937_64* rng,
                Dataset* d) {
  std::normal_distribution<double> normal(0, 1);
  for (int i = 0; i < kNumParams; ++i) {
    const Param q = ParamAt(i);
    if (!IsMassOrInertia(q)) continue;
    d->known.erase(q);
    d->initial[q] = truth[q] * std::exp(prior_spread * normal(*rng));
  }
}

double LargestShift(const Parameters& truth, const Effect& effect, Param p, double value) {
  const ModalSolution base = RigidRingModel().Solve(truth);
  Parameters q = truth;
  q[p] = value;
  const ModalSolution with = RigidRingModel({&effect}).Solve(q);
  if (!base.ok || !with.ok) return INFINITY;
  double shift = 0;
  for (const Mode& m : base.modes) {
    const Mode* w = with.Find(m.label);
    if (!w) return INFINITY;
    shift = std::max(shift, std::abs(w->frequency_hz / m.frequency_hz - 1));
  }
  return shift;
}

double ValueForShift(const Parameters& truth, const Effect& effect, Param p, double target) {
  double lo = TypicalScale(p) * 1e-4, hi = TypicalScale(p) * 1e3;
  for (int k = 0; k < 60; ++k) {
    const double mid = std::sqrt(lo * hi);
    (LargestShift(truth, effect, p, mid) < target ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

namespace {

// `v` as short as it reads back exactly, in fixed notation where that is
// exact (6, 12.5, 3000), for condition names: letters, digits, '-', '.'.
std::string CompactNumber(double v) {
  char buffer[64];
  for (int digits = 0; digits <= 17; ++digits) {
    const int n = std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
    if (n < static_cast<int>(sizeof buffer) && std::strtod(buffer, nullptr) == v) return buffer;
  }
  for (int digits = 1; digits <= 17; ++digits) {  // tiny or huge: 3e-300, 1e+300
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
    if (std::strtod(buffer, nullptr) == v) break;
  }
  std::string text = buffer;
  text.erase(std::remove(text.begin(), text.end(), '+'), text.end());
  return text;
}


}  // namespace

bool SimulateObstacles(const RigidRingModel& model, const Parameters& truth,
                       const ObstacleSpec& spec, const std::vector<double>& loads,
                       std::mt19937_64* rng, std::vector<Condition>* conditions,
                       std::vector<std::string>* warnings, LoadError* error) {
  std::normal_distribution<double> normal(0, 1);
  *error = LoadError{spec.path, "", ""};
  const bool lugs = spec.profile.kind == ProfileKind::kLugs;
  for (Condition c : SimulatedConditions(spec.speeds_m_s, loads)) {
    c.name.replace(0, c.name.find('_'), "obstacle");
    Parameters p = truth;
    for (const auto& [q, v] : c.known) p[q] = v;
    ObstacleRun run;
    run.speed_m_s = c.speed_m_s;
    run.profile = spec.profile;
    run.cam = CamOf(p);
    run.position_at_t0_m = spec.position_at_t0_m;
    for (int k = 0; k < spec.samples; ++k) run.times_s.push_back(k / spec.sample_rate_hz);
    ObstacleResult r;
    std::string why;
    if (!ObstacleResponse(model, p, run, &r, &why)) {  // why: "field: message"
      const size_t colon = why.find(": ");
      error->field = colon == std::string::npos ? "" : why.substr(0, colon);
      error->message = "condition " + c.name + ": " + why.substr(colon == std::string::npos ? 0 : colon + 2);
      return false;
    }
    if (r.reaches_at_t0) {
      error->field = "position_at_t0_m";
      error->message = "a cam reaches the profile at t = 0: start below " +
                       FormatSignificant3(FirstContact(run.profile, run.cam)) + " m, where the road under " +
                       "every cam is flat (contract §11)";
      return false;
    }
    if (!(r.lowest_contact_force_n > 0)) {
      error->field = "profile";
      error->message = "condition " + c.name + ": the tire leaves the road at t = " +
                       FormatSignificant3(r.lowest_at_s) + " s (contact force " +
                       FormatSignificant3(r.lowest_contact_force_n) + " N): the linear model does not hold " +
                       "(contract §11): a lower obstacle or a higher load";
      return false;
    }
    if (r.largest_load_change > kLargeLoadChange) {
      warnings->push_back("condition " + c.name + ": the contact force changes by " +
                          FormatSignificant3(100 * r.largest_load_change) + " % of F_cz0 at t = " +
                          FormatSignificant3(r.largest_at_s) + " s, more than " +
                          FormatSignificant3(100 * kLargeLoadChange) + " %: the linear model is stretched");
    }
    ObstacleTest test;
    test.profile = spec.profile;
    test.position_at_t0_m = spec.position_at_t0_m;
    test.times_s = run.times_s;
    test.sample_rate_hz = spec.sample_rate_hz;
    for (int o : spec.outputs) {
      const Eigen::RowVectorXd y = r.y.row(o);
      const double span = y.maxCoeff() - y.minCoeff();
      if (!std::isfinite(span)) {
        error->field = "profile";
        error->message = "condition " + c.name + ": " + TimeOutputName(o) + " is not finite";
        return false;
      }
      if (!(span > 0)) {
        error->field = "outputs";
        error->message = std::string(TimeOutputName(o)) + " is identically zero in condition " +
                         c.name + (lugs ? "" : " (its noise would be 0)") +
                         ": leave it out";
        return false;
      }
      ObstacleChannel ch;
      ch.output = o;
      ch.one_sigma = true;
      const double sigma = spec.noise * span;
      for (Eigen::Index k = 0; k < y.size(); ++k) ch.values.push_back(y[k] + sigma * normal(*rng));
      ch.sigma.assign(y.size(), spec.noise > 0 ? sigma : kDefaultObstacleNoise * span);
      test.channels.push_back(std::move(ch));
    }
    c.obstacle = std::move(test);
    conditions->push_back(std::move(c));
  }
  return true;
}

std::vector<Condition> SimulatedConditions(const std::vector<double>& speeds,
                                           const std::vector<double>& loads) {
  std::vector<Condition> conditions;
  for (double v : speeds) {
    Condition c;
    c.name = v == 0 ? "standing" : "drum_" + CompactNumber(v);
    c.speed_m_s = v;
    if (loads.empty()) conditions.push_back(c);
    for (double f : loads) {
      Condition with_load = c;
      with_load.name += "_" + CompactNumber(f) + "N";
      with_load.known[Param::F_cz0] = f;
      conditions.push_back(with_load);
    }
  }
  return conditions;
}


Dataset PlanSimulation(const Parameters& truth, double prior_spread,
                       const std::vector<double>& speeds, const std::vector<double>& loads,
                       std::mt19937_64* rng) {
  Dataset d;
  SetEngineerPriors(truth, prior_spread, rng, &d);
  d.conditions = SimulatedConditions(speeds, loads);
  if (!loads.empty()) {  // the load is known in each condition, not shared
    d.known.erase(Param::F_cz0);
    d.initial.erase(Param::F_cz0);
    d.per_condition = {Param::F_cz0};
  }
  if (d.conditions.size() > 1 || !loads.empty()) d.format = 2;
  // Rolling, the data separate K_cx from sigma_cx (and K_cy from sigma_cy):
  // the relaxation lengths are unknowns to fit, from the prior's spread.
  if (std::any_of(speeds.begin(), speeds.end(), [](double v) { return v > 0; })) {
    std::normal_distribution<double> normal(0, 1);
    for (Param q : {Param::sigma_cx, Param::sigma_cy}) {
      d.known.erase(q);
      d.initial[q] = truth[q] * std::exp(prior_spread * normal(*rng));
    }
  }
  return d;
}

std::string EffectList(const std::vector<const Effect*>& effects) {
  std::string names;
  for (const std::string& name : EffectNames(effects)) names += (names.empty() ? "" : ",") + name;
  return names.empty() ? "none" : names;
}


}  // namespace ringid
