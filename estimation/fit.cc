#include "estimation/fit.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include <ceres/ceres.h>

namespace ringid {
namespace internal {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Records the cost after each Levenberg-Marquardt iteration.
class HistoryCallback : public ceres::IterationCallback {
 public:
  HistoryCallback(const ModalResiduals& residuals, LocalFit* fit)
      : residuals_(residuals), before_(residuals.evaluations()), fit_(fit) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    fit_->history.emplace_back(residuals_.evaluations() - before_, s.cost);
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const ModalResiduals& residuals_;
  const long before_;
  LocalFit* fit_;
};

LocalFit FitLevenbergMarquardt(const ModalResiduals& residuals,
                               const Eigen::VectorXd& start, const Box& box,
                               int max_iterations, int fixed) {
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
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = max_iterations;
  so.function_tolerance = 1e-14;
  so.gradient_tolerance = 1e-14;
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
  HistoryCallback history(residuals, &fit);
  so.callbacks.push_back(&history);
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  // The whole cost, rows of conditions without free coordinates included.
  fit.cost = summary.IsSolutionUsable() ? CostAt(residuals, fit.x) : kInf;
  fit.converged = summary.termination_type == ceres::CONVERGENCE;
  fit.message = summary.message;
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

std::vector<Eigen::VectorXd> DrawStarts(
    const ParameterSetup& setup, const Eigen::VectorXd& x0, const Box& box,
    int starts, double spread, unsigned seed,
    const std::function<bool(const Eigen::VectorXd&)>& usable) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Eigen::VectorXd> out = {x0};
  for (int k = 1; k < starts; ++k) {
    Eigen::VectorXd start;
    for (int attempt = 0; attempt < 100; ++attempt) {
      start = x0;
      for (int i = 0; i < setup.size(); ++i) {
        const double step = spread * normal(rng);
        start[i] += setup.is_log(i) ? step : step * std::max(std::abs(x0[i]), 1.0);
      }
      start = start.cwiseMax(box.lower).cwiseMin(box.upper);
      if (!usable || usable(start)) break;
    }
    out.push_back(start);
  }
  return out;
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
                    int fixed) {
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
    fit = FitLevenbergMarquardt(residuals, start, box, max_iterations, fixed);
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

}  // namespace internal
}  // namespace ringid
