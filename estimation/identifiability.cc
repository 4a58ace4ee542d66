#include "estimation/identifiability_internal.h"
#include "estimation/identifiability.h"

#include "estimation/fit.h"
#include "estimation/parallel.h"
#include "estimation/problem.h"
#include "estimation/uncertainty.h"
#include "estimation/statistics.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <Eigen/SVD>

namespace ringid {

using internal::ModalResiduals;
using internal::ParameterSetup;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// "log K_cx" for a log coordinate, the name otherwise.
std::string CoordinateText(const ParameterSetup& setup, int i) {
  return (setup.is_log(i) ? "log " : "") + setup.name(i);
}

// A direction in coordinates as text: terms above 10 % of the largest,
// coefficients scaled so the largest is 1.
Combination Describe(const ParameterSetup& setup, const Eigen::VectorXd& d,
                     double singular_value) {
  Combination c;
  c.singular_value = singular_value;
  const double big = d.cwiseAbs().maxCoeff();
  std::vector<int> order;
  for (int i = 0; i < d.size(); ++i) {
    if (std::abs(d[i]) >= 0.1 * big) order.push_back(i);
  }
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return std::abs(d[a]) > std::abs(d[b]); });
  // Sign convention: the largest term positive.
  const double sign = d[order.front()] < 0 ? -1 : 1;
  std::ostringstream text;
  for (size_t k = 0; k < order.size(); ++k) {
    const double coef = sign * d[order[k]] / big;
    c.terms.emplace_back(setup.name(order[k]), coef);
    const double mag = std::abs(coef);
    if (k > 0) text << (coef < 0 ? " - " : " + ");
    else if (coef < 0) text << "-";
    if (std::abs(mag - 1) > 0.005) {
      char num[32];
      std::snprintf(num, sizeof num, "%.2f ", mag);
      text << num;
    }
    text << CoordinateText(setup, order[k]);
  }
  c.text = text.str();
  return c;
}

// Fisher information with a weak prior (sd 10 in coordinates) so that its
// inverse exists; the prior only sets the floor of the information gain.
Eigen::MatrixXd Information(const Eigen::MatrixXd& J) {
  Eigen::MatrixXd F = J.transpose() * J;
  F.diagonal().array() += 1e-2;
  return F;
}

Eigen::VectorXd Variances(const Eigen::MatrixXd& F) {
  return F.ldlt().solve(Eigen::MatrixXd::Identity(F.rows(), F.cols())).diagonal();
}

}  // namespace

bool IdentifiabilityOptions::IsValid(std::string* why) const {
  if (profile_steps < 0 || profile_steps > 1000) *why = "profile_steps must lie in [0, 1000]";
  else if (!(profile_first_step > 0) || !(profile_growth >= 1)) *why = "profile steps must grow from a positive first step";
  else if (!(collinearity_threshold > 1)) *why = "collinearity_threshold must exceed 1";
  else if (!(near_null > 0 && near_null < 1)) *why = "near_null must lie in (0, 1)";
  else if (!(same_direction > 0 && same_direction < 1)) *why = "same_direction must lie in (0, 1)";
  else if (!(advice_damping_sigma > 0 && advice_shape_sigma > 0 && advice_known_relative_sigma > 0)) *why = "advice sigmas must be positive";
  else if (!(advice_load_factor > 0) || !std::isfinite(advice_load_factor)) *why = "advice_load_factor must be positive";
  else if (std::any_of(advice_speeds_m_s.begin(), advice_speeds_m_s.end(),
                       [](double v) { return !(v > 0) || !std::isfinite(v); })) *why = "advice speeds must be positive";
  else return fit.IsValid(why);
  return false;
}

