// Weighted residuals of measured against model modes: the functor behind the
// Ceres cost function and the simplex objective.
#ifndef RINGID_ESTIMATION_RESIDUALS_H_
#define RINGID_ESTIMATION_RESIDUALS_H_

#include <atomic>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <ceres/cost_function.h>
#include <ceres/problem.h>

#include "datasets/dataset.h"
#include "datasets/measurement.h"
#include "estimation/options.h"
#include "estimation/setup.h"
#include "model/modal.h"
#include "model/rigid_ring_model.h"

namespace ringid {

// Frequency ratios the pairing is judged by (ModalResiduals::PairingWarnings).
// At the start: a guess whose stiffnesses lie within a factor 4 of the truth
// puts every mode within a factor 2 (f ~ sqrt(k / m)); further, the guess or
// the measured frequency is wrong.
inline constexpr double kStartFrequencyRatio = 2;
// At the best fit: 20 %, tens of sigmas of any measured frequency.
inline constexpr double kFitFrequencyRatio = 1.2;
// Two model modes within this relative difference share one frequency.
inline constexpr double kCoincidentRelative = 1e-3;

namespace internal {

class ModalResiduals {
 public:
  ModalResiduals(const ModalModel& model, const Dataset& dataset,
                 const ParameterSetup& setup, const ResidualOptions& options);

  int num_residuals() const { return num_residuals_; }
  int num_parameters() const { return setup_.size(); }
  const ParameterSetup& setup() const { return setup_; }
  const ModalModel& model() const { return model_; }
  const Dataset& dataset() const { return dataset_; }

  // r(x): every condition's residuals in order, then the priors. False when
  // the model cannot be solved or a measured mode has no model counterpart
  // (say, its pair of roots became real).
  // With `near`, each condition's solution at a nearby point, labels are
  // carried from it (ModalModel::SolveFrom), as numeric derivatives ask.
  bool Evaluate(const double* x, double* residuals,
                const std::vector<ModalSolution>* near = nullptr) const;
  // For ceres::DynamicNumericDiffCostFunction.
  bool operator()(double const* const* x, double* residuals) const {
    return Evaluate(x[0], residuals);
  }
  // The rows of condition c, [row_begin(c), row_begin(c + 1)), from the
  // shared coordinates and that condition's own; rows of the priors follow.
  bool EvaluateCondition(int c, const double* shared, const double* own, double* r,
                         const ModalSolution* near = nullptr) const;
  // Condition c's model solution there (one evaluation); an empty one where
  // the condition measures no mode (nothing of it reads the modes).
  ModalSolution SolveCondition(int c, const double* shared, const double* own) const;
  // The same rows and their exact derivatives with respect to the shared and
  // own coordinates (row-major; either may be null). False as
  // EvaluateCondition; *defined false where the derivatives do not exist
  // (two eigenvalues coincide), the rows still set. Each thread keeps the last
  // point of each condition: asked again there (the fit's bounded line
  // search, its stopping rule, the analysis at the optimum), they are copied,
  // not made (nor counted in evaluations()).
  bool EvaluateConditionJacobian(int c, const double* shared, const double* own, double* r,
                                 double* jacobian_shared, double* jacobian_own,
                                 bool* defined) const;
  // The rows this thread kept of condition c at (shared, own), as
  // EvaluateConditionJacobian made them; false where it kept none there.
  bool KeptRows(int c, const double* shared, const double* own, double* r) const {
    bool defined;
    return Recall(c, shared, own, r, nullptr, nullptr, &defined);
  }
  // Forgets what this thread kept, so that what a fit evaluates does not
  // depend on what the thread did before it (one start after another).
  void ForgetKept() const;
  int row_begin(int c) const { return row_begin_[c]; }
  const ResidualOptions& options() const { return options_; }
  // Whether condition c's rows are differentiated exactly: options().derivatives
  // analytic, or auto and the condition measures no mode (types.h).
  bool ExactJacobian(int c) const {
    return options_.derivatives == Derivatives::kAnalytic ||
           (options_.derivatives == Derivatives::kAuto && !modal_[c]);
  }

  // A prior as a residual on one shared coordinate x (docs/conventions.md §7):
  // normal (value(x) - mean) / sigma, lognormal (x - log median) / s with
  // s = log(factor_95) / 1.96.
  struct PriorTerm {
    int coordinate;
    PriorDistribution distribution;
    double center;  // mean, or log median
    double scale;   // sigma, or s
    double Residual(const ParameterSetup& setup, double x) const;
    double Derivative(const ParameterSetup& setup, double x) const;
    // The prior's variance in the coordinate at x (delta method for normal).
    double CoordinateVariance(const ParameterSetup& setup, double x) const;
  };
  const std::vector<PriorTerm>& priors() const { return priors_; }

  // The model solution of each condition at x and, for each measured mode,
  // the index of the model mode paired with it in its condition's solution.
  // False (with `why`) as for Evaluate.
  bool Pair(const double* x, std::vector<ModalSolution>* solutions, std::vector<int>* pairs,
            std::string* why) const;

