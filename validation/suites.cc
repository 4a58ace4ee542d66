#include "validation/suites.h"

#include "validation/extract_suite.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>

#include "datasets/paper.h"
#include "datasets/synthetic.h"
#include "estimation/diagnose.h"
#include "estimation/identifiability.h"
#include "estimation/identify.h"
#include "estimation/statistics.h"
#include "model/effects.h"
#include "model/rigid_ring_model.h"

namespace ringid {
namespace {

using P = Param;

}  // namespace

Status LoadPaper(const SuiteOptions& o, Dataset* table1, Parameters* paper) {
  LoadError e;
  if (!LoadDataset(o.source_dir + "/datasets/paper/table1.json", table1, &e)) {
    return Status::InvalidInput(e.OneLine());
  }
  *paper = InitialParameters(*table1);
  return Status::Success();
}

namespace {

// datasets/synthetic.h's Simulate, shapes on the seven belt and rim DOFs.
Dataset Simulated(const Parameters& truth, double freq_rel, double zeta_rel,
                  double shape_sd, std::mt19937_64* rng, bool damping, bool shapes) {
  SimulateOptions so;
  so.frequency_noise = freq_rel;
  so.damping_noise = zeta_rel;
  so.shape_noise = shape_sd;
  so.damping = damping;
  so.shapes = shapes;
  so.hub_components = false;
  Dataset d;
  d.name = "synthetic";
  std::string why;
  if (!Simulate(RigidRingModel(), truth, so, rng, &d, &why)) d.modes.clear();
  return d;
}

// The measured frequencies of Table 3, as printed.
constexpr double kTable3Hz[] = {48.9, 68.4, 72.1, 91.6, 36.8, 36.7, 84.5};

// The ten parameters full modal data determine (not k_bz with k_cz: the
// vertical mode sees only their sum).
const Param kSyntheticFree[] = {P::k_bx, P::k_bz, P::k_btheta, P::K_cx, P::c_bx,
                                P::c_btheta, P::k_by, P::k_bgamma, P::k_bpsi, P::c_by};

// Synthetic noise: 0.25 % frequency, 10 % damping, 0.02 shape.
constexpr double kFrequencyNoise = 0.0025, kDampingNoise = 0.10, kShapeNoise = 0.02;

template <class R, class Body>
SuiteOutput Output(Status (*run)(const SuiteOptions&, Body*), const SuiteOptions& o,
                   const Provenance& provenance) {
  R report{provenance, {}};
  SuiteOutput out;
  out.status = run(o, &report.body);
  if (!out.status.ok()) return out;
  out.json = ReportText(report);
  out.markdown = report.body.Markdown();
  return out;
}

}  // namespace

Status RunPaperSuite(const SuiteOptions& o, PaperSuite* suite) {
  Dataset table1;
  Parameters paper;
  if (Status s = LoadPaper(o, &table1, &paper); !s.ok()) return s;
  const ModalSolution s = RigidRingModel().Solve(paper);
  for (int k = 0; k < 7; ++k) {
    const Mode* m = s.Find(static_cast<ModeLabel>(k));
    suite->table3.push_back({static_cast<ModeLabel>(k), kTable3Hz[k], m ? m->frequency_hz : NAN});
  }
  for (Method method : {Method::kLevenbergMarquardt, Method::kSimplex}) {
    IdentifyOptions io;
    io.method = method;
    io.starts = 1;
    io.residuals.derivatives = o.derivatives;
    IdentifyResult f;
    Identify(RigidRingModel(), table1, io, &f);
    suite->identify.push_back({method, f.relative_error_in_plane, f.relative_error_out_of_plane,
                               f.evaluations, f.seconds, f.uncertainty.rank});
  }
  suite->paper_reported_eq19_eq20 = {kPaperSimplexErrorInPlane, kPaperSimplexErrorOutOfPlane};
  return Status::Success();
}

Status RunSyntheticSuite(const SuiteOptions& o, SyntheticSuite* suite) {
  Dataset table1;
  Parameters paper;
  if (Status s = LoadPaper(o, &table1, &paper); !s.ok()) return s;
  std::mt19937_64 rng(o.seed);
  const struct { const char* name; double scale; } tires[] = {
      {"small (0.7 x paper)", 0.7}, {"paper", 1.0}, {"large (1.5 x paper)", 1.5}};
  long inside_all = 0, total_all = 0;
  int done = 0;
  for (const auto& tire : tires) {
    const Parameters truth = ScaledTire(paper, tire.scale);
    long inside = 0, total = 0;
    int failed = 0;
    std::vector<double> z;
    for (int k = 0; k < o.replicates; ++k) {
      Dataset d = Simulated(truth, kFrequencyNoise, kDampingNoise, kShapeNoise, &rng, true, true);
      for (int i = 0; i < kNumParams; ++i) {
        if (IsBaseline(ParamAt(i))) d.known[ParamAt(i)] = truth[ParamAt(i)];
      }
      for (Param p : kSyntheticFree) {  // start dampers low and stiffnesses high
        d.known.erase(p);
        d.initial[p] = truth[p] * (IsDamping(p) ? 0.8 : 1.25);
      }
      IdentifyOptions io;
      io.starts = 1;
      io.residuals.derivatives = o.derivatives;
      IdentifyResult f;
      Identify(RigidRingModel(), d, io, &f);
      if (!f.status.ok()) {
        ++failed;
        continue;
      }
      for (const ParameterEstimate& e : f.estimates) {
        if (!e.free || !e.std || e.identifiable != Identifiability::kYes) continue;
        const double err = std::abs(std::log(e.value / truth[e.param()]));
        const double sd = *e.std / e.value;
        z.push_back(err / sd);
        ++total;
        inside += err <= kNormal95 * sd;
      }
      if (o.on_case) o.on_case(++done, 3 * o.replicates);
    }
    std::sort(z.begin(), z.end());
    suite->tires.push_back({tire.name, tire.scale, o.replicates, total,
                            total ? static_cast<double>(inside) / total : NAN,
                            z.empty() ? NAN : z[z.size() / 2], failed});
    inside_all += inside;
    total_all += total;
  }
  suite->coverage_95 = total_all ? static_cast<double>(inside_all) / total_all : NAN;
  suite->frequency_noise = kFrequencyNoise;
  suite->damping_noise = kDampingNoise;
  suite->shape_noise = kShapeNoise;
  suite->free.assign(std::begin(kSyntheticFree), std::end(kSyntheticFree));
  return Status::Success();
}

Status RunConditioningSuite(const SuiteOptions& o, ConditioningSuite* suite) {
  Dataset table1;
  Parameters paper;
  if (Status s = LoadPaper(o, &table1, &paper); !s.ok()) return s;
  const struct { const char* name; bool damping, shapes; } variants[] = {
      {"frequencies only", false, false}, {"+ mode shapes", false, true},
      {"+ damping ratios", true, false}, {"+ shapes and damping", true, true}};
  std::mt19937_64 rng(o.seed);
  for (const auto& v : variants) {
    Dataset d = Simulated(paper, 1e-12, 1e-12, 1e-12, &rng, v.damping, v.shapes);
    for (MeasuredMode& m : d.modes) {
      // Realistic sigmas, exact values: the conditioning of a real test.
      m.frequency_sigma_hz = kFrequencyNoise * m.frequency_hz;
      if (m.damping_ratio) m.damping_sigma = 0.01;  // 0.01 absolute: a good test
      if (!m.shape.empty()) m.shape_sigma = kShapeNoise;
    }
    d.known = table1.known;
    d.initial = table1.initial;
    d.ties = table1.ties;
    IdentifiabilityOptions io;
    io.profile_steps = 0;
    io.fit.residuals.derivatives = o.derivatives;
    IdentifiabilityResult a;
    AnalyzeIdentifiability(RigidRingModel(), d, io, &a);
    if (!a.status.ok()) return Status::Failed(std::string(v.name) + ": " + a.status.message);
    ConditioningVariant row{v.name, a.num_residuals, a.rank, a.condition_number, {},
                            a.identifiable_subset};
    for (const auto& p : a.parameters) row.classes[p.param()] = p.identifiable;
    suite->variants.push_back(std::move(row));
  }
  return Status::Success();
}

namespace {

// The rolling suite's free parameters: everything the three conditions
// determine with the paper's four ties (docs/rolling.md); the rest known.
const Param kRollingFree[] = {P::c_bx, P::c_btheta, P::k_bx,     P::k_btheta, P::K_cx,
                              P::sigma_cx, P::k_cz, P::c_by,     P::c_bgamma, P::k_by,
                              P::k_bgamma, P::K_cy, P::sigma_cy, P::t_0};
const std::pair<Param, Param> kRollingTies[] = {
    {P::c_bz, P::c_bx}, {P::k_bz, P::k_bx}, {P::c_bpsi, P::c_bgamma}, {P::k_bpsi, P::k_bgamma}};

}  // namespace

Status RollingDataset(const Parameters& truth, const std::vector<double>& speeds,
                      std::mt19937_64* rng, Dataset* d) {
  d->name = "rolling";
  d->format = 2;
  d->conditions.clear();
  for (double v : speeds) {
    Condition c;
    c.name = ConditionName(v);
    c.speed_m_s = v;
    d->conditions.push_back(c);
  }
  SimulateOptions so;
  so.frequency_noise = kFrequencyNoise;
  so.damping_noise = kDampingNoise;
  so.shape_noise = kShapeNoise;
  std::string why;
  if (!Simulate(RigidRingModel(), truth, so, rng, d, &why)) return Status::InvalidInput(why);
  for (int i = 0; i < kNumParams; ++i) {
    if (IsBaseline(ParamAt(i))) d->known[ParamAt(i)] = truth[ParamAt(i)];
  }
  for (const auto& [tied, to] : kRollingTies) {
    d->known.erase(tied);
    d->ties[tied] = to;
  }
  for (Param p : kRollingFree) {  // start dampers low and the rest high
    d->known.erase(p);
    d->initial[p] = truth[p] * (IsDamping(p) ? 0.8 : 1.25);
  }
  return Status::Success();
}


Status RunRollingSuite(const SuiteOptions& o, RollingSuite* suite) {
  if (o.replicates < 1) return Status::InvalidInput("replicates: must be at least 1");
  if (o.speeds.empty()) return Status::InvalidInput("speeds: none given");
  for (size_t i = 0; i < o.speeds.size(); ++i) {
    if (!(o.speeds[i] >= 0) || !std::isfinite(o.speeds[i])) {
      return Status::InvalidInput("speeds: must be finite and not negative");
    }
    for (size_t j = 0; j < i; ++j) {
      if (o.speeds[j] == o.speeds[i]) return Status::InvalidInput("speeds: listed twice");
    }
  }
  const auto start = std::chrono::steady_clock::now();
  const Parameters truth = ExampleCarTire();
  std::mt19937_64 rng(o.seed);
  std::map<Param, CoverageTally> tallies;
  double fit_seconds = 0;
  int fits = 0;
  for (int k = 0; k < o.replicates; ++k) {
    Dataset d;
    if (Status s = RollingDataset(truth, o.speeds, &rng, &d); !s.ok()) return s;
    IdentifyOptions io;
    io.starts = 1;
    io.residuals.derivatives = o.derivatives;
    IdentifyResult f;
    Identify(RigidRingModel(), d, io, &f);
    if (f.status.invalid_input()) return Status::Failed("identify: " + f.status.message);
    if (!f.status.ok()) {
      ++suite->failed_fits;
    } else {
      ++fits;
      fit_seconds += f.seconds;
      for (const ParameterEstimate& e : f.estimates) {
        if (e.free) tallies[e.param()].Add(e, truth[e.param()], false);
      }
    }
    if (o.on_case) o.on_case(k + 1, o.replicates);
  }
  long inside_all = 0;
  for (Param p : kRollingFree) {
    const CoverageTally& t = tallies[p];
    RollingParameter r;
    r.param = p;
    r.truth = truth[p];
    t.Into(&r);
    suite->parameters.push_back(r);
    suite->intervals += t.intervals();
    inside_all += t.inside();
  }
  suite->coverage_95 =
      suite->intervals ? static_cast<double>(inside_all) / suite->intervals : NAN;
  suite->tire = "example car tire (205/60R15 belt, 4 kN load)";
  suite->speeds_m_s = o.speeds;
  suite->replicates = o.replicates;
  suite->frequency_noise = kFrequencyNoise;
  suite->damping_noise = kDampingNoise;
  suite->shape_noise = kShapeNoise;
  suite->ties.insert(std::begin(kRollingTies), std::end(kRollingTies));
  suite->seconds_per_fit = fits ? fit_seconds / fits : NAN;
  suite->seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Success();
}

const RollingParameter* RollingSuite::Find(Param p) const {
  for (const RollingParameter& r : parameters) {
    if (r.param == p) return &r;
  }
  return nullptr;
}

bool RollingSuite::ContactClassedYes() const {
  for (Param p : contact) {
    const RollingParameter* r = Find(p);
    if (!r || replicates < 1 || r->yes < contact_yes_min * replicates) return false;
  }
  return true;
}

bool RollingSuite::NeverNo() const {
  for (const RollingParameter& r : parameters) {
    if (r.no > 0) return false;
  }
  return true;
}

bool RollingSuite::CoverageInRange() const {
  return coverage_95 >= coverage_range.first && coverage_95 <= coverage_range.second;
}

std::vector<Param> RollingSuite::OutsideCoverageRange() const {
  std::vector<Param> out;
  for (const RollingParameter& r : parameters) {
    if (!(r.coverage_95 >= coverage_range.first && r.coverage_95 <= coverage_range.second)) {
      out.push_back(r.param);
    }
  }
  return out;
}

int ConditioningVariant::Count(Identifiability c) const {
  int n = 0;
  for (const auto& [p, k] : classes) n += k == c;
  return n;
}

const std::vector<SuiteEntry>& Suites() {
  static const std::vector<SuiteEntry> suites = {
      {"paper", [](const SuiteOptions& o, const Provenance& p) {
         return Output<BenchPaperReport>(RunPaperSuite, o, p);
       }},
      {"synthetic", [](const SuiteOptions& o, const Provenance& p) {
         return Output<BenchSyntheticReport>(RunSyntheticSuite, o, p);
       }},
      {"conditioning", [](const SuiteOptions& o, const Provenance& p) {
         return Output<BenchConditioningReport>(RunConditioningSuite, o, p);
       }},
      {"diagnosis", [](const SuiteOptions& o, const Provenance& p) {
         return Output<BenchDiagnosisReport>(RunDiagnosisSuite, o, p);
       }},
      {"rolling", [](const SuiteOptions& o, const Provenance& p) {
         return Output<BenchRollingReport>(RunRollingSuite, o, p);
       }},
      {"speed", [](const SuiteOptions& o, const Provenance& p) {
         return Output<BenchSpeedReport>(RunSpeedSuite, o, p);
       }},
      {"forces", [](const SuiteOptions& o, const Provenance& p) {
         return Output<BenchForcesReport>(RunForcesSuite, o, p);
       }},
      {"static", [](const SuiteOptions& o, const Provenance& p) {
         return Output<BenchStaticReport>(RunStaticSuite, o, p);
       }},
      {"frf", [](const SuiteOptions& o, const Provenance& p) {
         return Output<BenchFrfReport>(RunFrfSuite, o, p);
       }},
      {"extract", [](const SuiteOptions& o, const Provenance& p) {
         return Output<BenchExtractReport>(RunExtractSuite, o, p);
       }},
  };
  return suites;
}

std::string SuiteNames() {
  std::string names;
  for (const SuiteEntry& s : Suites()) names += (names.empty() ? "" : ", ") + std::string(s.name);
  return names;
}

Parameters ScaledTire(const Parameters& paper, double s) {
  Parameters t = paper;
  const double s2 = s * s, s3 = s2 * s, s4 = s2 * s2;
  for (P p : {P::m_b, P::F_cz0}) t[p] *= s2;
  for (P p : {P::I_ay, P::I_by, P::I_bx, P::I_bz}) t[p] *= s4;
  for (P p : {P::sigma_cx, P::r_e0, P::sigma_cy, P::r_l0, P::t_0}) t[p] *= s;
  for (P p : {P::k_bx, P::k_bz, P::k_cz, P::k_by}) t[p] *= s;
  for (P p : {P::K_cx, P::K_cy}) t[p] *= s2;
  for (P p : {P::k_btheta, P::k_bgamma, P::k_bpsi}) t[p] *= s3;
  // zeta ~ c / sqrt(k m): translational c ~ s^1.5, rotational c ~ s^3.5.
  for (P p : {P::c_bx, P::c_bz, P::c_by}) t[p] *= std::pow(s, 1.5);
  for (P p : {P::c_btheta, P::c_bgamma, P::c_bpsi}) t[p] *= std::pow(s, 3.5);
  return t;
}

std::string ConditionName(double speed) {
  if (speed == 0) return "standing";
  char text[48];
  std::snprintf(text, sizeof text, "drum_%g", speed);
  return text;
}

}  // namespace ringid