namespace {

std::string RankExplanation(const Uncertainty& u, int n) {
  const long rows = u.jacobian.rows();
  std::ostringstream e;
  e << "rank " << u.rank << " of " << n << " free coordinates from " << rows
    << " weighted residuals";
  if (u.rank < n) {
    e << ": " << n - u.rank << " direction(s) change no residual";
    if (rows < n) {
      e << " (" << rows << " observations cannot determine " << n << " unknowns; at least "
        << n - rows << " are left free)";
    }
  }
  return e.str();
}

// Whether the profiles run (o.profiles), and why or why not.
ProfilesRun ProfilesFor(const Problem& problem, const IdentifiabilityOptions& o) {
  const auto& conditions = problem.dataset().conditions;
  const bool frfs = std::any_of(conditions.begin(), conditions.end(),
                                [](const Condition& c) { return c.frf.has_value(); });
  if (o.profile_steps == 0) return {false, "profile_steps is 0"};
  switch (o.profiles) {
    case Profiles::kNever: return {false, "--profiles=never"};
    case Profiles::kAlways: return {true, "--profiles=always"};
    case Profiles::kAuto: break;
  }
  if (frfs) {
    return {false, "the data measure FRFs, where each profile is a series of FRF fits: "
                   "--profiles=always computes them"};
  }
  return {true, "the data measure no FRFs, where refits are cheap"};
}

// Per coordinate: class, std, Wald and, where `run`, profile intervals, the
// coordinates' profiles on o.fit.threads, each thread on its own copy of the
// problem. o.on_step: the fit, then each coordinate's profile as it ends,
// then the rest.
std::vector<ParameterIdentifiability> Classify(const Problem& problem, const Eigen::VectorXd& xhat,
                                               double cost, const Uncertainty& u,
                                               const IdentifiabilityOptions& o, bool run) {
  const ParameterSetup& setup = problem.setup();
  const int n = setup.size();
  std::vector<ParameterIdentifiability> out(n);
  for (int i = 0; i < n; ++i) {
    ParameterIdentifiability& p = out[i];
    p.key = setup.key(i);
    p.value = setup.ToPhysical(i, xhat[i]);
    p.identifiable = u.classes[i];
    p.reason = u.reasons[i];
    if (std::isfinite(u.std[i])) {
      const double s = u.std[i];
      p.std = setup.PhysicalStd(i, xhat[i], s);
      p.wald_95 = setup.Interval95(i, xhat[i], s);
    }
  }
  // Thread 0 on the problem itself, each other on a copy made here (as the
  // problem was made: not expected to fail; where one does, fewer threads).
  std::vector<std::unique_ptr<Problem>> copies(1);
  for (int t = 1; run && t < std::min(internal::ThreadsFor(o.fit.threads), n); ++t) {
    Status created;
    auto copy = Problem::Create(problem.model(), problem.dataset(), problem.residuals().options(),
                                &created);
    if (!copy) break;
    copies.push_back(std::move(copy));
  }
  const int threads = static_cast<int>(copies.size());
  std::mutex mutex;
  int done = 0;
  std::atomic<int> next{0};
  internal::ParallelFor(threads, threads, [&](int t) {
    for (int i; (i = next++) < n;) {
      try {
        if (run) {
          const Problem& mine = t > 0 ? *copies[t] : problem;
          out[i].profile_95 = internal::ProfileCoordinate(mine, xhat, cost, i, u.std[i], o);
        }
      } catch (...) {
        next = n;  // the other threads take no new coordinate
        throw;
      }
      const std::lock_guard<std::mutex> lock(mutex);
      if (o.on_step) o.on_step(1 + ++done, n + 2);
    }
  });
  return out;
}

// The sine of the angle between the unit direction of d and the span of the
// orthonormal columns of `span` (1 for an empty span).
double OutsideSpan(const Eigen::MatrixXd& span, const Eigen::VectorXd& d) {
  const Eigen::VectorXd u = d.normalized();
  return span.cols() ? (u - span * (span.transpose() * u)).norm() : 1.0;
}

// The combinations as listed, each once: the structural ones, then collinear
// pairs, then the data's free and near-free directions. Two directions are
// one combination when they differ by a structurally free direction (no data
// can tell them apart) and a multiple: the sine of the angle between their
// parts outside the structural span is below `same_direction`.
class CombinationList {
 public:
  CombinationList(const Eigen::MatrixXd& structural, double same_direction)
      : structural_(structural), same_(same_direction) {}