  // What a reader must know about the pairing at x (issue 21), one sentence
  // each: a measured mode paired with a model mode of another label, or with
  // one kNearerRatio (residuals.cc) further from it than the nearest; one
  // further than kStartFrequencyRatio (at the start) or kFitFrequencyRatio (at
  // the best fit) from every model mode; two model modes driven to one
  // frequency (kCoincidentRelative) where the data have two. Each names the
  // nearest model modes.
  std::vector<std::string> PairingWarnings(const double* x, bool start) const;

  // Which residuals belong to which measurement and item (datasets/measurement.h).
  struct Slot {
    int item = -1;                             // of measurement->records(); -1 for a prior
    const Measurement* measurement = nullptr;  // null for a prior
    int component = 0;                         // the row within the item's
    int prior = -1;                            // for a prior: index into priors()
  };
  const std::vector<Slot>& slots() const { return slots_; }

  long evaluations() const { return evaluations_.load(); }
  void reset_evaluations() { evaluations_ = 0; }

 private:
  const ModalModel& model_;
  const Dataset& dataset_;
  const ParameterSetup& setup_;
  ResidualOptions options_;
  // Condition c's rows from its parameters p and model solution (null where
  // it measures no mode) and, where dr is not empty, their derivatives with
  // respect to each catalogue parameter.
  bool Rows(int c, const Parameters& p, const ModalSolution* solution, double* r,
            Eigen::Ref<RowMatrix> dr) const;
  // Pairs the measured modes of condition c with `solution`'s
  // (datasets/pairing.h).
  bool PairCondition(int c, const ModalSolution& solution, std::vector<int>* pairs,
                     std::string* why) const;

  std::vector<Slot> slots_;
  std::vector<PriorTerm> priors_;
  std::vector<int> row_begin_;  // per condition, then the first prior row
  // Per condition: whether it measures modes, the only rows that read the
  // model's modes (FRFs and statics do not: their conditions skip the solve).
  std::vector<bool> modal_;
  std::vector<int> derived_;    // catalogue parameters some coordinate moves
  int num_residuals_ = 0;
  mutable std::atomic<long> evaluations_{0};
  // Tells this problem's kept points (EvaluateConditionJacobian) from any
  // other's on the same thread.
  const uint64_t id_;
  static uint64_t NextId();
  // EvaluateConditionJacobian without what is kept.
  bool MakeConditionJacobian(int c, const double* shared, const double* own, double* r,
                             double* jacobian_shared, double* jacobian_own, bool* defined) const;
  // Copies what this thread kept of condition c at (shared, own) into the
  // outputs asked for; false where it kept nothing there or not every output.
  bool Recall(int c, const double* shared, const double* own, double* r, double* jacobian_shared,
              double* jacobian_own, bool* defined) const;
};

// Whether v[0, n) are all finite, without a branch per value (a residual
// block's Jacobian has millions): v * 0 is 0 but where v is not finite.
inline bool AllFinite(const double* v, size_t n) {
  double zero[4] = {0, 0, 0, 0};
  size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    for (int k = 0; k < 4; ++k) zero[k] += v[i + k] * 0.0;
  }
  for (; i < n; ++i) zero[0] += v[i] * 0.0;
  return zero[0] + zero[1] + zero[2] + zero[3] == 0;
}

// The Ceres cost functions (estimation/residual_costs.cc).

// The residuals as a Ceres cost function of one parameter block of all free
// coordinates, with the Jacobian options().derivatives asks for. Numeric:
// central differences through the eigen-solution. The relative
// step is 1e-4, not Ceres' 1e-6: before the state matrix was balanced
// (model/modal.cc) the eigenvectors of these near-critically damped modes
// carried errors near 1e-10, which a 1e-6 step turned into Jacobian noise of
// 1e-4 (measured on the exact K_cx / sigma_cx pair); with 1e-4 the noise and
// the truncation error were both near 1e-7. The functor is not owned.
ceres::CostFunction* NewResidualCost(const ModalResiduals& residuals);

// Eqs. (19), (20): sum ((f_exp - f_cal) / f_exp)^2 over the measured in-plane
// and out-of-plane modes, each paired with solutions[its condition].modes
// [pairs[i]] (ModalResiduals::Pair); NaN for a plane without a measured mode.
void RelativeErrors(const Dataset& dataset, const std::vector<ModalSolution>& solutions,
                    const std::vector<int>& pairs, double* in_plane, double* out_of_plane);

// The same residuals in `problem` as one Ceres problem over x: per condition
// a cost function of the shared coordinates' block and its own block (both
// pieces of x), and the priors as one more residual block with exact
// derivatives. Returns the parameter blocks, each {offset in x, size}.
std::vector<std::pair<int, int>> AddResidualBlocks(const ModalResiduals& residuals,
                                                   Eigen::VectorXd* x, ceres::Problem* problem);

}  // namespace internal
}  // namespace ringid

#endif  // RINGID_ESTIMATION_RESIDUALS_H_
