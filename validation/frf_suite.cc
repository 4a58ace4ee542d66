// The frf suite (validation/suites.h): synthetic tires struck standing, and
// on a drum, fitted to their FRFs with the masses free from initial values
// scattered within a factor of the truth (issue 36).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <mutex>
#include <random>
#include <sstream>

#include "datasets/synthetic.h"
#include "estimation/identify.h"
#include "estimation/parallel.h"
#include "validation/suites.h"

namespace ringid {
namespace {

// One tire of `variant` measured with the suite's layout and noise, its
// initial values scattered within start_factor; false where its truth
// cannot be simulated (a mode overdamped).
bool FrfTire(const Parameters& truth, const std::vector<double>& speeds, double noise,
             double start_factor, std::mt19937_64* rng, Dataset* d, std::string* why) {
  *d = PlanSimulation(truth, 0, speeds, {}, rng);
  FreeMasses(truth, 0, rng, d);
  for (Condition& c : d->conditions) {
    c.frf = c.speed_m_s == 0 ? HammerTest() : DrumTest();
  }
  SimulateOptions so;
  so.modes = false;
  so.frf_noise = noise;
  if (!Simulate(RigidRingModel(), truth, so, rng, d, why)) return false;
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (auto& [q, v] : d->initial) v = truth[q] * std::pow(start_factor, uniform(*rng));
  return true;
}

double Relative(const IdentifyResult& r, Param p, const Parameters& truth) {
  for (const ParameterEstimate& e : r.estimates) {
    if (e.param() == p && e.free) return std::abs(e.value / truth[p] - 1);
  }
  return INFINITY;
}

bool ClassedYes(const IdentifyResult& r, Param p) {
  for (const ParameterEstimate& e : r.estimates) {
    if (e.param() == p && e.free) return e.identifiable == Identifiability::kYes;
  }
  return false;
}

// One tire's fits: from the scattered initial values, and from the truth.
struct TireFits {
  Parameters truth;
  Dataset d;
  IdentifyResult f;
  bool truth_ok = false;  // the truth-started fit, its chi-square
  double truth_chi2 = 0;
};

// Tires fitted at once: each fit on one thread, kTireBatch tires drawn
// (in order: the suite is the same on any number of threads) and held at a time.
constexpr int kTireBatch = 8;

Status RunVariant(const SuiteOptions& o, const std::vector<double>& speeds, FrfSuite* suite,
                  FrfVariant* v, std::mt19937_64* rng, int* done, int total) {
  IdentifyOptions io;
  io.residuals.derivatives = o.derivatives;
  io.threads = 1;
  io.starts = o.starts;
  std::map<Param, CoverageTally> tallies;
  double fit_seconds = 0;
  std::mutex mutex;
  for (int begin = 0; begin < o.replicates; begin += kTireBatch) {
    std::vector<TireFits> tires(std::min(kTireBatch, o.replicates - begin));
    for (size_t k = 0; k < tires.size(); ++k) {
      std::string why;
      for (int draw = 0;; ++draw) {
        tires[k].truth = ScatteredTire(rng);
        if (FrfTire(tires[k].truth, speeds, suite->frf_noise, o.start_factor, rng, &tires[k].d,
                    &why)) {
          break;
        }
        if (draw == 100) return Status::Failed("no plausible tire in 100 draws: " + why);
      }
      tires[k].d.name = v->name + "_" + std::to_string(begin + k);
    }
    internal::ParallelFor(static_cast<int>(tires.size()), 0, [&](int k) {
      TireFits& t = tires[k];
      Identify(RigidRingModel(), t.d, io, &t.f);
      Dataset at = t.d;
      for (auto& [q, value] : at.initial) value = t.truth[q];
      IdentifyOptions one = io;
      one.starts = 1;
      IdentifyResult at_truth;
      Identify(RigidRingModel(), at, one, &at_truth);
      t.truth_ok = at_truth.status.ok();
      t.truth_chi2 = at_truth.fit.chi_square;
      std::lock_guard<std::mutex> lock(mutex);
      if (o.on_case) o.on_case(++*done, total);
    });
    for (const TireFits& t : tires) {
      const IdentifyResult& f = t.f;
      if (f.status.invalid_input()) return Status::Failed("identify: " + f.status.message);
      ++v->tires;
      if (!f.status.ok()) {
        ++v->failed_fits;
        continue;
      }
      fit_seconds += f.seconds;
      // A truth-started fit that fails gives no reference: not counted as found.
      v->best_found += t.truth_ok && f.fit.chi_square <= t.truth_chi2 + 1;
      v->masses_within += Relative(f, Param::m_b, t.truth) <= suite->mass_tolerance &&
                          Relative(f, Param::I_by, t.truth) <= suite->mass_tolerance;
      v->contact_separated += ClassedYes(f, Param::K_cx) && ClassedYes(f, Param::sigma_cx);
      for (const ParameterEstimate& e : f.estimates) {
        if (e.free) tallies[e.param()].Add(e, t.truth[e.param()], true);
      }
    }
  }
  long inside = 0;
  for (const auto& [p, t] : tallies) {
    StaticParameter r;
    r.param = p;
    t.Into(&r);
    v->parameters.push_back(r);
    inside += t.inside();
    v->intervals += t.intervals();
  }
  v->coverage_95 = v->intervals ? static_cast<double>(inside) / v->intervals : NAN;
  const int fits = v->tires - v->failed_fits;
  v->seconds_per_fit = fits ? fit_seconds / fits : NAN;
  return Status::Success();
}

std::string Percent(int n, int of) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %%", of ? 100.0 * n / of : 0.0);
  return text;
}

}  // namespace

