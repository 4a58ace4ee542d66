#include "estimation/identify.h"

#include "estimation/frf_start.h"
#include "estimation/parallel.h"
#include "estimation/problem.h"
#include "estimation/starts.h"
#include "estimation/statistics.h"
#include "estimation/uncertainty.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>

namespace ringid {

using internal::Box;
using internal::LocalFit;
using internal::ModalResiduals;
using internal::ParameterSetup;

namespace {


double Seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
      .count();
}

// The estimate of p in condition c at the fitted point x.
ParameterEstimate Estimate(const ParameterSetup& setup, const ModalResiduals& residuals,
                           const Uncertainty& u, const Box& box, const Eigen::VectorXd& x,
                           Param p, int c) {
  ParameterEstimate e;
  e.key.param = p;
  e.value = setup.Decode(x.data(), c)[p];
  const auto tie = setup.ties().find(p);
  if (tie != setup.ties().end()) e.tied_to = tie->second;
  const int i = setup.CoordinateOf(p, c);
  e.free = i >= 0 && !e.tied_to;
  if (i >= 0 && !e.tied_to) e.on_bound = box.On(i, x[i]);
  if (i < 0) {
    e.identifiable = Identifiability::kYes;
    e.reason = e.tied_to ? "tied to a fixed parameter" : "fixed (known)";
    return e;
  }
  if (!u.ok) {
    e.identifiable = Identifiability::kNo;
    e.reason = u.error;
    return e;
  }
  e.identifiable = u.classes[i];
  e.reason = u.reasons[i];
  if (e.tied_to) e.reason = std::string("tied to ") + ParamName(*e.tied_to) + "; " + e.reason;
  if (e.identifiable != Identifiability::kNo) {
    for (const KnownDependence& d : u.known_dependence) {
      if (d.coordinate == i) {
        e.conditional_on.push_back({d.known, d.known_value, d.measured, d.structural});
      }
    }
  }
  const double sd = u.std[i];
  if (std::isfinite(sd)) {
    e.std = setup.PhysicalStd(i, x[i], sd);
    e.interval_95 = setup.Interval95(i, x[i], sd);
  }
  for (const auto& prior : residuals.priors()) {
    if (prior.coordinate != i || !u.covariance_ok || e.tied_to) continue;
    e.prior_share = u.covariance(i, i) / prior.CoordinateVariance(setup, x[i]);
    e.decided_by = *e.prior_share > kPriorDecides  ? DecidedBy::kPrior
                   : *e.prior_share < kDataDecides ? DecidedBy::kData
                                                   : DecidedBy::kDataAndPrior;
    e.prior_z = prior.Residual(setup, x[i]);
  }
  return e;
}

// Free parameters the data, not the model, tell from a known one only
// because it is fixed. Freed, known q's weighted-residual column j (exact
// derivatives in its coordinate) is partly absorbed by the free coordinates,
// b = C J^T j (C the covariance, J the Jacobian of `u`), and s = |j - J b|^2
// is all the data say of q; coordinate i's variance becomes C_ii + b_i^2 / s
// (the Schur complement). A coordinate classed yes that this leaves wider
// than practical_relative_std rests on q where it also moves materially
// with q (kKnownDependenceShare). One Jacobian of the freed problem.
// A parameter rests on a known one in the data only where an error in the
// known value moves it by at least this share and at most its inverse
// (relative to relative): below, freeing it costs too little to name; above,
// the first-order compensation means nothing.
constexpr double kKnownDependenceShare = 0.25;

void AddPracticalDependence(const ModalModel& model, const Dataset& dataset,
                            const IdentifyOptions& o, const ParameterSetup& setup,
                            const Eigen::VectorXd& x, Uncertainty* u) {
  if (!u->ok || !u->covariance_ok || setup.size() == 0) return;
  std::vector<Param> known;
  for (Param q : model.parameters()) {
    if (dataset.known.count(q) && !setup.ties().count(q)) known.push_back(q);
  }
  if (known.empty()) return;
  // Only the known ones free, the rest held at the fit: their columns are
  // those of the whole problem freed, at a fraction of its cost.
  const Parameters p = setup.Decode(x.data(), 0);
  Dataset freed = dataset;
  for (int i = 0; i < setup.size(); ++i) {
    const Param q = setup.free()[i];
    const int c = setup.condition_of(i);
    if (c < 0) {
      freed.known[q] = p[q];
      freed.initial.erase(q);
    } else {
      freed.conditions[c].known[q] = setup.Decode(x.data(), c)[q];
    }
  }
  for (Param q : known) {
    freed.initial[q] = freed.known.at(q);
    freed.known.erase(q);
  }
  Status status;
  ResidualOptions exact = o.residuals;
  exact.derivatives = Derivatives::kAnalytic;
  const auto problem = Problem::Create(model, freed, exact, &status);
  if (!problem) return;
  const ParameterSetup& fs = problem->setup();
  const ModalResiduals& r = problem->residuals();
  const Eigen::MatrixXd& J = u->jacobian;
  // J's rows past the conditions' are priors, 0 in a known one's column.
  const int data_rows = r.row_begin(fs.num_conditions());
  if (r.num_residuals() != data_rows || data_rows > J.rows()) return;
  Eigen::MatrixXd freed_jacobian;
  if (!internal::EvaluateJacobian(r, fs.StartCoordinates(), &freed_jacobian)) return;
  freed_jacobian.conservativeResize(J.rows(), Eigen::NoChange);
  freed_jacobian.bottomRows(J.rows() - data_rows).setZero();
  for (Param q : known) {
    const int k = fs.CoordinateOf(q, 0);
    if (k < 0 || fs.condition_of(k) >= 0) continue;
    // Freed, q is structurally free with those (FindStructuralFreedom): the
    // exact claim, and j lies in J's range but for rounding, where b / s
    // would be noise.
    const bool structural = std::any_of(u->known_dependence.begin(), u->known_dependence.end(),
                                        [&](const KnownDependence& d) { return d.known == q; });
    if (structural) continue;
    const Eigen::VectorXd j = freed_jacobian.col(k);
    if (j.squaredNorm() == 0) continue;
    const Eigen::VectorXd b = u->covariance * (J.transpose() * j);
    const double s = (j - J * b).squaredNorm();
    for (int i = 0; i < setup.size(); ++i) {
      if (u->classes[i] != Identifiability::kYes) continue;
      // Relative to the value: coordinate i's sd with q freed, and how far
      // it moves per relative change of q.
      const double to_relative = setup.is_log(i) ? 1 : 1 / std::max(std::abs(x[i]), 1e-300);
      const double per_q = Info(q).domain == Domain::kPositive ? 1 : TypicalScale(q) / std::abs(p[q]);
      const double var = u->covariance(i, i) + (s > 0 ? b[i] * b[i] / s : INFINITY);
      if (!(std::sqrt(var) * to_relative > o.uncertainty.practical_relative_std)) continue;
      const double share = std::abs(b[i]) * to_relative / per_q;
      if (!(share >= kKnownDependenceShare && share <= 1 / kKnownDependenceShare)) continue;
      KnownDependence d;
      d.coordinate = i;
      d.known = q;
      d.known_value = p[q];
      // Along the direction the data do not see, i moves by -b_i as q by 1.
      d.measured = internal::MeasuredCombination(setup, p, i, q, -b[i], 1, 0.05);
      d.structural = false;
      u->known_dependence.push_back(d);
    }
  }
}

std::vector<SpeedCurve> SpeedCurves(const ModalModel& model, const Dataset& dataset,
                                    const Parameters& p) {
  double top = 0;
  for (const Condition& c : dataset.conditions) top = std::max(top, c.speed_m_s);
  if (!(top > 0)) return {};
  const int points = 41;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::map<ModeLabel, SpeedCurve> curves;
  for (int k = 0; k < points; ++k) {
    const double v = 1.25 * top * k / (points - 1);
    const ModalSolution s = model.Solve(p, v);
    for (const Mode& m : s.modes) curves[m.label].label = m.label;
    for (auto& [label, curve] : curves) {
      const Mode* m = s.ok ? s.Find(label) : nullptr;
      curve.speed_m_s.push_back(v);
      curve.frequency_hz.push_back(m ? m->frequency_hz : nan);
      curve.damping_ratio.push_back(m ? m->damping_ratio : nan);
    }
  }
  std::vector<SpeedCurve> out;
  for (auto& [label, curve] : curves) {
    // A label first seen at speed k gets NaN before it.
    const size_t missing = points - curve.speed_m_s.size();
    for (auto* v : {&curve.frequency_hz, &curve.damping_ratio}) v->insert(v->begin(), missing, nan);
    curve.speed_m_s.clear();
    for (int k = 0; k < points; ++k) curve.speed_m_s.push_back(1.25 * top * k / (points - 1));
    out.push_back(std::move(curve));
  }
  return out;
}

}  // namespace

