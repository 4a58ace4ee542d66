// The static suite (validation/suites.h): synthetic standing tires measured
// by their modes and static stiffnesses (contract §10), identified from
// scattered initial values; the 95 % intervals' coverage per parameter.
#include <chrono>
#include <cmath>
#include <map>
#include <random>
#include <sstream>

#include "datasets/synthetic.h"
#include "estimation/identify.h"
#include "estimation/statistics.h"
#include "validation/suites.h"

namespace ringid {

Parameters ScatteredTire(std::mt19937_64* rng) {
  std::normal_distribution<double> normal(0, 1);
  Parameters p = ExampleCarTire();
  for (int i = 0; i < kNumParams; ++i) {
    const Param q = ParamAt(i);
    if (!p.IsSet(q) || !IsBaseline(q) || Info(q).domain != Domain::kPositive) {
      continue;
    }
    const bool inertia = IsMassOrInertia(q);
    p[q] *= std::exp((inertia ? 0.1 : 1.0) * kTireSpread * normal(*rng));
  }
  p[Param::I_bz] = p[Param::I_bx];  // a ring
  // The paper's ties, which the engineer's dataset states (SetEngineerPriors).
  p[Param::k_bz] = p[Param::k_bx];
  p[Param::c_bz] = p[Param::c_bx];
  p[Param::k_bpsi] = p[Param::k_bgamma];
  p[Param::c_bpsi] = p[Param::c_bgamma];
  return p;
}

Status RunStaticSuite(const SuiteOptions& o, StaticSuite* suite) {
  if (o.replicates < 1) return Status::InvalidInput("replicates: must be at least 1");
  if (!(o.start_factor >= 1)) return Status::InvalidInput("start_factor: must be at least 1");
  if (o.starts < 1) return Status::InvalidInput("starts: must be at least 1");
  const auto start = std::chrono::steady_clock::now();
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  SimulateOptions so;
  so.statics = {StaticDirection::kVertical, StaticDirection::kLongitudinal,
                StaticDirection::kLateral};
  std::map<Param, CoverageTally> tallies;
  double fit_seconds = 0;
  int fits = 0;
  for (int k = 0; k < o.replicates; ++k) {
    Parameters truth;
    Dataset d;
    std::string why;
    for (int draw = 0;; ++draw) {  // a tire whose seven modes all oscillate
      truth = ScatteredTire(&rng);
      d = PlanSimulation(truth, 0, {0}, {}, &rng);
      d.name = "static_" + std::to_string(k);
      if (Simulate(RigidRingModel(), truth, so, &rng, &d, &why)) break;
      if (draw == 100) return Status::Failed("no plausible tire in 100 draws: " + why);
    }
    for (auto& [q, v] : d.initial) v = truth[q] * std::pow(o.start_factor, uniform(rng));
    IdentifyOptions io;
    io.residuals.derivatives = o.derivatives;
    io.threads = 1;
    io.starts = o.starts;
    IdentifyResult f;
    Identify(RigidRingModel(), d, io, &f);
    if (f.status.invalid_input()) return Status::Failed("identify: " + f.status.message);
    if (!f.status.ok()) {
      ++suite->failed_fits;
    } else {
      ++fits;
      suite->poor_fits += f.fit.poor;
      fit_seconds += f.seconds;
      for (const ParameterEstimate& e : f.estimates) {
        if (e.free) tallies[e.param()].Add(e, truth[e.param()], true);
      }
    }
    if (o.on_case) o.on_case(k + 1, o.replicates);
  }
  for (const auto& [p, t] : tallies) {
    StaticParameter r;
    r.param = p;
    t.Into(&r);
    suite->parameters.push_back(r);
  }
  suite->tires = o.replicates;
  suite->tire_spread = kTireSpread;
  suite->start_factor = o.start_factor;
  suite->starts = o.starts;
  suite->frequency_noise = so.frequency_noise;
  suite->damping_noise = so.damping_noise;
  suite->shape_noise = so.shape_noise;
  suite->static_noise = so.static_noise;
  suite->seconds_per_fit = fits ? fit_seconds / fits : NAN;
  suite->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Success();
}

std::vector<Param> StaticSuite::Identifiable() const {
  std::vector<Param> out;
  for (const StaticParameter& r : parameters) {
    if (tires > 0 && r.yes >= identifiable_share * tires) out.push_back(r.param);
  }
  return out;
}

std::vector<Param> StaticSuite::OutsideCoverageRange() const {
  std::vector<Param> out;
  for (const StaticParameter& r : parameters) {
    const bool identifiable = tires > 0 && r.yes >= identifiable_share * tires;
    if (identifiable && !(r.coverage_95 >= coverage_range.first &&
                          r.coverage_95 <= coverage_range.second)) {
      out.push_back(r.param);
    }
  }
  return out;
}

std::string StaticSuite::Markdown() const {
  std::ostringstream o;
  o << CoverageTableHeader();
  for (const StaticParameter& r : parameters) o << CoverageRow(r.param, r);
  char line[256];
  std::snprintf(line, sizeof line,
                "\n%d tires, initial values within a factor %g, %d starts; %d failed fits, %d poor "
                "fits; %.2f s per fit; pass: %s\n",
                tires, start_factor, starts, failed_fits, poor_fits, seconds_per_fit,
                Pass() ? "yes" : "no");
  o << line;
  return o.str();
}

}  // namespace ringid