  // Whether d lies in the span of the structurally free directions.
  bool Structural(const Eigen::VectorXd& d) const {
    return structural_.cols() > 0 && OutsideSpan(structural_, d) < same_;
  }
  // The combination listed as d, or null.
  Combination* Along(const Eigen::VectorXd& d) {
    if (Structural(d)) return nullptr;
    const Eigen::VectorXd p = Seen(d);
    for (size_t k = 0; k < seen_.size(); ++k) {
      if (seen_[k].size() && OutsideSpan(seen_[k], p) < same_) return &combinations_[k];
    }
    return nullptr;
  }
  void Add(const Eigen::VectorXd& d, Combination c) {
    seen_.push_back(Structural(d) ? Eigen::VectorXd() : Eigen::VectorXd(Seen(d).normalized()));
    combinations_.push_back(std::move(c));
  }
  std::vector<Combination> Release() { return std::move(combinations_); }

 private:
  // The part of d outside the structural span, the part data can see.
  Eigen::VectorXd Seen(const Eigen::VectorXd& d) const {
    return structural_.cols() ? Eigen::VectorXd(d - structural_ * (structural_.transpose() * d)) : d;
  }

  const Eigen::MatrixXd& structural_;
  const double same_;
  std::vector<Eigen::VectorXd> seen_;  // unit; empty for a structural entry
  std::vector<Combination> combinations_;
};

// The directions the model cannot see (estimation/structure.h), each with its
// invariance.
void StructuralDirections(const Uncertainty& u, const ParameterSetup& setup, CombinationList* list) {
  for (size_t k = 0; k < u.structural_readable.size(); ++k) {
    Combination c = Describe(setup, u.structural_readable[k], 0.0);
    c.meaning = "structurally free: " + u.structural_invariances[k] + ", whatever the data";
    list->Add(u.structural_readable[k], c);
  }
}

// Collinear pairs (Brun et al. 2001: index 1/sqrt(lambda_min) of the
// normalised columns), named as the combination they leave free. A pair
// whose combination is structural is listed as that already, not again.
void CollinearPairs(const Eigen::MatrixXd& J, const ParameterSetup& setup,
                    const IdentifiabilityOptions& o, CombinationList* list,
                    IdentifiabilityResult* r) {
  const int n = setup.size();
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const double ni = J.col(i).norm(), nj = J.col(j).norm();
      if (!(ni > 0) || !(nj > 0)) continue;
      const double cos = J.col(i).dot(J.col(j)) / (ni * nj);
      const double lambda_min = 1 - std::abs(cos);
      const double index = lambda_min > 1e-16 ? 1 / std::sqrt(lambda_min) : kInf;
      if (!(index > o.collinearity_threshold)) continue;
      Eigen::VectorXd d = Eigen::VectorXd::Zero(n);
      d[i] = 1 / ni;
      d[j] = -(cos > 0 ? 1 : -1) / nj;
      if (list->Structural(d)) continue;
      r->collinear_pairs.push_back({{setup.name(i), setup.name(j)}, index});
      Combination c = Describe(setup, d, (J * d).norm() / d.norm());
      const std::string a = setup.name(i), b = setup.name(j);
      const bool unit = c.terms.size() == 2 && std::abs(std::abs(c.terms[1].second) - 1) < 0.01;
      if (setup.is_log(i) && setup.is_log(j) && unit) {
        c.meaning = c.terms[1].second > 0
                        ? "moving both together changes nothing: only " + a + " / " + b + " is determined"
                        : "moving them oppositely changes nothing: only " + a + " * " + b + " is determined";
      } else {
        c.meaning = "only one combination of " + a + " and " + b + " is determined";
      }
      if (Combination* listed = list->Along(d)) {
        listed->meaning += "; so is " + c.text + ", the same up to a structurally free direction";
      } else {
        list->Add(d, c);
      }
    }
  }
}

