#include "python/problem.h"

#include <cmath>
#include <limits>
#include <memory>

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "estimation/problem.h"
#include "operations/fit.h"
#include "python/convert.h"

namespace ringid::python {
namespace {

// The problem and the box identify fits it in, through the public API alone
// (estimation/problem.h).
struct PyProblem {
  std::unique_ptr<Problem> problem;
  Eigen::VectorXd lower, upper;

  void CheckSize(const Eigen::VectorXd& x) const {
    if (x.size() != problem->num_coordinates()) {
      throw Error::Usage("x: " + std::to_string(x.size()) + " coordinates, the problem has " +
                         std::to_string(problem->num_coordinates()));
    }
  }
  // NaN everywhere where the model cannot be solved.
  Eigen::VectorXd Residuals(const Eigen::VectorXd& x) const {
    CheckSize(x);
    Eigen::VectorXd r;
    py::gil_scoped_release release;
    if (!problem->Evaluate(x, &r)) r.setConstant(std::numeric_limits<double>::quiet_NaN());
    return r;
  }
  // NaN everywhere where the derivatives are not defined.
  Eigen::MatrixXd Jacobian(const Eigen::VectorXd& x) const {
    CheckSize(x);
    Eigen::VectorXd r;
    Eigen::MatrixXd j;
    py::gil_scoped_release release;
    if (!problem->Evaluate(x, &r, &j)) {
      j.setConstant(problem->num_residuals(), problem->num_coordinates(),
                    std::numeric_limits<double>::quiet_NaN());
    }
    return j;
  }
};

std::shared_ptr<PyProblem> MakeProblem(py::handle dataset, const py::kwargs& kw) {
  std::vector<std::string> argv;
  const FitSettings s = ReadOptions<FitSettings>("Problem", kw, &argv);
  IdentifyOptions o;
  std::string error;
  if (!FitOptionsOf(s, 1, &o, &error)) throw Error::Usage(error);
  const auto loaded = PathOf(dataset) || py::isinstance<py::dict>(dataset)
                          ? LoadDatasetFrom(dataset)
                          : dataset.cast<std::shared_ptr<LoadedDataset>>();
  Dataset d = loaded->dataset;
  if (!ApplyFix(s.fix, &d, &error)) throw Error::Usage(error);
  auto p = std::make_shared<PyProblem>();
  Status status;
  p->problem = Problem::Create(RigidRingModel(s.effects), d, o.residuals, &status);
  if (!p->problem) throw Error{loaded->Name() + ": " + status.message, loaded->Name(), "", status.message};
  p->problem->Box(o.bound_factor, o.bounds, &p->lower, &p->upper);
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
        for (int i = 0; i < p.problem->num_coordinates(); ++i) names.push_back(p.problem->coordinate_name(i));
        return names;
      }, "The coordinates' names.")
      .def_property_readonly("log_coordinates", [](const PyProblem& p) {
        std::vector<bool> logs;
        for (int i = 0; i < p.problem->num_coordinates(); ++i) logs.push_back(p.problem->is_log(i));
        return logs;
      }, "Whether each coordinate is its parameter's log (positive parameters) or its value.")
      .def_property_readonly("num_residuals", [](const PyProblem& p) { return p.problem->num_residuals(); },
                             "The number of weighted residuals.")
      .def_property_readonly("evaluations", [](const PyProblem& p) { return p.problem->evaluations(); },
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