const char* DecidedByWords(DecidedBy d) {
  switch (d) {
    case DecidedBy::kData: return "the data";
    case DecidedBy::kDataAndPrior: return "data and prior";
    case DecidedBy::kPrior: return "the prior";
  }
  return "";
}

int internal::ShapeScales(const ModalResiduals& residuals) {
  int scales = 0;
  const Dataset& d = residuals.dataset();
  for (const Measurement* unit : Measurements()) {
    for (int i = 0; i < unit->records().Items(d); ++i) scales += unit->Scales(d, i, residuals.options());
  }
  return scales;
}

bool internal::FitsWithinNoise(const ModalResiduals& residuals, double cost) {
  if (!std::isfinite(cost)) return false;
  const FitQuality q = AssessFit(cost, residuals.num_residuals(), residuals.setup().size(),
                                 ShapeScales(residuals));
  return q.p_value && !q.poor;
}

StartAgreement internal::AssessStarts(const ParameterSetup& setup, const std::vector<double>& costs,
                            const std::vector<Eigen::VectorXd>& ends) {
  StartAgreement a;
  const double best = *std::min_element(costs.begin(), costs.end());
  std::vector<int> at_best;
  for (size_t k = 0; k < costs.size(); ++k) {
    a.of += std::isfinite(costs[k]);
    if (2 * (costs[k] - best) <= kSameOptimumChiSquare) at_best.push_back(static_cast<int>(k));
  }
  a.at_best = static_cast<int>(at_best.size());
  std::string names;
  char b[200];
  for (int i = 0; i < setup.size(); ++i) {
    double lo = INFINITY, hi = -INFINITY;
    for (int k : at_best) lo = std::min(lo, ends[k][i]), hi = std::max(hi, ends[k][i]);
    if (!(hi - lo > kStartsDisagree)) continue;
    const double spread = setup.is_log(i) ? std::exp(hi - lo) : hi - lo;
    a.disagree[setup.name(i)] = spread;
    std::snprintf(b, sizeof b, "%s%s (%s%.3g)", names.empty() ? "" : ", ", setup.name(i).c_str(),
                  setup.is_log(i) ? "x" : "by ", spread);
    names += b;
  }
  if (a.of <= 1) {
    a.verdict = a.of == 1 && costs.size() == 1
                    ? "one start only: nothing shows whether it found the best point (--starts)"
                    : "only one start gave a usable fit: nothing shows whether it found the best "
                      "point";
  } else if (a.at_best == 1) {
    std::snprintf(b, sizeof b,
                  "only 1 of %d starts reached the best chi-square (within %g): a lower optimum "
                  "may exist that no start found; more starts (--starts) would tell",
                  a.of, kSameOptimumChiSquare);
    a.verdict = b;
  } else {
    std::snprintf(b, sizeof b, "%d of %d starts reached the best chi-square (within %g)",
                  a.at_best, a.of, kSameOptimumChiSquare);
    a.verdict = b;
    if (names.empty()) {
      a.verdict += " at the same values";
    } else {
      a.verdict += "; at equal chi-square they end at different values of " + names +
                   ": the data do not fix these";
    }
  }
  return a;
}