// Null and near-null directions of the data Jacobian (structural directions
// projected out), outside the structural span: the structural directions
// enter the SVD as rows weighted like the largest singular value, which
// moves them to the top and leaves every other singular value and vector as
// it was (J S = 0). One along a listed collinear pair adds its singular value
// and meaning to that entry instead of a second one.
void FreeDirections(const Uncertainty& u, const ParameterSetup& setup,
                    const IdentifiabilityOptions& o, CombinationList* list) {
  const Eigen::MatrixXd& J = u.jacobian;
  const Eigen::MatrixXd& S = u.structural_directions;
  const int n = setup.size(), structural = static_cast<int>(S.cols());
  const double smax = u.singular_values.size() ? u.singular_values[0] : 0;
  Eigen::MatrixXd A(J.rows() + structural, n);
  A << J, (smax > 0 ? smax : 1.0) * S.transpose();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
  const int free = std::max(0, n - u.rank - structural);
  for (int k = 0; k < n; ++k) {
    const double s = k < svd.singularValues().size() ? svd.singularValues()[k] : 0.0;
    const bool null = k >= n - free;
    if (!null && !(s < o.near_null * smax)) continue;
    const Eigen::VectorXd d = svd.matrixV().col(k);
    if (list->Structural(d)) continue;  // not expected: a guard
    const std::string meaning =
        null ? "free: the data do not change along it"
             : "nearly free: singular value " + std::to_string(s / smax) + " of the largest";
    if (Combination* listed = list->Along(d)) {
      listed->meaning += "; " + meaning;
      listed->singular_value = null ? 0.0 : s;
      continue;
    }
    Combination c = Describe(setup, d, null ? 0.0 : s);
    c.meaning = meaning;
    list->Add(d, c);
  }
}

// Correlations of the determined coordinates; empty without a covariance.
Eigen::MatrixXd Correlation(const Uncertainty& u) {
  if (!u.covariance_ok) return {};
  const int n = static_cast<int>(u.classes.size());
  Eigen::MatrixXd c = Eigen::MatrixXd::Constant(n, n, std::numeric_limits<double>::quiet_NaN());
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      if (u.classes[i] == Identifiability::kNo || u.classes[j] == Identifiability::kNo) continue;
      c(i, j) = u.covariance(i, j) / std::sqrt(u.covariance(i, i) * u.covariance(j, j));
    }
  }
  return c;
}

// Largest identifiable subset: rank-revealing QR with column pivoting on the
// column-normalised Jacobian, over the coordinates with no component in a
// free direction, structural or of the data's null space (those not classed
// no: one decision, in AnalyzeUncertainty). A coordinate with such a
// component is not determined while the others are free, whatever the
// pivoting would make of its column (a structural pair's projected column,
// or noise normalised to length 1).
std::vector<std::string> IdentifiableSubset(const Uncertainty& u, const ParameterSetup& setup,
                                            double rank_tolerance) {
  std::vector<int> candidates;
  for (int i = 0; i < setup.size(); ++i) {
    if (u.classes[i] != Identifiability::kNo) candidates.push_back(i);
  }
  std::vector<std::string> subset;
  if (candidates.empty()) return subset;
  Eigen::MatrixXd Jn(u.jacobian.rows(), candidates.size());
  for (size_t k = 0; k < candidates.size(); ++k) {
    Jn.col(k) = u.jacobian.col(candidates[k]);
    if (Jn.col(k).norm() > 0) Jn.col(k) /= Jn.col(k).norm();
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Jn);
  qr.setThreshold(rank_tolerance);
  for (int k = 0; k < qr.rank(); ++k) {
    subset.push_back(setup.name(candidates[qr.colsPermutation().indices()[k]]));
  }
  return subset;
}

