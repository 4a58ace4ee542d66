// Downhill Simplex against Levenberg-Marquardt from the same starts.
#ifndef RINGID_ESTIMATION_COMPARE_H_
#define RINGID_ESTIMATION_COMPARE_H_

#include <functional>
#include <optional>
#include <utility>
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

  template <class Archive>  // keyed by method in ComparisonResult
  void Serialize(Archive* a) {
    a->Visit("final_costs", &final_costs);
    a->Derived("starts", final_costs.size());
    a->Visit("success_rate", &success_rate);
    a->Visit("evaluations", &evaluations);
    a->Visit("seconds", &seconds);
    a->Visit("seconds_per_fit", &seconds_per_fit);
    a->Visit("median_evaluations", &median_evaluations);
    a->Group("relative_error", [&](auto* g) {
      g->Visit("in_plane_eq19", &relative_error_in_plane);
      g->Visit("out_of_plane_eq20", &relative_error_out_of_plane);
    });
    a->Visit("histories_evaluations_cost", &histories);
  }
};

struct ComparisonResult {
  Status status;
  int starts = 0;
  double best_cost = 0;
  std::vector<MethodRun> methods;  // lm, simplex
  // The dataset's initial point (for the paper's Table 1: Table 2), with the
  // paper's own stopping errors for reference.
  double initial_cost = 0;
  double initial_error_in_plane = 0, initial_error_out_of_plane = 0;
  // The stopping errors the paper reported for its simplex, where the
  // dataset is the paper's Table 1 (eq. 19, eq. 20; docs/model.md section 10).
  std::optional<std::pair<double, double>> paper_reported;

  std::string FullReport() const;

  template <class Archive>
  void Serialize(Archive* a) {
    status.Serialize(a);
    a->Visit("starts", &starts);
    a->Visit("best_cost", &best_cost);
    a->VisitKeyed("methods", &methods, &MethodRun::method);
    a->Group("initial", [&](auto* g) {
      g->Visit("cost", &initial_cost);
      g->Group("relative_error", [&](auto* e) {
        e->Visit("in_plane_eq19", &initial_error_in_plane);
        e->Visit("out_of_plane_eq20", &initial_error_out_of_plane);
      });
    });
    a->VisitIfSet("paper_reported_eq19_eq20", &paper_reported);
  }
};

void CompareMethods(const ModalModel& model, const Dataset& dataset,
                    const CompareOptions& options, ComparisonResult* report);

}  // namespace ringid

#endif  // RINGID_ESTIMATION_COMPARE_H_
