// One identification problem, built once and owned together: the model, the
// dataset, which parameters are free, fixed or tied (ParameterSetup) and the
// weighted residuals that refer to them.
#ifndef RINGID_ESTIMATION_PROBLEM_H_
#define RINGID_ESTIMATION_PROBLEM_H_

#include <memory>
#include <string>

#include <Eigen/Core>

#include "datasets/dataset.h"
#include "estimation/options.h"
#include "estimation/status.h"
#include "estimation/types.h"
#include "model/rigid_ring_model.h"

namespace ringid {
namespace internal {
class ModalResiduals;   // estimation/residuals.h
class ParameterSetup;   // estimation/setup.h
}  // namespace internal

class Problem {
 public:
  // Null, with *status an invalid input naming the parameter or option, when
  // the dataset's setup cannot be built or the options are unusable.
  static std::unique_ptr<Problem> Create(const ModalModel& model, const Dataset& dataset,
                                         const ResidualOptions& options, Status* status);

  Problem(const Problem&) = delete;
  Problem& operator=(const Problem&) = delete;
  ~Problem();

  const ModalModel& model() const { return *model_; }
  const Dataset& dataset() const { return dataset_; }
  const internal::ParameterSetup& setup() const { return *setup_; }
  const internal::ModalResiduals& residuals() const { return *residuals_; }
  // The dataset's initial point in coordinates.
  Eigen::VectorXd start() const;

  // The coordinates fitted: the free parameters (per condition where they
  // vary), each its parameter's log when the parameter is positive.
  int num_coordinates() const;
  std::string coordinate_name(int i) const;  // "k_bx", or "F_cz0@drum_10"
  bool is_log(int i) const;
  // The weighted residuals: every condition's rows in order, then the priors'.
  int num_residuals() const;
  // The box identify fits in: each coordinate within bound_factor of the
  // start (IdentifyOptions), `bounds` replacing that for their parameters.
  void Box(double bound_factor, const Bounds& bounds, Eigen::VectorXd* lower,
           Eigen::VectorXd* upper) const;
  // As Ceres' Problem::Evaluate: the weighted residuals at x
  // (num_coordinates) and, where `jacobian` is not null, their exact
  // derivatives (num_residuals x num_coordinates). False where the model
  // cannot be solved at x or a measured mode has no counterpart there, and,
  // for the Jacobian, where the derivatives do not exist (two eigenvalues
  // coincide).
  bool Evaluate(const Eigen::VectorXd& x, Eigen::VectorXd* residuals,
                Eigen::MatrixXd* jacobian = nullptr) const;
  // Model solutions so far.
  long evaluations() const;

 private:
  Problem(std::unique_ptr<ModalModel> model, const Dataset& dataset);

  std::unique_ptr<ModalModel> model_;
  Dataset dataset_;
  std::unique_ptr<internal::ParameterSetup> setup_;
  std::unique_ptr<internal::ModalResiduals> residuals_;  // refers to the members above
};

}  // namespace ringid

#endif  // RINGID_ESTIMATION_PROBLEM_H_
