// Downhill Simplex against Levenberg-Marquardt from the same starts.
#ifndef RINGID_ESTIMATION_COMPARE_H_
#define RINGID_ESTIMATION_COMPARE_H_

#include <functional>
#include <string>
#include <vector>

#include "estimation/identify.h"

namespace ringid {

struct CompareOptions {
  IdentifyOptions fit;  // starts, spread, seed, bounds, iteration budgets
  // A start succeeds when its final cost is within
  // success_absolute + success_relative * best of the best cost any method
  // found.
  double success_absolute = 1e-6;
  double success_relative = 1e-3;
  // Called after each fit (2 x starts in all), e.g. to show progress.
  std::function<void()> on_fit;
  bool IsValid(std::string* why) const;
};

struct MethodRun {
  Method method;
  std::vector<double> final_costs;  // per start, in start order
  std::vector<long> evaluations;
  std::vector<double> seconds;
  std::vector<double> relative_error_in_plane;      // eq. (19) per start
  std::vector<double> relative_error_out_of_plane;  // eq. (20) per start
  // Per start: (model solutions so far, cost) per iteration (LocalFit).
  std::vector<std::vector<std::pair<long, double>>> histories;
  double success_rate = 0;
  double seconds_per_fit = 0;
  double median_evaluations = 0;
};

struct ComparisonReport {
  bool success = false;
  bool invalid_input = false;
  std::string message;
  int starts = 0;
  double best_cost = 0;
  std::vector<MethodRun> methods;  // lm, simplex
  // The dataset's initial point (for the paper's Table 1: Table 2), with the
  // paper's own stopping errors for reference.
  double initial_cost = 0;
  double initial_error_in_plane = 0, initial_error_out_of_plane = 0;

  std::string FullReport() const;
};

void CompareMethods(const ModalModel& model, const Dataset& dataset,
                    const CompareOptions& options, ComparisonReport* report);

// Eqs. (19), (20): sum ((f_exp - f_cal) / f_exp)^2 per plane at x; NaN where
// the plane has no measured mode or the model cannot be solved.
void RelativeErrors(const ModalResiduals& residuals, const Dataset& dataset,
                    const Eigen::VectorXd& x, double* in_plane,
                    double* out_of_plane);

}  // namespace ringid

#endif  // RINGID_ESTIMATION_COMPARE_H_