// An observation the test could add: rows of the augmented Jacobian, or (a
// known value) rows of its own.
struct Candidate {
  std::string text;
  std::vector<int> rows;
  Eigen::MatrixXd extra;
};

// The standard errors advice assumes of what the test could add.
AdviceSigmas SigmasOf(const IdentifiabilityOptions& o) {
  AdviceSigmas sigmas;
  sigmas.damping = o.advice_damping_sigma;
  sigmas.shape = o.advice_shape_sigma;
  return sigmas;
}

// The dataset with every observation the model predicts at xhat where the
// test did not measure (or the fit did not use) it: damping ratios and
// shapes of the fitted modes, static stiffnesses of a standing condition.
Dataset WithEveryObservation(const Problem& problem, const Eigen::VectorXd& xhat,
                             const std::vector<ModalSolution>& solutions,
                             const std::vector<int>& pairs, const IdentifiabilityOptions& o) {
  Dataset more = problem.dataset();
  for (int c = 0; c < static_cast<int>(more.conditions.size()); ++c) {
    const Parameters p = problem.setup().Decode(xhat.data(), c);
    const ModelAt at{&problem.model(), &p, &solutions[c], &pairs};
    for (const Measurement* unit : Measurements()) {
      unit->AddUnmeasured(at, c, o.fit.residuals, SigmasOf(o), &more);
    }
  }
  return more;
}

// The candidates: each observation the augmented problem adds (its rows),
// and a known value of each free parameter.
std::vector<Candidate> Candidates(const Dataset& dataset, const Problem& augmented,
                                  const Eigen::VectorXd& xhat, const IdentifiabilityOptions& o) {
  std::vector<Candidate> candidates;
  const auto& slots = augmented.residuals().slots();
  const Dataset& more = augmented.dataset();
  const ParameterSetup& setup = augmented.setup();
  for (const MeasurementRecords* records : Records()) {
    for (int i = 0; i < records->Items(more); ++i) {
      for (const Measurement* unit : Measurements()) {
        if (&unit->records() != records) continue;
        if (i < records->Items(dataset) && unit->Rows(dataset, i, o.fit.residuals) > 0) {
          continue;  // measured and used
        }
        Candidate added{unit->Addition(more, i), {}, {}};
        for (size_t k = 0; k < slots.size(); ++k) {
          if (slots[k].measurement == unit && slots[k].item == i) added.rows.push_back(k);
        }
        if (!added.rows.empty()) candidates.push_back(added);
      }
    }
  }
  const int n = setup.size();
  for (int i = 0; i < n; ++i) {
    Candidate known{std::string("a known value of ") + setup.name(i) + " (to " +
                        std::to_string(static_cast<int>(100 * o.advice_known_relative_sigma)) + " %)",
                    {}, Eigen::MatrixXd::Zero(1, n)};
    const double sigma = setup.is_log(i) ? o.advice_known_relative_sigma
                                         : o.advice_known_relative_sigma * std::max(std::abs(xhat[i]), 1e-12);
    known.extra(0, i) = 1 / sigma;
    candidates.push_back(known);
  }
  return candidates;
}

