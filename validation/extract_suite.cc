// The extract suite (validation/extract_suite.h).
#include "validation/extract_suite.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <sstream>

#include "datasets/synthetic.h"
#include "estimation/extract.h"
#include "estimation/statistics.h"

namespace ringid {
namespace {


const Mode* WithLabel(const ModalSolution& s, ModeLabel label) {
  for (const Mode& m : s.modes) {
    if (m.label == label) return &m;
  }
  return nullptr;
}

// ScatteredTire with its masses and inertias scattered as its stiffnesses.
Parameters RandomMassTire(std::mt19937_64* rng) {
  Parameters p = ScatteredTire(rng);
  std::normal_distribution<double> normal(0, 1);
  for (int i = 0; i < kNumParams; ++i) {
    const Param q = ParamAt(i);
    if (IsMassOrInertia(q) && p.IsSet(q)) p[q] *= std::exp(kTireSpread * normal(*rng));
  }
  p[Param::I_bz] = p[Param::I_bx];  // a ring
  return p;
}

// One tire's hammer test, its initial values within start_factor; false
// where its truth cannot be simulated.
bool HammerTire(const Parameters& truth, const ExtractSuite& suite, std::mt19937_64* rng,
                Dataset* d, std::string* why) {
  *d = PlanSimulation(truth, 0, {0}, {}, rng);
  FreeMasses(truth, 0, rng, d);
  d->conditions[0].frf = HammerTest(0.31, 5, 250, suite.line_step_hz);
  SimulateOptions so;
  so.modes = false;
  so.frf_noise = suite.frf_noise;
  if (!Simulate(RigidRingModel(), truth, so, rng, d, why)) return false;
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (auto& [q, v] : d->initial) v = truth[q] * std::pow(suite.start_factor, uniform(*rng));
  return true;
}

// The extraction of one tire against the model's modes at its truth.
void Score(const ExtractSuite& suite, const Parameters& truth, const ExtractResult& r, int tire,
           ExtractVariant* v) {
  const ModalSolution s = RigidRingModel().Solve(truth);
  for (const Mode& m : s.modes) {
    ++v->modes;
    ExtractMiss miss{tire, LabelName(m.label), m.frequency_hz, m.damping_ratio};
    const auto found = std::find_if(r.dataset.modes.begin(), r.dataset.modes.end(),
                                    [&](const MeasuredMode& x) { return x.label == m.label; });
    if (found == r.dataset.modes.end()) {
      v->misses.push_back(miss);
      continue;
    }
    const MeasuredMode& x = *found;
    ++v->found;
    miss.extracted_frequency_hz = x.frequency_hz;
    miss.extracted_damping_ratio = x.damping_ratio;
    miss.frequency_sigma_hz = x.frequency_sigma_hz;
    miss.damping_sigma = x.damping_sigma;
    const double df = std::abs(x.frequency_hz / m.frequency_hz - 1);
    const double dz = x.damping_ratio ? std::abs(*x.damping_ratio / m.damping_ratio - 1) : INFINITY;
    v->frequency_within += df <= suite.frequency_tolerance;
    v->damping_within += dz <= suite.damping_tolerance;
    if (df > suite.frequency_tolerance || dz > suite.damping_tolerance) v->misses.push_back(miss);
    v->worst_frequency = std::max(v->worst_frequency, df);
    v->worst_damping = std::max(v->worst_damping, dz);
    if (!x.frequency_sigma_hz || !x.damping_sigma || !x.damping_ratio) continue;
    const double zf = (x.frequency_hz - m.frequency_hz) / *x.frequency_sigma_hz;
    const double zd = (*x.damping_ratio - m.damping_ratio) / *x.damping_sigma;
    v->unresolved_misses +=
        (df > suite.frequency_tolerance &&
         kNormal95 * *x.frequency_sigma_hz > suite.frequency_tolerance * m.frequency_hz) +
        (dz > suite.damping_tolerance &&
         kNormal95 * *x.damping_sigma > suite.damping_tolerance * m.damping_ratio);
    const auto outside = [](double tolerance, double sd) { return std::erfc(tolerance / sd / std::sqrt(2.0)); };
    v->frequency_misses_expected += outside(suite.frequency_tolerance * m.frequency_hz, *x.frequency_sigma_hz);
    v->damping_misses_expected += outside(suite.damping_tolerance * m.damping_ratio, *x.damping_sigma);
    ++v->intervals;
    v->frequency_covered += std::abs(zf) <= kNormal95;
    v->damping_covered += std::abs(zd) <= kNormal95;
    v->frequency_bias_sd += zf;  // a sum until RunVariant divides
    v->damping_bias_sd += zd;
  }
}

// Whether the pair stands alone: no third mode within twice its gap of
// either (a third mode there makes a cluster, not a pair).
bool PairAlone(const Parameters& p, double gap_hz) {
  const ModalSolution s = RigidRingModel().Solve(p);
  const Mode* camber = WithLabel(s, ModeLabel::kCamber);
  const Mode* vertical = WithLabel(s, ModeLabel::kVertical);
  if (!camber || !vertical) return false;
  for (const Mode& m : s.modes) {
    if (&m == camber || &m == vertical) continue;
    if (std::abs(m.frequency_hz - camber->frequency_hz) < 2 * gap_hz ||
        std::abs(m.frequency_hz - vertical->frequency_hz) < 2 * gap_hz) {
      return false;
    }
  }
  return true;
}

Status RunVariant(const SuiteOptions& o, bool close_pair, ExtractSuite* suite, ExtractVariant* v,
                  std::mt19937_64* rng, int* done, int total) {
  double seconds = 0;
  for (int k = 0; k < o.replicates; ++k) {
    Parameters truth;
    Dataset d;
    const Status drawn = DrawExtractTire(*suite, close_pair, rng, &truth, &d);
    if (!drawn.ok()) return drawn;
    d.name = v->name + "_" + std::to_string(k);
    const auto start = std::chrono::steady_clock::now();
    ExtractResult r;
    ExtractModalDataset(RigidRingModel(), d, PlscfOptions{}, &r);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++v->tires;
    if (r.status.ok()) Score(*suite, truth, r, k, v);
    else ++v->failed;
    if (o.on_case) o.on_case(++*done, total);
  }
  v->seconds_per_tire = v->tires ? seconds / v->tires : NAN;
  v->frequency_bias_sd = v->intervals ? v->frequency_bias_sd / v->intervals : NAN;
  v->damping_bias_sd = v->intervals ? v->damping_bias_sd / v->intervals : NAN;
  return Status::Success();
}

std::string Count(int n, int of) { return std::to_string(n) + " of " + std::to_string(of); }

}  // namespace

Status DrawExtractTire(const ExtractSuite& suite, bool close_pair, std::mt19937_64* rng,
                       Parameters* truth, Dataset* d) {
  std::string why;
  for (int draw = 0; draw <= 100; ++draw) {
    *truth = RandomMassTire(rng);
    if ((!close_pair || (CloseCamberAndVertical(suite.pair_gap_hz, suite.pair_damping, truth) &&
                         PairAlone(*truth, suite.pair_gap_hz))) &&
        HammerTire(*truth, suite, rng, d, &why)) {
      return Status::Success();
    }
  }
  return Status::Failed("no plausible tire in 100 draws: " + why);
}

bool CloseCamberAndVertical(double gap_hz, double zeta, Parameters* p) {
  for (int step = 0; step < 50; ++step) {
    const ModalSolution s = RigidRingModel().Solve(*p);
    if (!s.ok) return false;
    const Mode* camber = WithLabel(s, ModeLabel::kCamber);
    const Mode* vertical = WithLabel(s, ModeLabel::kVertical);
    if (!camber || !vertical) return false;
    const double target = vertical->frequency_hz - gap_hz;
    if (std::abs(camber->frequency_hz - target) < 1e-6 * target &&
        std::abs(camber->damping_ratio - zeta) < 1e-6 && std::abs(vertical->damping_ratio - zeta) < 1e-6) {
      return true;
    }
    if (!(target > 0)) return false;
    (*p)[Param::k_bgamma] *= std::pow(target / camber->frequency_hz, 2);
    (*p)[Param::k_bpsi] = (*p)[Param::k_bgamma];
    (*p)[Param::c_bgamma] *= zeta / camber->damping_ratio;
    (*p)[Param::c_bpsi] = (*p)[Param::c_bgamma];
    (*p)[Param::c_bz] *= zeta / vertical->damping_ratio;
    (*p)[Param::c_bx] = (*p)[Param::c_bz];
  }
  return false;
}

Status RunExtractSuite(const SuiteOptions& o, ExtractSuite* suite) {
  if (o.replicates < 1) return Status::InvalidInput("replicates: must be at least 1");
  if (!(o.start_factor >= 1)) return Status::InvalidInput("start_factor: must be at least 1");
  const auto start = std::chrono::steady_clock::now();
  suite->start_factor = o.start_factor;
  suite->frf_noise = SimulateOptions{}.frf_noise;
  std::mt19937_64 rng(o.seed);
  int done = 0;
  for (const bool close_pair : {false, true}) {
    ExtractVariant v;
    v.name = close_pair ? "close_pair" : "standing";
    const Status s = RunVariant(o, close_pair, suite, &v, &rng, &done, 2 * o.replicates);
    if (!s.ok()) return s;
    suite->variants.push_back(std::move(v));
  }
  suite->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Success();
}

std::vector<std::string> ExtractSuite::Failing() const {
  std::vector<std::string> out;
  for (const ExtractVariant& v : variants) {
    const std::string at = v.name + ": ";
    if (v.failed > 0) out.push_back(at + std::to_string(v.failed) + " extractions failed");
    if (v.found < v.modes) out.push_back(at + "modes found and labelled: " + Count(v.found, v.modes));
    if (v.frequency_within < v.modes) {
      out.push_back(at + "frequencies within tolerance: " + Count(v.frequency_within, v.modes));
    }
    if (v.damping_within < v.modes) {
      out.push_back(at + "damping ratios within tolerance: " + Count(v.damping_within, v.modes));
    }
    const auto covers = [&](int n) {
      return v.intervals > 0 && n >= coverage_range.first * v.intervals &&
             n <= coverage_range.second * v.intervals;
    };
    if (!covers(v.frequency_covered)) {
      out.push_back(at + "frequency intervals covering: " + Count(v.frequency_covered, v.intervals));
    }
    if (!covers(v.damping_covered)) {
      out.push_back(at + "damping intervals covering: " + Count(v.damping_covered, v.intervals));
    }
  }
  return out;
}

std::string ExtractSuite::Markdown() const {
  std::ostringstream o;
  o << "| variant | tires | modes | found and labelled | f within " << 100 * frequency_tolerance
    << " % | zeta within " << 100 * damping_tolerance
    << " % | worst f error | worst zeta error | f covered | zeta covered | bias f, zeta (sd) | s per tire |\n"
       "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const ExtractVariant& v : variants) {
    char line[400];
    std::snprintf(line, sizeof line,
                  "| %s | %d | %d | %d | %d | %d | %.3g %% | %.3g %% | %d of %d | %d of %d | %+.2f, %+.2f | %.2f |\n",
                  v.name.c_str(), v.tires, v.modes, v.found, v.frequency_within, v.damping_within,
                  100 * v.worst_frequency, 100 * v.worst_damping, v.frequency_covered, v.intervals,
                  v.damping_covered, v.intervals, v.frequency_bias_sd, v.damping_bias_sd,
                  v.seconds_per_tire);
    o << line;
  }
  for (const ExtractVariant& v : variants) {
    char expected[160];
    std::snprintf(expected, sizeof expected, "; their standard errors predict %.1f frequencies and %.1f "
                  "damping ratios outside, against %d and %d", v.frequency_misses_expected,
                  v.damping_misses_expected, v.found - v.frequency_within, v.found - v.damping_within);
    o << "\n" << v.name << ": " << v.unresolved_misses
      << " of the values outside their tolerance have a 95 % interval wider than it" << expected;
  }
  o << "\n\n| variant | tire | mode | f truth (Hz) | f (Hz) | sd | zeta truth | zeta | sd |\n"
       "|---|---|---|---|---|---|---|---|---|\n";
  const auto value = [](const std::optional<double>& x, const char* format) {
    char text[40];
    std::snprintf(text, sizeof text, format, x.value_or(NAN));
    return x ? std::string(text) : std::string("-");
  };
  for (const ExtractVariant& v : variants) {
    for (const ExtractMiss& m : v.misses) {
      o << "| " << v.name << " | " << m.tire << " | " << m.label << " | " << value(m.frequency_hz, "%.2f")
        << " | " << value(m.extracted_frequency_hz, "%.2f") << " | " << value(m.frequency_sigma_hz, "%.2f")
        << " | " << value(m.damping_ratio, "%.4f") << " | " << value(m.extracted_damping_ratio, "%.4f")
        << " | " << value(m.damping_sigma, "%.4f") << " |\n";
    }
  }
  o << "\n\nclose_pair: the camber mode " << pair_gap_hz << " Hz below the vertical one, both at zeta "
    << pair_damping << "; " << 100 * frf_noise << " % noise, lines every " << line_step_hz
    << " Hz; initial values within a factor " << start_factor << "; pass: " << (Pass() ? "yes" : "no")
    << "\n";
  for (const std::string& f : Failing()) o << "- " << f << "\n";
  return o.str();
}

}  // namespace ringid