FitQuality AssessFit(double cost, int residuals, int rank, int shape_scales) {
  FitQuality f;
  f.chi_square = 2 * cost;
  f.degrees_of_freedom = residuals - rank - shape_scales;
  char words[320];
  if (f.degrees_of_freedom <= 0) {
    std::snprintf(words, sizeof words,
                  "no degree of freedom left (%d residuals, %d determined directions): the fit "
                  "matches by construction and cannot say whether the model is right",
                  residuals, rank);
    f.verdict = words;
    return f;
  }
  f.p_value = ChiSquareTail(f.chi_square, f.degrees_of_freedom);
  f.poor = *f.p_value < kPoorFitP;
  std::snprintf(words, sizeof words,
                f.poor ? "poor fit: chi-square %.4g on %d degrees of freedom (p = %.2g). The model "
                         "misses what the data show, so the classes and intervals below are "
                         "optimistic; ringid diagnose says where and which effect"
                       : "the model fits within the noise: chi-square %.4g on %d degrees of "
                         "freedom (p = %.2g)",
                f.chi_square, f.degrees_of_freedom, *f.p_value);
  f.verdict = words;
  return f;
}

std::optional<std::string> ParameterEstimate::Condition() const {
  if (conditional_on.empty()) return std::nullopt;
  std::string text;
  char value[48];
  for (const KnownCondition& c : conditional_on) {
    std::snprintf(value, sizeof value, "%.4g", c.value);
    const std::string unit = Info(c.known).unit;
    text += (text.empty() ? "given " : "; given ") + std::string(ParamName(c.known)) + " = " +
            value + (unit.empty() || unit == "-" ? "" : " " + unit) +
            " (known): the data measure " + (c.structural ? "" : "mainly ") + c.measured;
  }
  return text;
}

