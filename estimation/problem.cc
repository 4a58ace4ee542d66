#include "estimation/problem.h"

#include <string>
#include <utility>

#include "estimation/residuals.h"
#include "estimation/setup.h"

namespace ringid {

using internal::ModalResiduals;
using internal::ParameterSetup;

Problem::Problem(std::unique_ptr<ModalModel> model, const Dataset& dataset)
    : model_(std::move(model)), dataset_(dataset), setup_(std::make_unique<ParameterSetup>()) {}

Problem::~Problem() = default;

Eigen::VectorXd Problem::start() const { return setup_->StartCoordinates(); }

std::unique_ptr<Problem> Problem::Create(const ModalModel& model, const Dataset& dataset,
                                         const ResidualOptions& options, Status* status) {
  std::string why;
  if (!options.IsValid(&why)) {
    *status = Status::InvalidInput("invalid options: " + why);
    return nullptr;
  }
  std::unique_ptr<Problem> p(new Problem(model.Clone(), dataset));
  if (!ParameterSetup::Build(*p->model_, p->dataset_, p->setup_.get(), &why)) {
    *status = Status::InvalidInput(why);
    return nullptr;
  }
  p->residuals_ = std::make_unique<ModalResiduals>(*p->model_, p->dataset_, *p->setup_, options);
  *status = Status::Success();
  return p;
}

}  // namespace ringid
