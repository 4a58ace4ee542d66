#include "estimation/diagnose.h"
#include "estimation/diagnose_internal.h"

#include "estimation/detectable.h"
#include "estimation/fit.h"
#include "estimation/parallel.h"
#include "estimation/problem.h"
#include "estimation/score.h"
#include "estimation/statistics.h"
#include "estimation/uncertainty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <mutex>
#include <sstream>

#include "model/effects.h"

namespace ringid {

using internal::ModalResiduals;
using internal::ParameterSetup;

namespace {

// Per measured mode (and other measurement): its residuals in sigma, by
// observable (Measurement::AddMisfit).
MisfitTable Misfits(const std::vector<ModalResiduals::Slot>& slots,
                    const std::vector<double>& res, const Dataset& dataset,
                    const MeasurementOptions& o) {
  MisfitTable table;
  for (size_t k = 0; k < slots.size(); ++k) {
    if (slots[k].measurement) {
      slots[k].measurement->AddMisfit(dataset, slots[k].item, slots[k].component, res[k], o,
                                      &table);
    }
  }
  return table;
}

// The weighted residuals of `dataset` under `model` at the coordinates x of
// a fit of the same free parameters.
bool ResidualsAt(const ModalModel& model, const Dataset& dataset,
                 const Eigen::VectorXd& x, std::vector<ModalResiduals::Slot>* slots,
                 std::vector<double>* r, const ResidualOptions& options) {
  Status status;
  const auto problem = Problem::Create(model, dataset, options, &status);
  if (!problem || problem->setup().size() != x.size()) return false;
  r->assign(problem->residuals().num_residuals(), 0);
  *slots = problem->residuals().slots();
  return problem->residuals().Evaluate(x.data(), r->data());
}

std::vector<double> ModeChi2(const std::vector<ModalResiduals::Slot>& slots,
                             const std::vector<double>& r, size_t modes) {
  std::vector<double> chi2(modes, 0);
  for (size_t k = 0; k < slots.size(); ++k) {
    if (slots[k].measurement && &slots[k].measurement->records() == &ModeRecords()) {
      chi2[slots[k].item] += r[k] * r[k];
    }
  }
  return chi2;
}

// `dataset` with its free parameters seeded at `fitted` (a warm start).
Dataset WarmStart(const Dataset& dataset, const IdentifyResult& fitted) {
  Dataset d = dataset;
  for (const ParameterEstimate& e : fitted.estimates) {
    if (e.free) d.initial[e.param()] = e.value;
  }
  return d;
}

// Leave-one-mode-out: fit without each mode in turn, predict it; the sum of
// the predicted modes' chi-square.
// A dropped mode frees the directions only it determined, which a fit then
// wanders along until its prediction is lost: each refit holds the values of
// the fit with every mode (`warm`'s initial values, not the user's guess) as
// a lognormal prior of log-sd kHeldOutPriorSigma where no prior is declared.
constexpr double kHeldOutPriorSigma = 0.2;
std::optional<double> HeldOut(const ModalModel& model, const Dataset& warm,
                              const DiagnoseOptions& o) {
  if (warm.modes.size() < 2) return std::nullopt;
  IdentifyOptions one = o.fit;
  one.starts = 1;
  Dataset held = warm;
  for (const auto& [p, v] : warm.initial) {
    if (Info(p).domain == Domain::kPositive && v > 0 && !held.priors.count(p)) {
      held.priors[p] = {PriorDistribution::kLognormal, v, std::exp(kNormal95 * kHeldOutPriorSigma)};
    }
  }
  double total = 0;
  for (size_t j = 0; j < warm.modes.size(); ++j) {
    Dataset without = held;
    without.modes.erase(without.modes.begin() + j);
    IdentifyResult s;
    Identify(model, without, one, &s);
    if (!s.status.ok()) return std::nullopt;
    std::vector<ModalResiduals::Slot> slots;
    std::vector<double> r;
    if (!ResidualsAt(model, warm, s.x, &slots, &r, o.fit.residuals)) return std::nullopt;
    total += ModeChi2(slots, r, warm.modes.size())[j];
  }
  return total;
}

// An effect fit may end this much (in cost) above the baseline's optimum and still
// count as having reached it: the stopping rule's own resolution.
constexpr double kEffectFitSlack = 0.05;

// Cost of `dataset` under `model` at its initial values (+inf if unsolvable).
double InitialCost(const ModalModel& model, const Dataset& dataset, const ResidualOptions& options) {
  Status status;
  const auto problem = Problem::Create(model, dataset, options, &status);
  return problem ? CostAt(problem->residuals(), problem->start()) : INFINITY;
}

// An effect fitted on top of the calibrated baseline (`warm`): from its
// optimum with the effect at 0, and from the best points of a scan of the
// effect's parameters over +-{0.1, 0.3, 1, 3, 10} typical scales (from 0
// alone a non-smooth effect such as a hub released at s_h = 0 is not found).
// The effect at 0 is the baseline, so a fit that ends above the baseline's
// cost has failed: the next seed of the scan is tried, up to kEffectSeeds.
constexpr int kEffectSeeds = 4;
constexpr int kEffectStarts = 3;
constexpr int kEffectColdIterations = 50;
IdentifyResult FitEffect(const RigidRingModel& model, const Effect& effect, const Dataset& warm,
                          const Dataset& dataset, double baseline_cost,
                          const DiagnoseOptions& o) {
  IdentifyOptions one = o.fit;
  one.starts = 1;
  std::vector<std::pair<double, Dataset>> seeds;
  for (Param p : effect.parameters()) {
    if (warm.known.count(p)) continue;
    for (double g : {0.1, 0.3, 1.0, 3.0, 10.0}) {
      for (double sign : {1.0, -1.0}) {
        if (sign < 0 && Info(p).domain != Domain::kReal) continue;
        Dataset d = warm;
        d.initial[p] = sign * g * TypicalScale(p);
        seeds.emplace_back(InitialCost(model, d, o.fit.residuals), d);
      }
    }
  }
  std::stable_sort(seeds.begin(), seeds.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<const Dataset*> starts = {&warm};
  for (const auto& [cost, d] : seeds) {
    if (std::isfinite(cost)) starts.push_back(&d);
  }
  IdentifyResult best;
  int tried = 0;
  for (const Dataset* start : starts) {
    // Two seeds always (0 and the scan's best); more while none reached the baseline.
    if (tried >= 2 && best.status.ok() && best.cost <= baseline_cost + kEffectFitSlack) break;
    if (tried >= kEffectSeeds) break;
    ++tried;
    IdentifyResult s;
    Identify(model, *start, one, &s);
    if (s.status.ok() && (!best.status.ok() || s.cost < best.cost)) best = s;
    if (!best.status.ok() && best.status.message.empty()) best = s;
  }
  // The baseline may have bent itself to absorb part of the effect, a basin
  // LM does not leave: the effect's model also gets identify's own starts
  // (kEffectStarts of them, each at most kEffectColdIterations: a hub's cold
  // starts crawl at 22 times the baseline's chi-square), its parameters at the scan's best size.
  Dataset cold = dataset;
  if (starts.size() > 1) {
    for (Param p : effect.parameters()) {
      if (starts[1]->initial.count(p)) cold.initial[p] = starts[1]->initial.at(p);
    }
  } else {
    for (Param p : effect.parameters()) {
      if (!cold.known.count(p)) cold.initial[p] = Info(p).domain == Domain::kPositive ? TypicalScale(p) : 0;
    }
  }
  IdentifyOptions multi = o.fit;
  multi.starts = std::min(o.fit.starts, kEffectStarts);
  multi.max_iterations = std::min(o.fit.max_iterations, kEffectColdIterations);
  IdentifyResult s;
  Identify(model, cold, multi, &s);
  if (s.status.ok() && (!best.status.ok() || s.cost < best.cost)) best = s;
  return best;
}

// DiagnoseOptions::on_step's count, one call at a time from any thread.
class Steps {
 public:
  Steps(const std::function<void(int, int)>& report, int total) : report_(report), total_(total) {
    Report(0);
  }
  void Done() { Report(1); }
  void More(int n) {  // a re-calibration and its candidates
    std::lock_guard<std::mutex> lock(mutex_);
    total_ += n;
  }

 private:
  void Report(int add) {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ += add;
    if (report_) report_(done_, total_);
  }
  const std::function<void(int, int)>& report_;
  std::mutex mutex_;
  int done_ = 0, total_;
};

}  // namespace

void DiagnoseWithOptions(const RigidRingModel& baseline, const Dataset& dataset,
                         const DiagnoseOptions& o, DiagnosisResult* r, std::chrono::steady_clock::time_point t0);

std::string internal::HeldOutChange(double before, double after) {
  std::ostringstream o;
  const double change = 1 - after / before;
  o << "on held-out modes (each predicted from a fit without it) the misfit "
    << (change >= 0 ? "falls" : "rises") << " from chi-square " << before << " to " << after;
  if (change >= 0) {
    o << " (" << static_cast<int>(std::round(100 * change)) << " % less)";
  } else {
    o << ": the effect predicts unseen modes worse than the baseline, which weakens the verdict";
  }
  return o.str();
}

bool DiagnoseOptions::IsValid(std::string* why) const {
  if (!(gap_significance > 0 && gap_significance < 1) ||
      !(effect_significance > 0 && effect_significance < 1)) {
    *why = "significance levels must lie in (0, 1)";
    return false;
  }
  if (!(detectable_likelihood_ratio > 0) || !std::isfinite(detectable_likelihood_ratio)) {
    *why = "detectable_likelihood_ratio must be finite and positive";
    return false;
  }
  if (!(screen_significance > 0 && screen_significance <= 1)) {
    *why = "screen_significance must lie in (0, 1]";
    return false;
  }
  if (!(absorbed_factor > 1)) {
    *why = "absorbed_factor must exceed 1";
    return false;
  }
  return fit.IsValid(why);
}

void Diagnose(const RigidRingModel& baseline, const Dataset& dataset, const DiagnoseOptions& o,
              DiagnosisResult* r) {
  const auto t0 = std::chrono::steady_clock::now();
  *r = DiagnosisResult{};
  std::string why;
  if (!o.IsValid(&why)) {
    r->status = Status::InvalidInput("invalid options: " + why);
    return;
  }
  if (!dataset.per_condition.empty()) {
    r->status = Status::InvalidInput(
        "diagnose does not take per-condition parameters yet (per_condition); conditions that "
        "differ only in speed are fine");
    return;
  }
  DiagnoseWithOptions(baseline, dataset, o, r, t0);
}

namespace {

// Baseline parameters that had absorbed part of the gap: those the verdict's
// fit `with` moves beyond o.absorbed_factor from the baseline's optimum, or
// without a verdict those beyond kPriorConflictZ of a declared prior.
std::vector<std::string> Absorbed(const IdentifyResult& calibrated, const IdentifyResult* with,
                                  const DiagnoseOptions& o) {
  std::vector<std::string> absorbed;
  char line[200];
  for (const ParameterEstimate& e : calibrated.estimates) {
    if (!e.free) continue;
    if (!with) {
      if (!e.PriorConflict()) continue;
      std::snprintf(line, sizeof line, "%s = %.4g is %.1f prior sigma from its prior",
                    e.key.Text().c_str(), e.value, *e.prior_z);
      absorbed.push_back(line);
      continue;
    }
    for (const ParameterEstimate& f : with->estimates) {
      if (!(f.key == e.key) || !(e.value > 0) || !(f.value > 0)) continue;
      const double factor = e.value / f.value;
      if (std::abs(std::log(factor)) <= std::log(o.absorbed_factor)) continue;
      std::snprintf(line, sizeof line, "%s = %.4g in the baseline, %.4g with the effect (x %.2f)",
                    e.key.Text().c_str(), e.value, f.value, factor);
      absorbed.push_back(line);
    }
  }
  return absorbed;
}

// One candidate effect refitted on top of the calibrated baseline, with the
// evidence for it against the baseline.
// `fitted` receives the effect's fit.
EffectFit FitCandidate(const RigidRingModel& baseline, const Effect& effect, const Dataset& warm,
                       const Dataset& dataset, const DiagnosisResult& r, const DiagnoseOptions& o,
                       IdentifyResult* fitted) {
  EffectFit f;
  f.effect = &effect;
  const RigidRingModel model = baseline.With(&effect);
  const IdentifyResult s = FitEffect(model, effect, warm, dataset, r.baseline.cost, o);
  *fitted = s;
  if (!s.status.ok()) {
    f.note = "not fitted: " + s.status.message;
    return f;
  }
  if (s.cost > r.baseline.cost + kEffectFitSlack) {
    char b[240];
    std::snprintf(b, sizeof b,
                  "not fitted: a failed fit, not evidence: from every seed it ended above the baseline's "
                  "chi-square (%.6g against %.6g), which the effect at 0 reproduces",
                  2 * s.cost, r.chi2_before);
    f.note = b;
    return f;
  }
  const int m = static_cast<int>(r.baseline.uncertainty.jacobian.rows());
  const int n_base = static_cast<int>(r.baseline.coordinate_names.size());
  f.ok = true;
  f.chi2 = 2 * s.cost;
  f.extra_parameters = static_cast<int>(s.coordinate_names.size()) - n_base;
  f.lrt_statistic = std::max(0.0, r.chi2_before - f.chi2);
  f.lrt_p = f.extra_parameters > 0 ? ChiSquareTail(f.lrt_statistic, f.extra_parameters) : 1.0;
  if (f.extra_parameters > 0) {
    f.lrt_threshold = ChiSquareCritical(o.effect_significance, f.extra_parameters);
  }
  f.aic = f.chi2 + 2 * (n_base + f.extra_parameters);
  f.bic = f.chi2 + std::log(std::max(m, 1)) * (n_base + f.extra_parameters);
  f.gap_after = std::max(0.0, f.chi2 - std::max(r.dof - f.extra_parameters, 0));
  f.shrink = r.gap_before > 0 ? 1 - f.gap_after / r.gap_before : 0;
  // The targeted likelihood-ratio test is far more powerful than the
  // omnibus chi-square of the gap: an effect stands on its own test.
  const double aic_base = r.chi2_before + 2 * n_base;
  f.supported = r.p_value && f.lrt_p < o.effect_significance && f.aic < aic_base - 2;
  for (Param p : effect.parameters()) {
    if (s.parameters.IsSet(p)) f.values[ParamName(p)] = s.parameters[p];
  }
  // What free parameters absorb, these data cannot show: never supported.
  f.absorbed_by = internal::AbsorbedBy(model, dataset, effect, s, o.fit.residuals);
  f.supported = f.supported && !f.AbsorbedWhole();
  std::vector<ModalResiduals::Slot> es;
  std::vector<double> er;
  if (ResidualsAt(model, dataset, s.x, &es, &er, o.fit.residuals)) {
    f.mode_chi2 = ModeChi2(es, er, dataset.modes.size());
    f.where = Misfits(es, er, dataset, o.fit.residuals).modes;
  }
  if (f.supported && o.held_out) f.held_out_chi2 = HeldOut(model, WarmStart(warm, s), o);
  f.minimal_detectable =
      internal::MinimalDetectable(baseline, effect, warm, r.baseline.uncertainty.jacobian,
                                  r.baseline.uncertainty.rank, o, o.detectable_likelihood_ratio);
  for (const auto& [name, by] : f.absorbed_by) f.minimal_detectable.erase(name);
  return f;
}

// An effect the score test leaves out (Refitted): its score, what free
// parameters absorb of it and its detectable sizes, without a fit.
EffectFit ScreenedCandidate(const RigidRingModel& baseline, const Effect& effect,
                            const Dataset& warm, const internal::EffectScore& score,
                            const DiagnosisResult& r, const DiagnoseOptions& o) {
  EffectFit f;
  f.effect = &effect;
  char b[320];
  if (score.dof == 0) {
    std::snprintf(b, sizeof b, "not refitted: at the baseline's optimum it has no first-order "
                               "signature beyond what the free parameters already do");
  } else {
    std::snprintf(b, sizeof b,
                  "not refitted: its score test at the baseline's optimum, %.3g on %d "
                  "parameter(s), p = %.3g, is above the screen's %.3g, and no refitted effect's "
                  "signature overlaps it",
                  score.statistic, score.dof, score.p, o.screen_significance);
  }
  f.note = b;
  const RigidRingModel model = baseline.With(&effect);
  Dataset at = warm;  // away from a kink at 0 (a hub released at s_h = 0), as MinimalDetectable
  for (Param p : effect.parameters()) {
    if (!at.known.count(p)) at.initial[p] = TypicalScale(p);
  }
  f.absorbed_by = internal::AbsorbedAt(model, at, effect, o.fit.residuals);
  f.minimal_detectable =
      internal::MinimalDetectable(baseline, effect, warm, r.baseline.uncertainty.jacobian,
                                  r.baseline.uncertainty.rank, o, o.detectable_likelihood_ratio);
  for (const auto& [name, by] : f.absorbed_by) f.minimal_detectable.erase(name);
  return f;
}

// Which candidates to refit: those whose score test passes the screen, those
// it cannot judge (no score, or no derivative at 0 to base one on), and their
// rivals (SignatureOverlap above kRivalOverlap).
std::vector<char> Refitted(const std::vector<internal::EffectScore>& scores, double level) {
  const size_t n = scores.size();
  std::vector<char> kept(n);
  for (size_t k = 0; k < n; ++k) {
    kept[k] = level >= 1 || !scores[k].ok || !scores[k].smooth || scores[k].p < level;
  }
  std::vector<char> refit = kept;
  for (size_t k = 0; k < n; ++k) {
    for (size_t j = 0; j < n && !refit[k]; ++j) {
      refit[k] = kept[j] && scores[j].ok &&
                 internal::SignatureOverlap(scores[k], scores[j]) >= kRivalOverlap;
    }
  }
  return refit;
}

// The group of the verdict `best`: every fitted effect whose chi-square
// differs from best's by less than the chi-square significant at o's level on
// max(|difference in parameters|, 1) degrees of freedom (a likelihood-ratio
// threshold; exact for nested effects), each with its difference and
// threshold recorded. Returns the others in words ("" when none).
std::string Group(const EffectFit& best, const DiagnoseOptions& o, DiagnosisResult* r) {
  std::ostringstream others;
  char b[160];
  for (EffectFit& f : r->ranking) {
    if (!f.ok || f.AbsorbedWhole()) continue;  // the baseline itself, on these data
    const int dof = std::max(std::abs(f.extra_parameters - best.extra_parameters), 1);
    f.chi2_above_verdict = f.chi2 - best.chi2;
    f.group_threshold = ChiSquareCritical(o.effect_significance, dof);
    if (!(std::abs(f.chi2_above_verdict) < f.group_threshold)) continue;
    r->indistinguishable.push_back(f.effect);
    if (f.effect == best.effect) continue;
    std::snprintf(b, sizeof b, "%s%s (chi-square %+.3g against %.3g on %d dof)",
                  others.tellp() ? ", " : "", f.effect->name(), f.chi2_above_verdict,
                  f.group_threshold, dof);
    others << b;
  }
  if (r->indistinguishable.size() < 2) r->indistinguishable.clear();
  return others.str();
}

// The verdict from the ranking: the supported effect of least AIC, its group
// (Group), and in words why.
void Verdict(const RigidRingModel& baseline, const Dataset& warm, const std::vector<double>& before,
             const DiagnoseOptions& o, DiagnosisResult* r, std::ostringstream* why) {
  r->level = o.effect_significance;
  const EffectFit* best = nullptr;
  for (const EffectFit& f : r->ranking) {
    if (f.supported && (!best || f.aic < best->aic)) best = &f;
  }
  if (!r->p_value) {
    *why << "no degree of freedom is left (" << r->baseline.uncertainty.jacobian.rows()
         << " residuals, rank " << r->baseline.uncertainty.rank << "): the baseline can match these data "
         << "exactly, so no gap can be detected and no effect supported";
    return;
  }
  if (!best && !r->significant) {
    *why << "no significant gap: chi-square " << r->chi2_before << " on " << r->dof
         << " degrees of freedom (p = " << *r->p_value << "), and no effect's likelihood-ratio test passes";
    return;
  }
  if (!best) {
    *why << "the gap is significant (p = " << *r->p_value
         << ") but no catalogue effect explains it beyond a re-calibration of the baseline";
    return;
  }
  r->verdict = best->effect;
  const std::string others = Group(*best, o, r);
  *why << best->effect->name() << " removes " << static_cast<int>(std::round(100 * best->shrink))
       << " % of the gap (likelihood ratio " << best->lrt_statistic << " on "
       << best->extra_parameters << " parameter(s), p = " << best->lrt_p << ")";
  *why << (others.empty() ? "; no other effect" : "; these data cannot tell it from " + others)
       << (others.empty() ? " fits" : ": each fits")
       << " within the chi-square significant at level " << o.effect_significance
       << " of it (degrees of freedom: the difference in parameters, at least 1)";
  if (o.held_out) r->held_out_before = HeldOut(baseline, warm, o);
  if (r->held_out_before && best->held_out_chi2 && *r->held_out_before > 0) {
    *why << "; " << internal::HeldOutChange(*r->held_out_before, *best->held_out_chi2);
  }
  for (size_t i = 0; i < before.size() && i < best->mode_chi2.size(); ++i) {
    r->mode_shrink.push_back(before[i] > 0 ? 1 - best->mode_chi2[i] / before[i] : 0);
  }
}

// The explanation's end: for a "none" verdict the sizes a re-calibration
// would absorb, and for any verdict the effects' parameters that free
// parameters absorb whatever their size.
void Conclude(const RigidRingModel& baseline, const Dataset& warm, const DiagnoseOptions& o,
              DiagnosisResult* r, std::ostringstream* why) {
  if (!r->verdict && r->p_value) {
    if (!r->absorbed.empty() && r->significant) *why << "; part of it sits in the parameters";
    const std::string sizes = internal::DetectableSizes(baseline, warm, o, r);
    if (!sizes.empty()) *why << ". A re-calibration of the baseline would absorb, undetected: " << sizes;
  }
  std::string whole;
  for (const EffectFit& f : r->ranking) {
    for (const auto& [name, by] : f.absorbed_by) {
      whole += (whole.empty() ? "" : ", ") + name + " of " + f.effect->name() + " (by";
      for (size_t i = 0; i < by.size(); ++i) whole += (i ? ", " : " ") + by[i];
      whole += ")";
    }
  }
  if (!whole.empty()) {
    *why << ". Free parameters absorb these whatever their size, so these data cannot show them "
            "while those are free: "
         << whole;
  }
}

}  // namespace

bool EffectFit::AbsorbedWhole() const {
  if (!effect || absorbed_by.empty()) return false;
  for (Param p : effect->parameters()) {
    const std::string name = ParamName(p);
    // A fit's values are its free parameters; unfitted, every one counts.
    const bool sizes = Info(p).domain != Domain::kPositive && (!ok || values.count(name));
    if (sizes && !absorbed_by.count(name)) return false;
  }
  return true;
}

// Whether `s`, a fit with `effect`, holds the effect at 0 (it is then the
// baseline's model).
bool EffectOff(const Effect& effect, const IdentifyResult& s) {
  for (Param p : effect.parameters()) {
    if (Info(p).domain != Domain::kPositive &&
        !(std::abs(s.parameters[p]) <= 1e-6 * TypicalScale(p))) {
      return false;
    }
  }
  return true;
}

namespace {

// Each candidate's score test, then the fits of those it keeps (Refitted), into
// r->ranking and `fits` (one per candidate); on o.fit.threads, shared as they free.
void ScoreAndFit(const RigidRingModel& baseline, const std::vector<const Effect*>& candidates,
                 const Dataset& warm, const Dataset& dataset, const DiagnoseOptions& o,
                 Steps* steps, DiagnosisResult* r, std::vector<IdentifyResult>* fits) {
  const int n = static_cast<int>(candidates.size());
  std::vector<internal::EffectScore> scores(n);
  internal::ParallelFor(n, o.fit.threads, [&](int k) {
    scores[k] = internal::ScoreEffect(baseline, *candidates[k], warm, o.fit.residuals,
                                      o.fit.uncertainty.rank_tolerance);
  });
  // A first-order test reads a gap an effect closes near size 0; a baseline that misses
  // by far more than the noise (kScreenReducedChiSquare) is no such place: all refitted.
  const bool local = r->chi2_before <= kScreenReducedChiSquare * std::max(r->dof, 1);
  const std::vector<char> refit = Refitted(scores, local ? o.screen_significance : 1.0);
  DiagnoseOptions one_thread = o;
  one_thread.fit.threads = 1;
  const auto fit = [&](int k) {
    r->ranking[k] = FitCandidate(baseline, *candidates[k], warm, dataset, *r, o, &(*fits)[k]);
  };
  internal::ParallelFor(n, o.fit.threads, [&](int k) {
    if (refit[k]) {
      fit(k);
    } else {
      r->ranking[k] = ScreenedCandidate(baseline, *candidates[k], warm, scores[k], *r, one_thread);
    }
    steps->Done();
  });
  // The screen must not shrink the verdict's group (Group): a screened
  // effect whose score, its likelihood ratio to first order, comes within
  // the group's threshold of the best supported effect's is fitted too.
  const EffectFit* best = nullptr;  // as Verdict picks it
  for (const EffectFit& f : r->ranking) {
    if (f.supported && (!best || f.aic < best->aic)) best = &f;
  }
  std::vector<int> near;
  for (int k = 0; best && k < n; ++k) {
    if (refit[k] || !scores[k].ok || scores[k].dof == 0) continue;
    const int dof = std::max(std::abs(scores[k].dof - best->extra_parameters), 1);
    if (scores[k].statistic > best->lrt_statistic - ChiSquareCritical(o.effect_significance, dof)) {
      near.push_back(k);
    }
  }
  internal::ParallelFor(static_cast<int>(near.size()), o.fit.threads,
                        [&](int i) { fit(near[i]); });
  for (int k = 0; k < n; ++k) {
    if (!scores[k].ok) continue;
    r->ranking[k].score_statistic = scores[k].statistic;
    r->ranking[k].score_dof = scores[k].dof;
    r->ranking[k].score_p = scores[k].p;
  }
}

}  // namespace

void DiagnoseWithOptions(const RigidRingModel& baseline, const Dataset& dataset,
                         const DiagnoseOptions& o, DiagnosisResult* r, std::chrono::steady_clock::time_point t0) {
  // The gap: calibrate the baseline by the multistart of Identify, on the one
  // problem of the baseline and the data.
  int candidates_in_catalogue = 0;
  for (const Effect* effect : EffectCatalogue()) candidates_in_catalogue += !baseline.Has(effect);
  Steps steps(o.on_step, candidates_in_catalogue + 2);  // the baseline, each candidate, the verdict
  const auto problem = Problem::Create(baseline, dataset, o.fit.residuals, &r->baseline.status);
  if (problem) Identify(*problem, o.fit, &r->baseline);
  steps.Done();
  std::vector<IdentifyResult> fits;
  // A candidate that holds its effect at 0 and still fits better than the
  // baseline shows that the baseline missed its optimum: re-calibrate from
  // that point and start again (at most twice).
  for (int attempt = 0;; ++attempt) {
    if (!r->baseline.status.ok()) {
      r->status = {r->baseline.status.outcome,
                   "the baseline could not be calibrated: " + r->baseline.status.message};
      return;
    }
    r->chi2_before = r->baseline.fit.chi_square;
    r->dof = r->baseline.fit.degrees_of_freedom;
    r->p_value = r->baseline.fit.p_value;
    r->significant = r->p_value && *r->p_value < o.gap_significance;
    r->gap_before = std::max(0.0, r->chi2_before - std::max(r->dof, 0));
    const Dataset warm = WarmStart(dataset, r->baseline);
    std::vector<const Effect*> candidates;
    for (const Effect* effect : EffectCatalogue()) {
      if (!baseline.Has(effect)) candidates.push_back(effect);
    }
    const int n = static_cast<int>(candidates.size());
    r->ranking.assign(n, EffectFit{});
    fits.assign(n, IdentifyResult{});
    ScoreAndFit(baseline, candidates, warm, dataset, o, &steps, r, &fits);
    int better = -1;
    for (int k = 0; k < n; ++k) {
      const IdentifyResult& s = fits[k];
      if (s.status.ok() && s.cost < r->baseline.cost - 0.5 * kSameOptimumChiSquare &&
          (EffectOff(*candidates[k], s) || r->ranking[k].AbsorbedWhole()) &&
          (better < 0 || s.cost < fits[better].cost)) {
        better = k;
      }
    }
    if (better < 0 || attempt == 2) break;
    steps.More(1);  // the re-calibration
    IdentifyOptions one = o.fit;
    one.starts = 1;
    IdentifyResult recalibrated;
    const Effect& off = *r->ranking[better].effect;  // at 0, or moved there along what absorbs it
    Identify(baseline, internal::BaselineFrom(baseline.With(&off), dataset, off, fits[better],
                                              o.fit.residuals), one, &recalibrated);
    steps.Done();
    if (!recalibrated.status.ok() || !(recalibrated.cost < r->baseline.cost)) break;
    // The baseline's starts, and this one after them.
    const double cost = recalibrated.cost;
    recalibrated.start_costs = r->baseline.start_costs;
    recalibrated.start_origins = r->baseline.start_origins;
    recalibrated.start_costs.push_back(cost);
    recalibrated.start_origins.push_back(StartOrigin::kEffectAtZero);
    recalibrated.start_agreement = r->baseline.start_agreement;
    recalibrated.start_agreement.verdict +=
        "; a fit holding an effect at 0 (or one free parameters absorb, moved to 0 along them) "
        "then found a lower chi-square, from which the baseline was calibrated again";
    r->baseline = std::move(recalibrated);
    steps.More(n);  // the candidates again
  }
  const Dataset warm = WarmStart(dataset, r->baseline);

  // Where it lies: per mode and observable, and in the parameters.
  const ModalResiduals& residuals = problem->residuals();
  const std::vector<ModalResiduals::Slot>& slots = residuals.slots();
  std::vector<double> res(residuals.num_residuals());
  if (r->baseline.x.size() != residuals.num_parameters() ||
      !residuals.Evaluate(r->baseline.x.data(), res.data())) {
    r->status = Status::Failed("the calibrated baseline cannot be evaluated");
    return;
  }
  const std::vector<double> before = ModeChi2(slots, res, dataset.modes.size());
  MisfitTable table = Misfits(slots, res, dataset, residuals.options());
  r->where = std::move(table.modes);
  if (!table.others.empty()) r->where_else = std::move(table.others);

  // Which effect: the fitted ranked by AIC, then the screened by their score.
  std::vector<int> order(r->ranking.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    const EffectFit& x = r->ranking[a];
    const EffectFit& y = r->ranking[b];
    if (x.ok != y.ok) return x.ok;
    if (x.ok) return x.aic < y.aic;
    // The unfitted by their score's p-value, those without one last.
    if (std::isnan(x.score_p) != std::isnan(y.score_p)) return std::isnan(y.score_p);
    return x.score_p < y.score_p;
  });
  std::vector<EffectFit> ranking;
  std::vector<IdentifyResult> ranked_fits;
  for (int k : order) {
    ranking.push_back(std::move(r->ranking[k]));
    ranked_fits.push_back(std::move(fits[k]));
  }
  r->ranking = std::move(ranking);
  std::ostringstream why;
  Verdict(baseline, warm, before, o, r, &why);
  const IdentifyResult* verdict_fit = nullptr;
  for (size_t k = 0; k < r->ranking.size(); ++k) {
    if (r->verdict && r->ranking[k].effect == r->verdict) verdict_fit = &ranked_fits[k];
  }
  r->absorbed = Absorbed(r->baseline, verdict_fit, o);
  Conclude(baseline, warm, o, r, &why);
  r->explanation = why.str();
  steps.Done();
  r->status = Status::Success();
  r->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace ringid