bool ParameterEstimate::PriorConflict() const {
  return prior_z && std::abs(*prior_z) > kPriorConflictZ;
}

std::string IdentifyResult::PriorConflicts() const {
  std::string list;
  char item[160];
  for (const ParameterEstimate& e : estimates) {
    if (!e.PriorConflict()) continue;
    std::snprintf(item, sizeof item, "%s%s is %.1f prior sigma %s its prior", list.empty() ? "" : "; ",
                  e.key.Text().c_str(), std::abs(*e.prior_z), *e.prior_z < 0 ? "below" : "above");
    list += item;
  }
  if (list.empty()) return "";
  char head[120];
  std::snprintf(head, sizeof head, "prior and data disagree (beyond %.0f prior sigma): ",
                kPriorConflictZ);
  return head + list +
         ". Either the prior is wrong or the model misses what the data show (ringid diagnose).";
}

std::string IdentifyResult::OnBounds() const {
  std::string list;
  for (const ParameterEstimate& e : estimates) {
    if (!e.on_bound) continue;
    list += (list.empty() ? "" : ", ") + e.key.Text() + " (" + ToString(*e.on_bound) + ")";
  }
  if (list.empty()) return "";
  return "on a bound of its box, so not an interior optimum (its std and class describe the "
         "box, not the data): " + list +
         ". Widen the box with --bounds=NAME:LO:HI, or hold the parameter with --fix=NAME.";
}

