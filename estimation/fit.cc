#include "estimation/fit.h"

#include <chrono>
#include <cmath>
#include <cstdio>

#include <Eigen/QR>
#include <ceres/ceres.h>

#include "estimation/interrupt.h"
#include "estimation/uncertainty.h"

namespace ringid {
namespace internal {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Records the cost after each Levenberg-Marquardt iteration; aborts the fit
// on an interrupt (estimation/interrupt.h).
class HistoryCallback : public ceres::IterationCallback {
 public:
  HistoryCallback(const ModalResiduals& residuals, LocalFit* fit)
      : residuals_(residuals), before_(residuals.evaluations()), fit_(fit) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    fit_->history.emplace_back(residuals_.evaluations() - before_, s.cost);
    return InterruptRequested() ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
  }

 private:
  const ModalResiduals& residuals_;
  const long before_;
  LocalFit* fit_;
};

// Stops in statistical units (issue 21), by either of two rules:
// - the full Gauss-Newton step from the current point (the pseudo-inverse of
//   the Jacobian, coordinates on a bound and a profile's fixed one held)
//   promises less than `stop` in chi-square. It is checked, at the price of
//   one Jacobian, only after a successful step that gained less than `stop`
//   itself (and then at most every kCheckEvery iterations);
// - the gains of the last kShrinkingGains successful steps shrink geometrically
//   (each at most kGainShrink times the one before) and their extrapolated tail,
//   gain r/(1-r) with r their slowest ratio but at least kSlowestShrink (so the last
//   gain itself is below `stop`), is below `stop`: the crawl to a kink of the
//   cost (a label or pairing that changes), where Gauss-Newton keeps
//   promising what no step delivers.
// Then no step is seen or expected to move chi-square by a visible fraction
// of one unit, so neither an estimate nor its interval moves visibly.
class StatisticalStop : public ceres::IterationCallback {
 public:
  StatisticalStop(const ModalResiduals& residuals, const Eigen::VectorXd& x, const Box& box,
                  int fixed, double stop)
      : residuals_(residuals), x_(x), box_(box), fixed_(fixed), stop_(stop) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (s.iteration == 0 || !s.step_is_successful) return ceres::SOLVER_CONTINUE;
    gains_.push_back(2 * s.cost_change);
    if (GeometricTail() < stop_) {
      by_tail_ = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    if (!(gains_.back() < stop_) || s.iteration < next_check_) return ceres::SOLVER_CONTINUE;
    next_check_ = s.iteration + kCheckEvery;
    return GaussNewtonGain() < stop_ ? ceres::SOLVER_TERMINATE_SUCCESSFULLY
                                     : ceres::SOLVER_CONTINUE;
  }

  // Whether the gains' tail stopped the fit (else Gauss-Newton's promise).
  bool by_tail() const { return by_tail_; }

 private:
  // What further steps would gain in all if the gains kept shrinking at
  // their slowest recent rate (at least kSlowestShrink); infinite unless they
  // shrink geometrically.
  double GeometricTail() const {
    const int n = static_cast<int>(gains_.size());
    if (n < kShrinkingGains + 1) return kInf;
    double r = kSlowestShrink;
    for (int k = n - kShrinkingGains; k < n; ++k) {
      if (!(gains_[k - 1] > 0 && gains_[k] >= 0 && gains_[k] <= kGainShrink * gains_[k - 1])) {
        return kInf;
      }
      r = std::max(r, gains_[k] / gains_[k - 1]);
    }
    return gains_.back() * r / (1 - r);
  }

  // ||r||^2 - ||r + J dx||^2 for the least-squares step dx.
  double GaussNewtonGain() const {
    Eigen::MatrixXd J;
    Eigen::VectorXd r(residuals_.num_residuals());
    if (!residuals_.Evaluate(x_.data(), r.data()) || !EvaluateJacobian(residuals_, x_, &J)) {
      return INFINITY;
    }
    for (int i = 0; i < J.cols(); ++i) {
      const double margin = 1e-6 * (box_.upper[i] - box_.lower[i]);
      if (i == fixed_ || x_[i] <= box_.lower[i] + margin || x_[i] >= box_.upper[i] - margin) {
        J.col(i).setZero();
      }
    }
    const Eigen::VectorXd dx = J.completeOrthogonalDecomposition().solve(-r);
    return r.squaredNorm() - (r + J * dx).squaredNorm();
  }

