// One identification problem, built once and owned together: the model, the
// dataset, which parameters are free, fixed or tied (ParameterSetup) and the
// weighted residuals that refer to them.
#ifndef RINGID_ESTIMATION_PROBLEM_H_
#define RINGID_ESTIMATION_PROBLEM_H_

#include <memory>

#include <Eigen/Core>

#include "datasets/dataset.h"
#include "estimation/options.h"
#include "estimation/status.h"
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

 private:
  Problem(std::unique_ptr<ModalModel> model, const Dataset& dataset);

  std::unique_ptr<ModalModel> model_;
  Dataset dataset_;
  std::unique_ptr<internal::ParameterSetup> setup_;
  std::unique_ptr<internal::ModalResiduals> residuals_;  // refers to the members above
};

}  // namespace ringid

#endif  // RINGID_ESTIMATION_PROBLEM_H_