namespace {

// Data with fewer observables than free parameters cannot set them all: said
// in one sentence, empty otherwise. A measurement's fitted scales (a shape's)
// are not observed (Measurement::Scales).
std::string FewObservables(const ModalResiduals& residuals) {
  const Dataset& d = residuals.dataset();
  const MeasurementOptions& o = residuals.options();
  int observables = 0, priors = 0;
  std::vector<std::string> counts;
  for (const ModalResiduals::Slot& slot : residuals.slots()) priors += slot.measurement ? 0 : 1;
  for (const Measurement* unit : Measurements()) {
    int n = 0;
    for (int i = 0; i < unit->records().Items(d); ++i) {
      const int rows = unit->Rows(d, i, o);
      n += rows > 0 ? rows - unit->Scales(d, i, o) : 0;
    }
    observables += n;
    if (unit->records().Items(d) > 0) counts.push_back(unit->Count(n));  // a kind the data hold
  }
  const int free = residuals.num_parameters();
  if (observables >= free) return "";
  std::ostringstream o2;
  o2 << d.modes.size() << " measured mode(s)";
  if (!d.statics.empty()) o2 << " and " << d.statics.size() << " static stiffness(es)";
  o2 << " give " << observables << " observable(s) (";
  for (size_t k = 0; k < counts.size(); ++k) o2 << (k ? ", " : "") << counts[k];
  o2 << ") for " << free << " free parameters: they cannot set them all";
  if (priors > 0) o2 << " (" << priors << " prior(s) add what they say)";
  o2 << "; fix what you know (known, --fix) or measure more modes";
  return o2.str();
}

// The multistart: the starts PlanStarts gives, each fitted on its own copy
// of the problem (which counts its evaluations) on o.threads. Each start's
// cost, origin and end point (`ends`) and every evaluation are recorded in
// `s`; returns the best fit, the first of equal costs.
LocalFit FitFromStarts(const ModalModel& model, const Dataset& dataset, const IdentifyOptions& o,
                       const Problem& problem, const Eigen::VectorXd& x0, const Box& box,
                       IdentifyResult* s, std::vector<Eigen::VectorXd>* ends) {
  const ModalResiduals& residuals = problem.residuals();
  const int starts = problem.setup().size() == 0 ? 1 : o.starts;
  auto usable = [&](const Eigen::VectorXd& x) {
    return std::isfinite(CostAt(residuals, x));
  };
  const std::vector<internal::Start> plan =
      PlanStarts(residuals, x0, box, starts, o.start_factor, o.seed, usable);
  // Measured FRFs: a start whose fit does not pass the chi-square test goes
  // through the modal stage, so that the model's peaks lie on the measured
  // ones (estimation/frf_start.h), and is fitted again from there.
  // The modes in the FRFs, extracted once, when a start first needs them.
  std::once_flag extracted;
  std::vector<std::vector<internal::FrfMode>> found;
  const auto modes_in_frfs = [&]() -> const std::vector<std::vector<internal::FrfMode>>& {
    std::call_once(extracted, [&] { found = internal::StageModes(dataset); });
    return found;
  };
  const bool frfs = std::any_of(dataset.conditions.begin(), dataset.conditions.end(),
                                [](const Condition& c) { return c.frf.has_value(); });
  const int n = static_cast<int>(plan.size());
  // On several threads each start has its own copy of the problem, made here
  // one after another; on one, the problem itself, whose kept solutions the
  // starts reuse. Either way each fit counts its own evaluations.
  std::vector<std::unique_ptr<Problem>> copies;
  if (std::min(internal::ThreadsFor(o.threads), n) > 1) {
    for (int k = 0; k < n; ++k) {
      Status created;
      copies.push_back(Problem::Create(model, dataset, o.residuals, &created));
      if (!copies.back()) {  // as the problem itself was made: not expected
        copies.clear();
        break;
      }
    }
  }
  s->evaluations = residuals.evaluations();
  std::vector<LocalFit> fits(n);
  internal::ParallelFor(n, copies.empty() ? 1 : o.threads, [&](int k) {
    const ModalResiduals& mine = copies.empty() ? residuals : copies[k]->residuals();
    const auto inside = [&](const Eigen::VectorXd& x) {
      return Eigen::VectorXd(x.cwiseMax(box.lower).cwiseMin(box.upper));
    };
    // Fits from `from` (at most `iterations`), keeping the lower cost and
    // counting every evaluation; a fit stopped at a lower limit than the
    // options' is a trial, kept only where it converged.
    const auto fit_from = [&](const Eigen::VectorXd& from, int iterations) {
      LocalFit f = FitLocally(mine, o.method, inside(from), box, iterations, o.simplex, -1,
                              o.stop_chi_square);
      const long used = fits[k].evaluations + f.evaluations;
      const bool usable = iterations == o.max_iterations || !f.at_limit;
      if (usable && f.cost < fits[k].cost) fits[k] = std::move(f);
      fits[k].evaluations = used;
    };
    // The dataset's initial values are fitted directly first; FRFs give the
    // other starts, and an initial one whose fit does not pass the
    // chi-square test within kDirectIterations, the modal stage.
    const bool direct = !frfs || plan[k].origin == StartOrigin::kInitial;
    // The trial's limit is Levenberg-Marquardt's; the simplex has its own.
    const int trial = frfs && o.method == Method::kLevenbergMarquardt
                          ? std::min(o.max_iterations, internal::kDirectIterations)
                          : o.max_iterations;
    if (direct) {
      fit_from(plan[k].x, trial);
      if (!frfs || internal::FitsWithinNoise(mine, fits[k].cost)) return;
    }
    Dataset stage;
    const auto& found = modes_in_frfs();
    const auto modal =
        found.empty() ? std::nullopt
                      : internal::FrfModalStart(model, dataset, problem.setup(), found,
                                                plan[k].x, &stage);
    if (!modal) {  // no stage: the start itself, wholly
      if (!direct || trial < o.max_iterations) fit_from(plan[k].x, o.max_iterations);
      return;
    }
    fit_from(*modal, o.max_iterations);
    if (internal::FitsWithinNoise(mine, fits[k].cost)) return;
    const auto frf_cost = [&](const Eigen::VectorXd& x) { return internal::CostAt(mine, inside(x)); };
    if (const auto other =
            internal::OtherLabelOrderStart(model, problem.setup(), stage, plan[k].x, frf_cost)) {
      fit_from(*other, o.max_iterations);
    }
  });
  LocalFit best;
  for (size_t k = 0; k < plan.size(); ++k) {
    s->start_costs.push_back(fits[k].cost);
    s->start_origins.push_back(plan[k].origin);
    s->evaluations += fits[k].evaluations;
    ends->push_back(fits[k].x);
    if (k == 0 || fits[k].cost < best.cost) best = std::move(fits[k]);
  }
  s->starts = static_cast<int>(s->start_costs.size());
  return best;
}

// The chi-square test of the best fit (AssessFit, one scale per measured
// shape), on the Jacobian's rank where the uncertainty has one. Where it is
// poor but not every start agrees that it is the best point, the verdict
// says the start may be to blame, not the model.
FitQuality JudgeFit(const ModalResiduals& residuals, double cost, const Uncertainty& u,
                    const StartAgreement& agreement) {
  const int scales = internal::ShapeScales(residuals);
  FitQuality fit = u.ok ? AssessFit(cost, static_cast<int>(u.jacobian.rows()), u.rank, scales)
                        : AssessFit(cost, residuals.num_residuals(), residuals.setup().size(),
                                    scales);
  if (fit.poor && agreement.at_best < std::max(agreement.of, 2)) {
    char words[400];
    std::snprintf(words, sizeof words,
                  "poor fit: chi-square %.4g on %d degrees of freedom (p = %.2g), reached by %d "
                  "of %d starts. Either the model misses what the data show or no start found "
                  "the best point: try more starts (--starts) before ringid diagnose",
                  fit.chi_square, fit.degrees_of_freedom, *fit.p_value, agreement.at_best,
                  agreement.of);
    fit.verdict = words;
  }
  return fit;
}

// Each measured mode against the model mode paired with it at x, into
// s->modes, and the sums of squared relative frequency errors in and out of
// plane (NaN where a plane has no mode).
void ModeFits(const Dataset& dataset, const ModalResiduals& residuals, const IdentifyOptions& o,
              const Eigen::VectorXd& x, IdentifyResult* s) {
  std::string why;
  std::vector<ModalSolution> solutions;
  std::vector<int> pairs;
  if (residuals.Pair(x.data(), &solutions, &pairs, &why)) {
    for (size_t i = 0; i < dataset.modes.size(); ++i) {
      const MeasuredMode& m = dataset.modes[i];
      const ModalSolution& solution = solutions[m.condition];
      const Mode& mode = solution.modes[pairs[i]];
      ModeFit f;
      if (dataset.NamesConditions()) {
        f.condition = dataset.conditions[m.condition].name;
        f.speed_m_s = dataset.conditions[m.condition].speed_m_s;
      }
      f.label = m.label;
      f.model_label = mode.label;
      f.measured_hz = m.frequency_hz;
      f.measured_sigma_hz = FrequencySigma(m, o.residuals);
      f.model_hz = mode.frequency_hz;
      f.measured_damping = m.damping_ratio;
      f.model_damping = mode.damping_ratio;
      if (!m.shape.empty()) {
        f.mac = Mac(ComparableShape(mode, o.residuals.shape_convention, m.shape), m.shape);
        for (const Mode& other : solution.modes) {
          f.mac_all[other.label] =
              Mac(ComparableShape(other, o.residuals.shape_convention, m.shape), m.shape);
        }
      }
      s->modes.push_back(f);
    }
    for (int c = 0; c < static_cast<int>(dataset.conditions.size()); ++c) {
      const Parameters p = residuals.setup().Decode(x.data(), c);
      const ModelAt at{&residuals.model(), &p, &solutions[c], &pairs};
      for (const Measurement* unit : Measurements()) {
        for (int i = 0; i < unit->records().Items(dataset); ++i) {
          MeasurementFit f;
          if (unit->records().ConditionOf(dataset, i) != c ||
              !unit->Compared(dataset, i, at, &f.measured, &f.sigma, &f.model)) {
            continue;
          }
          f.quantity = unit->quantity();
          f.name = unit->records().ItemName(dataset, i);
          if (dataset.NamesConditions()) f.condition = dataset.conditions[c].name;
          f.unit = unit->unit();
          if (!s->measurements) s->measurements.emplace();
          s->measurements->push_back(f);
        }
      }
    }
    internal::RelativeErrors(dataset, solutions, pairs, &s->relative_error_in_plane,
                             &s->relative_error_out_of_plane);
  } else {
    s->relative_error_in_plane = s->relative_error_out_of_plane =
        std::numeric_limits<double>::quiet_NaN();
  }
}

}  // namespace