  const ModalResiduals& residuals_;
  const Eigen::VectorXd& x_;
  const Box& box_;
  const int fixed_;
  const double stop_;
  // While a crawl keeps promising more, the check is repeated every few
  // iterations, not at each: it costs a Jacobian.
  static constexpr int kCheckEvery = 4;
  int next_check_ = 0;
  bool by_tail_ = false;
  std::vector<double> gains_;  // chi-square gained by each successful step
};

LocalFit FitLevenbergMarquardt(const ModalResiduals& residuals,
                               const Eigen::VectorXd& start, const Box& box,
                               int max_iterations, int fixed, double stop_chi_square) {
  LocalFit fit;
  fit.x = start;
  ceres::Problem problem;
  // One Ceres problem: each condition's block of residuals shares the
  // block of shared coordinates (docs/conventions.md §7).
  for (const auto& [begin, size] : AddResidualBlocks(residuals, &fit.x, &problem)) {
    double* block = fit.x.data() + begin;
    const int at = fixed - begin;
    if (at >= 0 && at < size) {
      if (size == 1) {
        problem.SetParameterBlockConstant(block);
      } else {
        problem.SetManifold(block, new ceres::SubsetManifold(size, {at}));
      }
    }
    for (int i = 0; i < size; ++i) {
      if (i == at) continue;
      problem.SetParameterLowerBound(block, i, box.lower[begin + i]);
      problem.SetParameterUpperBound(block, i, box.upper[begin + i]);
    }
  }
  ceres::Solver::Options so;
  so.minimizer_type = ceres::TRUST_REGION;
  so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  so.linear_solver_type = residuals.num_residuals() >= kNormalEquationsRows
                             ? ceres::DENSE_NORMAL_CHOLESKY
                             : ceres::DENSE_QR;
  so.max_num_iterations = max_iterations;
  so.function_tolerance = kCeresTolerance;
  so.gradient_tolerance = kCeresTolerance;
  so.parameter_tolerance = 1e-12;
  so.logging_type = ceres::SILENT;
  so.minimizer_progress_to_stdout = false;
  so.num_threads = 1;
  // An unsolvable start is refused here rather than inside Ceres.
  if (!(CostAt(residuals, fit.x) < kInf)) {
    std::vector<ModalSolution> solutions;
    std::vector<int> pairs;
    std::string why;
    fit.message = residuals.Pair(fit.x.data(), &solutions, &pairs, &why)
                      ? "the residuals are not finite at this start"
                      : "the model cannot be solved at this start: " + why;
    return fit;
  }
  residuals.ForgetKept();
  HistoryCallback history(residuals, &fit);
  so.callbacks.push_back(&history);
  StatisticalStop stop(residuals, fit.x, box, fixed, stop_chi_square);
  if (stop_chi_square > 0) {
    so.callbacks.push_back(&stop);
    so.update_state_every_iteration = true;  // the callback reads fit.x
  }
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  // The whole cost, rows of conditions without free coordinates included.
  fit.cost = summary.IsSolutionUsable() ? CostAt(residuals, fit.x) : kInf;
  fit.converged = summary.termination_type == ceres::CONVERGENCE ||
                  summary.termination_type == ceres::USER_SUCCESS;
  fit.at_limit = summary.termination_type == ceres::NO_CONVERGENCE;
  if (summary.termination_type == ceres::USER_SUCCESS) {
    char words[200];
    std::snprintf(words, sizeof words,
                  stop.by_tail() ? "chi-square converged: its gains shrink geometrically and "
                                   "promise less than %g in all (statistical stopping rule)"
                                 : "chi-square converged: no step changes it by %g "
                                   "(statistical stopping rule)",
                  stop_chi_square);
    fit.message = words;
  } else {
    fit.message = summary.message;
  }
  return fit;
}

LocalFit FitSimplex(const ModalResiduals& residuals,
                    const Eigen::VectorXd& start, const Box& box,
                    SimplexOptions options, int fixed) {
  Box held = box;
  if (fixed >= 0) held.lower[fixed] = held.upper[fixed] = start[fixed];
  auto f = [&](const Eigen::VectorXd& x) { return CostAt(residuals, x); };
  const SimplexResult s =
      MinimizeNelderMead(f, start, held.lower, held.upper, options);
  LocalFit fit;
  fit.x = s.x;
  fit.cost = s.cost;
  fit.converged = s.converged;
  fit.at_limit = !s.converged && s.evaluations >= options.max_evaluations;
  fit.message = s.message;
  for (const auto& [evaluations, cost] : s.history) fit.history.emplace_back(evaluations, cost);
  return fit;
}

}  // namespace

std::optional<BoundSide> Box::On(int i, double x) const {
  const double tol = 1e-3 * (upper[i] - lower[i]);
  if (x <= lower[i] + tol) return BoundSide::kLower;
  if (x >= upper[i] - tol) return BoundSide::kUpper;
  return std::nullopt;
}