Status RunFrfSuite(const SuiteOptions& o, FrfSuite* suite) {
  if (o.replicates < 1) return Status::InvalidInput("replicates: must be at least 1");
  if (!(o.start_factor >= 1)) return Status::InvalidInput("start_factor: must be at least 1");
  if (o.starts < 1) return Status::InvalidInput("starts: must be at least 1");
  const auto start = std::chrono::steady_clock::now();
  suite->start_factor = o.start_factor;
  suite->starts = o.starts;
  suite->frf_noise = SimulateOptions{}.frf_noise;
  std::mt19937_64 rng(o.seed);
  int done = 0;
  const std::pair<const char*, std::vector<double>> variants[] = {
      {"standing", {0}}, {"standing_drum", {0, suite->drum_speed_m_s}}};
  for (const auto& [name, speeds] : variants) {
    FrfVariant v;
    v.name = name;
    const Status s = RunVariant(o, speeds, suite, &v, &rng, &done, 2 * o.replicates);
    if (!s.ok()) return s;
    suite->variants.push_back(std::move(v));
  }
  suite->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Success();
}

std::vector<std::string> FrfSuite::Failing() const {
  std::vector<std::string> out;
  for (const FrfVariant& v : variants) {
    const int fits = v.tires - v.failed_fits;
    const std::string at = v.name + ": ";
    if (v.failed_fits > 0) out.push_back(at + std::to_string(v.failed_fits) + " failed fits");
    if (v.best_found < best_share * v.tires) out.push_back(at + "best found in " + Percent(v.best_found, v.tires));
    if (!(v.coverage_95 >= coverage_range.first && v.coverage_95 <= coverage_range.second)) {
      out.push_back(at + "coverage " + Percent(static_cast<int>(std::lround(1000 * v.coverage_95)), 1000));
    }
    if (v.masses_within < mass_share * fits) out.push_back(at + "masses within in " + Percent(v.masses_within, fits));
    if (v.name != "standing" && v.contact_separated < separated_share * fits) {
      out.push_back(at + "K_cx and sigma_cx separated in " + Percent(v.contact_separated, fits));
    }
  }
  return out;
}

std::string FrfSuite::Markdown() const {
  std::ostringstream o;
  for (const FrfVariant& v : variants) {
    o << "\n### " << v.name << "\n\n" << CoverageTableHeader();
    for (const StaticParameter& r : v.parameters) o << CoverageRow(r.param, r);
    char line[400];
    std::snprintf(line, sizeof line,
                  "\n%d tires: best found in %d, pooled 95 %% coverage %.3f (%ld intervals), m_b "
                  "and I_by within %g %% in %d, K_cx and sigma_cx both yes in %d; %d failed fits; "
                  "%.2f s per fit\n",
                  v.tires, v.best_found, v.coverage_95, v.intervals, 100 * mass_tolerance,
                  v.masses_within, v.contact_separated, v.failed_fits, v.seconds_per_fit);
    o << line;
  }
  o << "\ninitial values within a factor " << start_factor << ", " << starts
    << " starts; pass: " << (Pass() ? "yes" : "no") << "\n";
  for (const std::string& f : Failing()) o << "- " << f << "\n";
  return o.str();
}

}  // namespace ringid