bool IdentifyOptions::IsValid(std::string* why) const {
  if (starts < 1 || starts > 100000) {
    *why = "starts must lie in [1, 100000]";
    return false;
  }
  if (!(start_factor >= 1 && start_factor <= 1e3)) {
    *why = "start_factor must lie in [1, 1000]";
    return false;
  }
  if (!(bound_factor > 1 && std::isfinite(bound_factor))) {
    *why = "bound_factor must be finite and greater than 1";
    return false;
  }
  for (const auto& [param, b] : bounds) {
    const Domain domain = Info(param).domain;
    const double least = domain == Domain::kReal ? -INFINITY : 0;
    if (!(std::isfinite(b.lower) && std::isfinite(b.upper) && b.lower < b.upper) ||
        b.lower < least || (domain == Domain::kPositive && b.lower == 0)) {
      *why = std::string("bounds: ") + ParamName(param) +
             " needs finite LO < HI" +
             (domain == Domain::kPositive ? ", LO > 0" : domain == Domain::kNonNegative ? ", LO >= 0" : "");
      return false;
    }
  }
  if (!(stop_chi_square >= 0 && stop_chi_square < 1)) {
    *why = "stop_chi_square must lie in [0, 1)";
    return false;
  }
  if (max_iterations < 1) {
    *why = "max_iterations must be at least 1";
    return false;
  }
  if (threads < 0 || threads > kMaxThreads) {
    *why = "threads must lie in [0, " + std::to_string(kMaxThreads) + "] (0: one per core)";
    return false;
  }
  return simplex.IsValid(why) && residuals.IsValid(why) &&
         uncertainty.IsValid(why);
}