// A new condition as a candidate: the dataset's first condition measured
// again at `speed` (and at F_cz0 times `load_factor`), its modes the model's
// at xhat with the observables and sigmas of the measured ones. None where
// it would add coordinates (per-condition parameters) or cannot be solved.
std::optional<Candidate> ConditionCandidate(const Problem& problem, const Eigen::VectorXd& xhat,
                                            double speed, double load_factor,
                                            const IdentifiabilityOptions& o) {
  const Dataset& d = problem.dataset();
  if (!d.per_condition.empty()) return std::nullopt;
  for (const Condition& c : d.conditions) {
    if (c.speed_m_s == speed && load_factor == 1) return std::nullopt;  // measured already
  }
  Dataset more = d;
  more.format = std::max(more.format, 2);
  Condition added;
  char name[64];
  std::snprintf(name, sizeof name, "candidate_%g", speed);
  added.name = name;
  added.speed_m_s = speed;
  Parameters p = problem.setup().Decode(xhat.data(), 0);
  std::string text;
  if (load_factor != 1) {
    const auto load = d.known.find(Param::F_cz0);
    if (load == d.known.end()) return std::nullopt;
    more.per_condition = {Param::F_cz0};
    more.known.erase(Param::F_cz0);
    for (Condition& c : more.conditions) c.known[Param::F_cz0] = load->second;
    added.known[Param::F_cz0] = p[Param::F_cz0] = load->second * load_factor;
    std::snprintf(name, sizeof name, "a second load, F_cz0 x %g (standing)", load_factor);
  } else {
    std::snprintf(name, sizeof name, "a drum test at %g m/s", speed);
  }
  text = name;
  const ModalSolution s = problem.model().Solve(p, speed);
  if (!s.ok) return std::nullopt;
  const int index = static_cast<int>(more.conditions.size());
  more.conditions.push_back(added);
  const ModelAt at{&problem.model(), &p, &s, nullptr};  // modes by label
  for (const MeasurementRecords* records : Records()) records->Repeat(at, 0, index, speed, &more);
  for (const Measurement* unit : Measurements()) {
    for (int i = 0; i < unit->records().Items(more); ++i) {
      if (unit->records().ConditionOf(more, i) == index) unit->Measure(at, i, o.fit.residuals, &more);
    }
  }
  Status status;
  const auto augmented = Problem::Create(problem.model(), more, o.fit.residuals, &status);
  Eigen::MatrixXd J;
  if (!augmented || augmented->setup().size() != xhat.size() ||
      !EvaluateJacobian(augmented->residuals(), xhat, &J)) {
    return std::nullopt;
  }
  const int first = augmented->residuals().row_begin(index);
  const int rows = augmented->residuals().row_begin(index + 1) - first;
  if (rows == 0) return std::nullopt;
  return Candidate{text, {}, J.middleRows(first, rows)};
}

// Experiment design: for each parameter not identifiable, the candidate
// observations ranked by the information they add on it.
std::vector<Advice> ExperimentAdvice(const Problem& problem, const Eigen::VectorXd& xhat,
                                     const Uncertainty& u, const IdentifiabilityOptions& o) {
  std::vector<ModalSolution> solutions;
  std::vector<int> pairs;
  std::string why;
  if (!problem.residuals().Pair(xhat.data(), &solutions, &pairs, &why)) return {};
  ResidualOptions all = o.fit.residuals;
  all.use_damping = all.use_shapes = true;
  Status status;
  const auto augmented = Problem::Create(
      problem.model(), WithEveryObservation(problem, xhat, solutions, pairs, o), all, &status);
  Eigen::MatrixXd Ja;
  if (!augmented || !EvaluateJacobian(augmented->residuals(), xhat, &Ja)) return {};
  std::vector<Candidate> candidates = Candidates(problem.dataset(), *augmented, xhat, o);
  for (double speed : o.advice_speeds_m_s) {
    if (auto c = ConditionCandidate(problem, xhat, speed, 1, o)) candidates.push_back(*c);
  }
  if (auto c = ConditionCandidate(problem, xhat, 0, o.advice_load_factor, o)) candidates.push_back(*c);
  const ParameterSetup& setup = problem.setup();
  const int n = setup.size();
  const Eigen::MatrixXd F0 = Information(u.jacobian);
  const Eigen::VectorXd var0 = Variances(F0);
  std::vector<Eigen::VectorXd> var_after;
  for (const Candidate& c : candidates) {
    Eigen::MatrixXd G = c.extra.rows() ? c.extra : Eigen::MatrixXd(c.rows.size(), n);
    for (size_t k = 0; k < c.rows.size(); ++k) G.row(k) = Ja.row(c.rows[k]);
    var_after.push_back(Variances(F0 + G.transpose() * G));
  }
  std::vector<Advice> advice;
  for (int i = 0; i < n; ++i) {
    if (u.classes[i] == Identifiability::kYes) continue;
    std::vector<Advice> mine;
    for (size_t c = 0; c < candidates.size(); ++c) {
      Advice a;
      a.parameter = setup.name(i);
      a.observation = candidates[c].text;
      a.information_gain = 0.5 * std::log(var0[i] / var_after[c][i]);
      const double sd = std::sqrt(var_after[c][i]);
      const double relative = setup.is_log(i) ? sd : sd / std::max(std::abs(xhat[i]), 1e-300);
      a.relative_std_after = relative;
      a.makes_identifiable = relative <= o.fit.uncertainty.practical_relative_std;
      if (a.information_gain > 0.01) mine.push_back(a);
    }
    std::sort(mine.begin(), mine.end(), [](const Advice& a, const Advice& b) {
      return a.information_gain > b.information_gain;
    });
    if (static_cast<int>(mine.size()) > o.advice_per_parameter) mine.resize(o.advice_per_parameter);
    advice.insert(advice.end(), mine.begin(), mine.end());
  }
  return advice;
}

}  // namespace

