#include "estimation/compare.h"

#include "datasets/paper.h"
#include "estimation/fit.h"
#include "estimation/problem.h"
#include "estimation/starts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace ringid {

using internal::Box;
using internal::LocalFit;
using internal::ModalResiduals;
using internal::ParameterSetup;

namespace {

double Median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Eqs. (19), (20) at x (internal::RelativeErrors); NaN where the model
// cannot be solved.
void RelativeErrors(const ModalResiduals& residuals, const Dataset& dataset,
                    const Eigen::VectorXd& x, double* in_plane, double* out_of_plane) {
  *in_plane = *out_of_plane = std::numeric_limits<double>::quiet_NaN();
  std::vector<ModalSolution> s;
  std::vector<int> pairs;
  std::string why;
  if (residuals.Pair(x.data(), &s, &pairs, &why)) {
    internal::RelativeErrors(dataset, s, pairs, in_plane, out_of_plane);
  }
}

}  // namespace

bool CompareOptions::IsValid(std::string* why) const {
  if (!(success_absolute >= 0) || !(success_relative >= 0)) {
    *why = "success tolerances must not be negative";
    return false;
  }
  return fit.IsValid(why);
}

void CompareMethods(const ModalModel& model, const Dataset& dataset,
                    const CompareOptions& o, ComparisonResult* r) {
  *r = ComparisonResult{};
  std::string why;
  if (!o.IsValid(&why)) {
    r->status = Status::InvalidInput(why);
    return;
  }
  const auto problem = Problem::Create(model, dataset, o.fit.residuals, &r->status);
  if (!problem) return;
  const ParameterSetup& setup = problem->setup();
  const ModalResiduals& residuals = problem->residuals();
  const Eigen::VectorXd x0 = setup.StartCoordinates();
  std::string bad;
  if (!CheckBounds(setup, x0, o.fit.bounds, &bad)) {
    r->status = Status::InvalidInput(bad);
    return;
  }
  const Box box = BoundsAround(setup, x0, o.fit.bound_factor, o.fit.bounds);
  const auto starts = PlanStarts(residuals, x0, box, o.fit.starts, o.fit.start_factor, o.fit.seed,
                                 [&](const Eigen::VectorXd& x) { return std::isfinite(CostAt(residuals, x)); });
  r->starts = static_cast<int>(starts.size());
  r->initial_cost = CostAt(residuals, x0);
  RelativeErrors(residuals, dataset, x0, &r->initial_error_in_plane,
                 &r->initial_error_out_of_plane);
  if (dataset.name == kPaperTable1Name) {
    r->paper_reported = {kPaperSimplexErrorInPlane, kPaperSimplexErrorOutOfPlane};
  }
  r->best_cost = std::numeric_limits<double>::infinity();
  for (Method method : {Method::kLevenbergMarquardt, Method::kSimplex}) {
    MethodRun run;
    run.method = method;
    for (const internal::Start& start : starts) {
      const LocalFit fit = FitLocally(residuals, method, start.x, box,
                                      o.fit.max_iterations, o.fit.simplex);
      run.final_costs.push_back(fit.cost);
      run.evaluations.push_back(fit.evaluations);
      run.seconds.push_back(fit.seconds);
      run.histories.push_back(fit.history);
      double e19, e20;
      RelativeErrors(residuals, dataset, fit.x, &e19, &e20);
      run.relative_error_in_plane.push_back(e19);
      run.relative_error_out_of_plane.push_back(e20);
      r->best_cost = std::min(r->best_cost, fit.cost);
      if (o.on_fit) o.on_fit();
    }
    r->methods.push_back(run);
  }
  if (!std::isfinite(r->best_cost)) {
    r->status = Status::Failed("no start of either method produced a usable fit");
    return;
  }
  const double tolerance = o.success_absolute + o.success_relative * r->best_cost;
  for (MethodRun& run : r->methods) {
    int ok = 0;
    double total = 0;
    std::vector<double> evals;
    for (size_t k = 0; k < run.final_costs.size(); ++k) {
      ok += run.final_costs[k] <= r->best_cost + tolerance;
      total += run.seconds[k];
      evals.push_back(static_cast<double>(run.evaluations[k]));
    }
    run.success_rate = static_cast<double>(ok) / run.final_costs.size();
    run.seconds_per_fit = total / run.final_costs.size();
    run.median_evaluations = Median(evals);
  }
  r->status = Status::Success();
}

std::string ComparisonResult::FullReport() const {
  std::ostringstream o;
  char line[256];
  if (!status.ok()) return "ringid compare: FAILED: " + status.message + "\n";
  std::snprintf(line, sizeof line, "ringid compare: %d starts per method, best cost %.3e\n\n", starts, best_cost);
  o << line;
  o << "  method    success  median cost   worst cost   median evals  s/fit     median eq.19  median eq.20\n";
  // The finite values of `v` sorted (NaN: a start without a fit).
  const auto sorted = [](std::vector<double> v) {
    v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
    std::sort(v.begin(), v.end());
    return v;
  };
  const auto median = [](const std::vector<double>& v) { return v.empty() ? NAN : v[v.size() / 2]; };
  for (const MethodRun& m : methods) {
    const std::vector<double> c = sorted(m.final_costs);
    std::snprintf(line, sizeof line, "  %-8s  %5.1f %%  %11.3e  %11.3e  %12.0f  %8.4f  %12.3e  %12.3e\n",
                  ToString(m.method), 100 * m.success_rate, median(c), c.empty() ? NAN : c.back(),
                  m.median_evaluations, m.seconds_per_fit, median(sorted(m.relative_error_in_plane)),
                  median(sorted(m.relative_error_out_of_plane)));
    o << line;
  }
  std::snprintf(line, sizeof line,
                "  initial   (the dataset's initial values)\n"
                "            cost %.3e, eq. (19) %.3e, eq. (20) %.3e\n",
                initial_cost, initial_error_in_plane, initial_error_out_of_plane);
  o << line;
  if (paper_reported) {
    std::snprintf(line, sizeof line, "  paper     its simplex stopped at eq. (19) %.3g, eq. (20) %.3g\n",
                  paper_reported->first, paper_reported->second);
    o << line;
  }
  return o.str();
}

}  // namespace ringid