namespace {

// A fresh result that says how it fits; false, with the result saying why,
// when the options are invalid.
bool Begin(const IdentifyOptions& o, IdentifyResult* s) {
  *s = IdentifyResult{};
  s->method = o.method;
  s->frequency_weighting = o.residuals.frequency_weighting;
  std::string why;
  if (o.IsValid(&why)) return true;
  s->status = Status::InvalidInput("invalid options: " + why);
  return false;
}

}  // namespace

void Identify(const ModalModel& model, const Dataset& dataset,
              const IdentifyOptions& o, IdentifyResult* s) {
  if (!Begin(o, s)) return;  // the options first, then the dataset
  const auto problem = Problem::Create(model, dataset, o.residuals, &s->status);
  if (problem) Identify(*problem, o, s);
}

void Identify(const Problem& problem, const IdentifyOptions& options, IdentifyResult* s) {
  const auto t0 = std::chrono::steady_clock::now();
  IdentifyOptions o = options;
  o.residuals = problem.residuals().options();  // the problem's, wherever it is rebuilt
  const ModalModel& model = problem.model();
  const Dataset& dataset = problem.dataset();
  if (!Begin(o, s)) return;
  std::string why;
  const ParameterSetup& setup = problem.setup();
  const ModalResiduals& residuals = problem.residuals();
  const Eigen::VectorXd x0 = setup.StartCoordinates();
  if (!CheckBounds(setup, x0, o.bounds, &why)) {
    s->status = Status::InvalidInput(why);
    return;
  }
  s->warnings = residuals.PairingWarnings(x0.data(), true);
  if (const std::string few = FewObservables(residuals); !few.empty()) s->warnings.push_back(few);
  const Box box = BoundsAround(setup, x0, o.bound_factor, o.bounds);
  std::vector<Eigen::VectorXd> ends;
  const LocalFit best = FitFromStarts(model, dataset, o, problem, x0, box, s, &ends);
  if (!std::isfinite(best.cost)) {
    s->status = Status::Failed("no start produced a usable fit: " + best.message);
    s->seconds = Seconds(t0);
    return;
  }
  s->start_agreement = internal::AssessStarts(setup, s->start_costs, ends);
  s->status = Status::Success(best.message);
  s->converged = best.converged;
  if (!best.converged) {
    s->warnings.push_back(internal::NotConverged(best, o.method, o.max_iterations, o.simplex));
  }
  s->cost = best.cost;
  s->parameters = setup.Decode(best.x.data());
  s->x = best.x;
  if (!o.analysis) {
    s->seconds = Seconds(t0);
    return;
  }
  s->uncertainty = AnalyzeUncertainty(residuals, setup, best.x, o.uncertainty);
  AddPracticalDependence(model, dataset, o, setup, best.x, &s->uncertainty);
  s->fit = JudgeFit(residuals, best.cost, s->uncertainty, s->start_agreement);
  for (int i = 0; i < setup.size(); ++i) s->coordinate_names.push_back(setup.name(i));
  for (Param p : model.parameters()) {
    const bool per_condition = dataset.IsPerCondition(p);
    for (int c = 0; c < (per_condition ? setup.num_conditions() : 1); ++c) {
      ParameterEstimate e = Estimate(setup, residuals, s->uncertainty, box, best.x, p, c);
      if (per_condition) e.key.condition = dataset.conditions[c].name;
      s->estimates.push_back(e);
    }
  }
  std::vector<Param> used = model.parameters();
  s->plausibility = CheckPlausibility(s->parameters, used);
  for (std::string& w : residuals.PairingWarnings(best.x.data(), false)) {
    s->warnings.push_back(std::move(w));
  }

  ModeFits(dataset, residuals, o, best.x, s);
  std::vector<FrfFit> frfs = FrfFits(
      model, dataset, [&](int c) { return setup.Decode(best.x.data(), c); }, residuals.options());
  if (!frfs.empty()) s->frfs = std::move(frfs);
  s->speed_curves = SpeedCurves(model, dataset, s->parameters);
  s->seconds = Seconds(t0);
}

}  // namespace ringid
