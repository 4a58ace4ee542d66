#include "python/problem.h"

#include <cmath>
#include <limits>
#include <memory>

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "apps/flags.h"
#include "estimation/fit.h"
#include "estimation/problem.h"
#include "estimation/residuals.h"
#include "estimation/setup.h"
#include "python/convert.h"

namespace ringid::python {
namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct PyProblem {
  std::unique_ptr<Problem> problem;
  Eigen::VectorXd lower, upper;
  const internal::ModalResiduals& residuals() const { return problem->residuals(); }

  void CheckSize(const Eigen::VectorXd& x) const {
    if (x.size() != residuals().num_parameters()) {
      throw Error::Usage("x: " + std::to_string(x.size()) + " coordinates, the problem has " +
                         std::to_string(residuals().num_parameters()));
    }
  }
  Eigen::VectorXd Residuals(const Eigen::VectorXd& x) const {
    CheckSize(x);
    Eigen::VectorXd r(residuals().num_residuals());
    py::gil_scoped_release release;
    if (!residuals().Evaluate(x.data(), r.data())) r.setConstant(std::numeric_limits<double>::quiet_NaN());
    return r;
  }
  // Exact derivatives, each condition's rows from its shared and own coordinates.
  RowMatrix Jacobian(const Eigen::VectorXd& x) const {
    CheckSize(x);
    const internal::ModalResiduals& res = residuals();
    const internal::ParameterSetup& setup = res.setup();
    const int conditions = setup.num_conditions();
    if (res.row_begin(conditions) != res.num_residuals()) {
      throw Error::Usage("jacobian: not for a dataset with priors (use finite differences)");
    }
    RowMatrix j = RowMatrix::Zero(res.num_residuals(), res.num_parameters());
    py::gil_scoped_release release;
    for (int c = 0; c < conditions; ++c) {
      const int rows = res.row_begin(c + 1) - res.row_begin(c);
      const int own = setup.own_begin(c + 1) - setup.own_begin(c);
      RowMatrix shared(rows, setup.num_shared()), mine(rows, own);
      Eigen::VectorXd r(rows);
      bool defined = true;
      if (!res.EvaluateConditionJacobian(c, x.data(), x.data() + setup.own_begin(c), r.data(),
                                         shared.data(), own ? mine.data() : nullptr, &defined) ||
          !defined) {
        j.setConstant(std::numeric_limits<double>::quiet_NaN());
        return j;
      }
      j.block(res.row_begin(c), 0, rows, setup.num_shared()) = shared;
      if (own) j.block(res.row_begin(c), setup.own_begin(c), rows, own) = mine;
    }
    return j;
  }
};

std::shared_ptr<PyProblem> MakeProblem(py::handle dataset, const py::kwargs& kw) {
  FlagScope scope("Problem", Without(FitFlags(), {"dataset", "output"}), kw);
  const auto loaded = PathOf(dataset) || py::isinstance<py::dict>(dataset)
                          ? LoadDatasetFrom(dataset)
                          : dataset.cast<std::shared_ptr<LoadedDataset>>();
  FLAGS_dataset = loaded->Name();
  IdentifyOptions o;
  std::vector<const Effect*> effects;
  std::string error;
  if (!ReadFitOptions(&o, &effects, &error)) throw Error::Usage(error);
  Dataset d = loaded->dataset;
  if (!ApplyFix(&d, &error)) throw Error::Usage(error);
  auto p = std::make_shared<PyProblem>();
  Status status;
  p->problem = Problem::Create(RigidRingModel(effects), d, o.residuals, &status);
  if (!p->problem) throw Error{loaded->Name() + ": " + status.message, loaded->Name(), "", status.message};
  const internal::Box box = internal::BoundsAround(p->problem->setup(), p->problem->start(),
                                                   o.bound_factor, o.bounds);
  p->lower = box.lower;
  p->upper = box.upper;
  return p;
}

}  // namespace

void BindProblem(py::module_& m) {
  py::class_<PyProblem, std::shared_ptr<PyProblem>>(
      m, "Problem",
      "Problem(dataset, **options): the weighted residuals ringid.identify minimises, over the "
      "coordinates it fits (the log of each positive parameter), with the box it fits in and its "
      "start; options as ringid.identify's (weighting, shapes, damping, derivatives, fix, effects, "
      "bounds, ...).")
      .def(py::init(&MakeProblem), py::arg("dataset"))
      .def_property_readonly("start", [](const PyProblem& p) { return p.problem->start(); },
                             "The dataset's initial point in coordinates (numpy).")
      .def_property_readonly("lower", [](const PyProblem& p) { return p.lower; },
                             "The box's lower side (numpy), as identify's.")
      .def_property_readonly("upper", [](const PyProblem& p) { return p.upper; },
                             "The box's upper side (numpy), as identify's.")
      .def_property_readonly("names", [](const PyProblem& p) {
        std::vector<std::string> names;
        for (int i = 0; i < p.problem->setup().size(); ++i) names.push_back(p.problem->setup().name(i));
        return names;
      }, "The coordinates' names.")
      .def_property_readonly("log_coordinates", [](const PyProblem& p) {
        std::vector<bool> logs;
        for (int i = 0; i < p.problem->setup().size(); ++i) logs.push_back(p.problem->setup().is_log(i));
        return logs;
      }, "Whether each coordinate is its parameter's log (positive parameters) or its value.")
      .def_property_readonly("num_residuals", [](const PyProblem& p) { return p.residuals().num_residuals(); },
                             "The number of weighted residuals.")
      .def_property_readonly("evaluations", [](const PyProblem& p) { return p.residuals().evaluations(); },
                             "Model solutions so far.")
      .def("residuals", &PyProblem::Residuals, py::arg("x"),
           "The weighted residuals at x (numpy; NaN everywhere where the model cannot be solved).")
      .def("jacobian", &PyProblem::Jacobian, py::arg("x"),
           "Their exact derivatives at x (numpy, residuals x coordinates; NaN where undefined).")
      .def("cost", [](const PyProblem& p, const Eigen::VectorXd& x) {
        return 0.5 * p.Residuals(x).squaredNorm();
      }, py::arg("x"), "1/2 the sum of squared residuals at x, as identify's cost.");
}

}  // namespace ringid::python