void AnalyzeIdentifiability(const ModalModel& model, const Dataset& dataset,
                            const IdentifiabilityOptions& o, IdentifiabilityResult* r) {
  const auto t0 = std::chrono::steady_clock::now();
  *r = IdentifiabilityResult{};
  std::string why;
  if (!o.IsValid(&why)) {
    r->status = r->fit.status = Status::InvalidInput("invalid options: " + why);
    return;
  }
  const auto problem = Problem::Create(model, dataset, o.fit.residuals, &r->status);
  if (!problem) {
    r->fit.status = r->status;
    return;
  }
  IdentifyResult fit;
  if (o.on_step) o.on_step(0, problem->setup().size() + 2);
  Identify(*problem, o.fit, &fit);
  AnalyzeIdentifiability(*problem, fit, o, r);
  r->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void AnalyzeIdentifiability(const Problem& problem, const IdentifyResult& fit,
                            const IdentifiabilityOptions& options, IdentifiabilityResult* r) {
  const auto t0 = std::chrono::steady_clock::now();
  IdentifiabilityOptions o = options;
  o.fit.residuals = problem.residuals().options();  // the problem's, wherever it is rebuilt
  *r = IdentifiabilityResult{};
  r->fit = fit;
  std::string why;
  if (!o.IsValid(&why)) {
    r->status = Status::InvalidInput("invalid options: " + why);
    return;
  }
  if (!r->fit.status.ok()) {
    r->status = {r->fit.status.outcome, "identification failed: " + r->fit.status.message};
    return;
  }
  if (r->fit.x.size() != problem.setup().size()) {
    r->status = Status::InvalidInput("the fit is not one of this problem (its coordinates differ)");
    return;
  }
  const Uncertainty& u = r->fit.uncertainty;
  if (!u.ok) {
    r->status = Status::Failed("no Jacobian at the fitted point: " + u.error);
    return;
  }
  const ParameterSetup& setup = problem.setup();
  const Eigen::VectorXd& xhat = r->fit.x;
  const Eigen::MatrixXd& J = u.jacobian;
  r->rank = u.rank;
  r->num_residuals = static_cast<int>(J.rows());
  r->condition_number = u.condition_number;
  r->singular_values = u.singular_values;
  r->coordinate_names = r->fit.coordinate_names;
  r->rank_explanation = RankExplanation(u, setup.size());
  r->profiles = ProfilesFor(problem, o);
  if (o.on_step) o.on_step(1, setup.size() + 2);
  r->parameters = Classify(problem, xhat, r->fit.cost, u, o, r->profiles.computed);
  CombinationList combinations(u.structural_directions, o.same_direction);
  StructuralDirections(u, setup, &combinations);
  CollinearPairs(J, setup, o, &combinations, r);
  FreeDirections(u, setup, o, &combinations);
  r->combinations = combinations.Release();
  r->correlation = Correlation(u);
  r->identifiable_subset = IdentifiableSubset(u, setup, o.fit.uncertainty.rank_tolerance);
  if (o.on_step) o.on_step(setup.size() + 1, setup.size() + 2);
  r->advice = ExperimentAdvice(problem, xhat, u, o);
  if (o.on_step) o.on_step(setup.size() + 2, setup.size() + 2);
  r->status = Status::Success();
  r->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string IdentifiabilityResult::FullReport() const {
  std::ostringstream o;
  char line[512];
  o << "ringid identifiability: " << (status.ok() ? "" : "FAILED: " + status.message) << "\n";
  if (!status.ok()) return o.str();
  o << "  fit: " << fit.BriefReport() << "\n";
  o << "  " << rank_explanation << "\n";
  std::snprintf(line, sizeof line, "  condition number %.3e; singular values:", condition_number);
  o << line;
  for (int i = 0; i < singular_values.size(); ++i) {
    std::snprintf(line, sizeof line, " %.3g", singular_values[i]);
    o << line;
  }
  std::snprintf(line, sizeof line, "\n\n  %-12s %12s %-9s  %-15s %-12s %-24s %s\n", "parameter",
                "value", "unit", "class", "std", "Wald 95 %", "profile 95 %");
  o << line;
  for (const ParameterIdentifiability& p : parameters) {
    // A side that did not close: where it jumped or its refits failed, else "open".
    auto opt = [](const std::optional<double>& v, const std::optional<double>& jump_at,
                  const std::optional<double>& failed_at) {
      char b[64] = "open";
      if (v) std::snprintf(b, sizeof b, "%.4g", *v);
      else if (jump_at) std::snprintf(b, sizeof b, "jumps to another optimum at %.4g", *jump_at);
      else if (failed_at) std::snprintf(b, sizeof b, "failed at %.4g", *failed_at);
      return std::string(b);
    };
    char wald[64] = "-", sd[32] = "-";
    if (p.wald_95) std::snprintf(wald, sizeof wald, "[%.4g, %.4g]", p.wald_95->first, p.wald_95->second);
    if (p.std) std::snprintf(sd, sizeof sd, "%.3e", *p.std);
    const std::string prof = p.profile_95.computed
                                 ? "[" + opt(p.profile_95.lower, p.profile_95.lower_jump_at,
                                             p.profile_95.lower_failed_at) +
                                       ", " +
                                       opt(p.profile_95.upper, p.profile_95.upper_jump_at,
                                           p.profile_95.upper_failed_at) +
                                       "]"
                                 : "-";
    std::snprintf(line, sizeof line, "  %-12s %12.4e %-9s  %-15s %-12s %-24s %s\n",
                  p.key.Text().c_str(), p.value, Info(p.key.param).unit, ToString(p.identifiable),
                  sd, wald, prof.c_str());
    o << line;
  }
  if (!profiles.computed) o << "  profile intervals not computed: " << profiles.why << "\n";
  o << "\n  combinations the data leave free:\n";
  for (const Combination& c : combinations) {
    o << "    " << c.text << "  (" << c.meaning << ")\n";
  }
  o << "\n  largest identifiable subset (pivoted QR over the parameters with no component in a free "
       "direction):";
  for (const std::string& s : identifiable_subset) o << " " << s;
  if (identifiable_subset.empty()) o << " none";
  o << "\n";
  if (!advice.empty()) {
    o << "\n  what would help (information gain on the parameter, nats; the relative std it "
         "would leave):\n";
    for (const Advice& a : advice) {
      std::snprintf(line, sizeof line, "    %-10s %-55s %6.2f  to %.3g %%%s\n", a.parameter.c_str(),
                    a.observation.c_str(), a.information_gain, 100 * a.relative_std_after,
                    a.makes_identifiable ? "  -> identifiable" : "");
      o << line;
    }
  }
  return o.str();
}

}  // namespace ringid
