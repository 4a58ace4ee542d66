#include "estimation/problem.h"

#include <string>
#include <utility>

#include "datasets/measurement.h"
#include "estimation/fit.h"
#include "estimation/residuals.h"
#include "estimation/setup.h"

namespace ringid {

using internal::ModalResiduals;
using internal::ParameterSetup;

Problem::Problem(std::unique_ptr<ModalModel> model, const Dataset& dataset)
    : model_(std::move(model)), dataset_(dataset), setup_(std::make_unique<ParameterSetup>()) {}

Problem::~Problem() = default;

Eigen::VectorXd Problem::start() const { return setup_->StartCoordinates(); }

int Problem::num_coordinates() const { return setup_->size(); }
std::string Problem::coordinate_name(int i) const { return setup_->name(i); }
bool Problem::is_log(int i) const { return setup_->is_log(i); }
int Problem::num_residuals() const { return residuals_->num_residuals(); }
long Problem::evaluations() const { return residuals_->evaluations(); }

void Problem::Box(double bound_factor, const Bounds& bounds, Eigen::VectorXd* lower,
                  Eigen::VectorXd* upper) const {
  const internal::Box box = internal::BoundsAround(*setup_, start(), bound_factor, bounds);
  *lower = box.lower;
  *upper = box.upper;
}

bool Problem::Evaluate(const Eigen::VectorXd& x, Eigen::VectorXd* r,
                       Eigen::MatrixXd* jacobian) const {
  const ModalResiduals& res = *residuals_;
  r->resize(res.num_residuals());
  if (!jacobian) return res.Evaluate(x.data(), r->data());
  using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  const ParameterSetup& setup = *setup_;
  const int conditions = setup.num_conditions(), ns = setup.num_shared();
  jacobian->setZero(res.num_residuals(), setup.size());
  // Each condition's rows from its shared and own coordinates.
  for (int c = 0; c < conditions; ++c) {
    const int row = res.row_begin(c), rows = res.row_begin(c + 1) - row;
    const int own = setup.own_begin(c), size = setup.own_begin(c + 1) - own;
    RowMatrix shared(rows, ns), mine(rows, size);
    bool defined = true;
    if (!res.EvaluateConditionJacobian(c, x.data(), x.data() + own, r->data() + row,
                                       shared.data(), size ? mine.data() : nullptr, &defined) ||
        !defined) {
      return false;
    }
    jacobian->block(row, 0, rows, ns) = shared;
    if (size) jacobian->block(row, own, rows, size) = mine;
  }
  // Then the priors, each on one shared coordinate.
  const auto& priors = res.priors();
  for (size_t k = 0; k < priors.size(); ++k) {
    const int row = res.row_begin(conditions) + static_cast<int>(k);
    const double xi = x[priors[k].coordinate];
    (*r)[row] = priors[k].Residual(setup, xi);
    (*jacobian)(row, priors[k].coordinate) = priors[k].Derivative(setup, xi);
  }
  return true;
}

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
  for (const Measurement* unit : Measurements()) {
    for (int i = 0; i < unit->records().Items(p->dataset_); ++i) {
      if (auto why_not = unit->Unfit(*p->model_, p->dataset_, i)) {
        *status = Status::InvalidInput(*why_not);
        return nullptr;
      }
    }
  }
  p->residuals_ = std::make_unique<ModalResiduals>(*p->model_, p->dataset_, *p->setup_, options);
  if (p->residuals_->num_residuals() == 0) {  // an FRF band that holds no line
    *status = Status::InvalidInput("the dataset holds no value to fit: its FRFs have no line "
                                   "within the band");
    return nullptr;
  }
  *status = Status::Success();
  return p;
}

}  // namespace ringid