Box BoundsAround(const ParameterSetup& setup, const Eigen::VectorXd& x0,
                 double bound_factor, const Bounds& bounds) {
  const int n = setup.size();
  Box box{Eigen::VectorXd(n), Eigen::VectorXd(n)};
  const double log_bound = std::log(bound_factor);
  for (int i = 0; i < n; ++i) {
    if (const auto b = bounds.find(setup.key(i).param); b != bounds.end()) {
      box.lower[i] = setup.ToCoordinate(i, b->second.lower);
      box.upper[i] = setup.ToCoordinate(i, b->second.upper);
    } else if (setup.is_log(i)) {
      box.lower[i] = x0[i] - log_bound;
      box.upper[i] = x0[i] + log_bound;
    } else {
      const double span = std::max(std::abs(x0[i]), 1.0) * bound_factor;
      box.lower[i] = Info(setup.free()[i]).domain == Domain::kNonNegative
                         ? 0.0
                         : x0[i] - span;
      box.upper[i] = x0[i] + span;
    }
  }
  return box;
}

bool CheckBounds(const ParameterSetup& setup, const Eigen::VectorXd& x0, const Bounds& bounds,
                 std::string* why) {
  const Box box = BoundsAround(setup, x0, 2, bounds);  // the factor is unused for bounded ones
  for (const auto& [param, bound] : bounds) {
    bool free = false;
    for (int i = 0; i < setup.size(); ++i) {
      if (setup.key(i).param != param) continue;
      free = true;
      if (x0[i] < box.lower[i] || x0[i] > box.upper[i]) {
        char text[200];
        std::snprintf(text, sizeof text, "bounds: the initial value of %s (%.6g) lies outside %.6g..%.6g",
                      setup.name(i).c_str(), setup.ToPhysical(i, x0[i]), bound.lower, bound.upper);
        *why = text;
        return false;
      }
    }
    if (!free) {
      *why = std::string("bounds: ") + ParamName(param) + " is not free in this dataset";
      return false;
    }
  }
  return true;
}

double CostAt(const ModalResiduals& residuals, const Eigen::VectorXd& x) {
  std::vector<double> r(residuals.num_residuals());
  if (!residuals.Evaluate(x.data(), r.data())) return kInf;
  double c = 0;
  for (double v : r) c += v * v;
  return 0.5 * c;
}

LocalFit FitLocally(const ModalResiduals& residuals, Method method,
                    const Eigen::VectorXd& start, const Box& box,
                    int max_iterations, const SimplexOptions& simplex,
                    int fixed, double stop_chi_square) {
  const auto t0 = std::chrono::steady_clock::now();
  const long before = residuals.evaluations();
  LocalFit fit;
  if (start.size() == 0 || (fixed >= 0 && start.size() == 1 &&
                            method == Method::kSimplex)) {
    fit.x = start;
    fit.cost = CostAt(residuals, start);
    fit.converged = true;
    fit.message = fit.cost < kInf
                      ? "nothing free"
                      : "the model cannot be solved at the given parameters";
  } else if (method == Method::kSimplex) {
    fit = FitSimplex(residuals, start, box, simplex, fixed);
  } else {
    fit = FitLevenbergMarquardt(residuals, start, box, max_iterations, fixed, stop_chi_square);
  }
  fit.evaluations = residuals.evaluations() - before;
  if (fit.history.size() > 200) {  // keep the first, the last and 198 between
    std::vector<std::pair<long, double>> thin;
    const size_t n = fit.history.size();
    for (int k = 0; k < 200; ++k) thin.push_back(fit.history[k * (n - 1) / 199]);
    fit.history = thin;
  }
  fit.seconds = std::chrono::duration<double>(
                    std::chrono::steady_clock::now() - t0).count();
  return fit;
}

std::string NotConverged(const LocalFit& fit, Method method, int max_iterations,
                         const SimplexOptions& simplex) {
  if (fit.at_limit && method == Method::kLevenbergMarquardt) {
    return "not converged: the best start used all its " + std::to_string(max_iterations) +
           " Levenberg-Marquardt iterations (--max_iterations) before the stopping rule held; "
           "run again with --max_iterations=" + std::to_string(4 * max_iterations) +
           " (the estimates and their std may still move), or from initial values nearer the fit";
  }
  if (fit.at_limit) {
    return "not converged: the Downhill Simplex used all its " +
           std::to_string(simplex.max_evaluations) +
           " evaluations; try --method=lm (Levenberg-Marquardt), or hold what you know (--fix)";
  }
  return "not converged: the best start stopped on '" + fit.message +
         "'; try more starts (--starts) or exact Jacobians (--derivatives=analytic)";
}

}  // namespace internal
}  // namespace ringid
