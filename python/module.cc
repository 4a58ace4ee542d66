// The Python module `ringid` (issue 25): the library's operations
// in-process (python/operations.cc), on its typed inputs and reports.
// Keyword arguments are the options of operations/options.h, the command
// line's flags, with their defaults and meanings; errors are ringid.Error
// with the command line's one line. Only the installed headers are used
// (LayeringTest.PythonUsesOnlyThePublicLibrary).
#include <cmath>
#include <complex>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glog/logging.h>
#include <pybind11/complex.h>
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "operations/files.h"
#include "operations/fit.h"
#include "python/convert.h"
#include "python/operations.h"
#include "python/problem.h"
#include "python/results.h"

namespace ringid::python {
namespace {

using IdentifyHeld = Held<IdentifyReport>;

py::array_t<double> ModeColumn(const IdentifyResult& r, double ModeFit::*field) {
  py::array_t<double> out(static_cast<py::ssize_t>(r.modes.size()));
  for (size_t i = 0; i < r.modes.size(); ++i) out.mutable_at(i) = r.modes[i].*field;
  return out;
}

// What --save_parameters writes for this fit: named after the dataset, from
// the file it was read from.
ParameterSet SavedParameters(const IdentifyHeld& h) {
  std::string from = "<dict>";
  for (const InputFile& f : h.report.provenance.inputs) {
    if (f.role == "dataset") from = f.path;
  }
  return IdentifiedParameterSet(h.report.body.result, h.report.body.dataset,
                                "identified by ringid from " + from);
}

void BindIdentify(py::module_& m) {
  BindResult<IdentifyReport>(m, "IdentifyResult",
                             "What ringid.identify returns: the identify report of the command line.")
      .def_property_readonly("x", [](const IdentifyHeld& h) { return h.report.body.result.x; },
                             "The fitted coordinates (log for positive parameters), as covariance.names.")
      .def_property_readonly("coordinate_names",
                             [](const IdentifyHeld& h) { return h.report.body.result.coordinate_names; },
                             "The coordinates' names, in the order of x and of the matrices.")
      .def_property_readonly("covariance_matrix",
                             [](const IdentifyHeld& h) { return h.report.body.result.uncertainty.covariance; },
                             "The coordinates' covariance (numpy), the report's covariance.matrix.")
      .def_property_readonly("jacobian",
                             [](const IdentifyHeld& h) { return h.report.body.result.uncertainty.jacobian; },
                             "The weighted residuals' Jacobian at the fit (numpy, residuals x coordinates).")
      .def_property_readonly("singular_values",
                             [](const IdentifyHeld& h) { return h.report.body.result.uncertainty.singular_values; },
                             "The Jacobian's singular values, descending (numpy).")
      .def_property_readonly("null_space",
                             [](const IdentifyHeld& h) { return h.report.body.result.uncertainty.null_space; },
                             "Columns: coordinate directions the data leave free (numpy).")
      .def_property_readonly("measured_hz",
                             [](const IdentifyHeld& h) { return ModeColumn(h.report.body.result, &ModeFit::measured_hz); },
                             "The measured frequencies of the modes fitted (numpy), as modes.")
      .def_property_readonly("model_hz",
                             [](const IdentifyHeld& h) { return ModeColumn(h.report.body.result, &ModeFit::model_hz); },
                             "The fitted model's frequencies of those modes (numpy), as modes.")
      .def("parameter_set", [](const IdentifyHeld& h) {
        auto p = std::make_shared<LoadedParameters>();
        for (const auto& [q, v] : SavedParameters(h).parameters) p->values[q] = v.value;
        return p;
      }, "The fitted values as a ringid.ParameterSet, for predict, simulate and forces.")
      .def("save_parameters", [](const IdentifyHeld& h, py::handle path) {
        const auto file = PathOf(path);
        if (!file) throw Error::Usage("save_parameters: a path (str or os.PathLike)");
        if (!h.report.body.result.status.ok()) {
          throw Error::Usage("save_parameters: the identification did not succeed");
        }
        std::string error;
        if (!WriteFileAtomically(*file, ParameterSetText(SavedParameters(h)), &error)) {
          throw Error::Usage(error);
        }
      }, py::arg("path"), "Writes the fitted parameter set (ringid-parameters/1) to path, as --save_parameters.");
}

// The standing modes' frequencies (part 0) or damping ratios (1), by label
// as the report's modes; with speeds, a row per speed (NaN for a label a
// speed lacks: its roots became real).
py::array_t<double> AtSpeeds(const PredictBody& body, int part) {
  const auto value = [&](const std::pair<double, double>& v) { return part ? v.second : v.first; };
  if (!body.speeds) {
    std::vector<double> v;
    for (const PredictedMode& mode : body.modes) {
      v.push_back(part ? mode.damping_ratio : mode.model_hz);
    }
    return py::array_t<double>(v.size(), v.data());
  }
  py::array_t<double> out({body.speeds->size(), body.modes.size()});
  auto a = out.mutable_unchecked<2>();
  for (size_t i = 0; i < body.speeds->size(); ++i) {
    const auto& modes = (*body.speeds)[i].modes;
    for (size_t j = 0; j < body.modes.size(); ++j) {
      const auto it = modes.find(body.modes[j].label);
      a(i, j) = it == modes.end() ? std::nan("") : value(it->second);
    }
  }
  return out;
}

void BindPredict(py::module_& m) {
  using H = Held<PredictReport>;
  BindResult<PredictReport>(m, "PredictResult",
                            "What ringid.predict returns: the predict report of the command line.")
      .def_property_readonly("frequencies", [](const H& h) { return AtSpeeds(h.report.body, 0); },
                             "Each mode's damped frequency in Hz (numpy), as modes; with speeds= "
                             "(other than standing alone), a row per speed of speeds_m_s.")
      .def_property_readonly("labels", [](const H& h) {
        std::vector<std::string> labels;
        for (const PredictedMode& mode : h.report.body.modes) labels.push_back(ToString(mode.label));
        return labels;
      }, "Each mode's label, as modes: the columns of frequencies and damping_ratios.")
      .def_property_readonly("damping_ratios", [](const H& h) { return AtSpeeds(h.report.body, 1); },
                             "Each mode's damping ratio (numpy), as modes; with speeds=, a row "
                             "per speed of speeds_m_s.")
      .def_property_readonly("speeds_m_s", [](const H& h) {
        std::vector<double> v;
        for (const SpeedModes& at : h.report.body.speeds.value_or(std::vector<SpeedModes>{})) {
          v.push_back(at.speed_m_s);
        }
        return py::array_t<double>(v.size(), v.data());
      }, "The speeds of the rows of frequencies and damping_ratios, ascending (numpy; empty "
         "standing alone).")
      .def_property_readonly("dofs", [](const H& h) {
        std::vector<std::string> names;
        for (const std::string& name : NamesOf<Dof>()) names.push_back(name);
        return names;
      }, "The degrees of freedom, the columns of shapes.")
      .def_property_readonly("shapes", [](const H& h) {
        const auto names = NamesOf<Dof>();
        py::array_t<std::complex<double>> s({h.report.body.modes.size(), names.size()});
        auto a = s.mutable_unchecked<2>();
        for (size_t i = 0; i < h.report.body.modes.size(); ++i) {
          for (size_t j = 0; j < names.size(); ++j) {
            const auto& shape = h.report.body.modes[i].shape;
            const auto it = shape.find(*FromString<Dof>(names[j]));
            a(i, j) = it == shape.end() ? std::complex<double>() : it->second;
          }
        }
        return s;
      }, "The complex mode shapes (numpy, modes x dofs; 0 where a mode has no component).");
}

void BindInputs(py::module_& m) {
  py::class_<LoadedDataset, std::shared_ptr<LoadedDataset>>(
      m, "Dataset", "A modal dataset as ringid reads it (ringid.load_dataset).")
      .def_property_readonly("name", [](const LoadedDataset& d) { return d.dataset.name; },
                             "The dataset's name (its reports say it).")
      .def_property_readonly("description", [](const LoadedDataset& d) { return d.dataset.description; },
                             "What the dataset says it is.")
      .def_property_readonly("source", &LoadedDataset::Name, "The file it came from, or <dict>.")
      .def("to_dict", [](const LoadedDataset& d) { return JsonLoads(DatasetToJson(d.dataset)); },
           "The dataset as ringid writes it (the format it was read in, checked).")
      .def("__repr__", [](const LoadedDataset& d) {
        return "<ringid.Dataset '" + d.dataset.name + "' from " + d.Name() + ">";
      });
  py::class_<LoadedParameters, std::shared_ptr<LoadedParameters>>(
      m, "ParameterSet", "A parameter set (ringid-parameters/1, an identify report or a .tir).")
      .def(py::init([](const std::map<std::string, double>& values) {
        auto p = std::make_shared<LoadedParameters>();
        for (const auto& [name, v] : values) {
          const auto q = ParseParam(name);
          if (!q) throw Error::Usage("parameters: " + UnknownName("parameter", name, NamesOf<Param>()));
          const std::string problem = std::isfinite(v) ? ParameterValueProblem(*q, v) : "not finite";
          if (!problem.empty()) throw Error::Usage("parameters: " + name + ": " + problem);
          p->values[*q] = v;
        }
        return p;
      }), py::arg("values"), "ParameterSet(values): the values {NAME: VALUE} in SI units, checked as a file's.")
      .def_property_readonly("values", [](const LoadedParameters& p) {
        py::dict out;
        for (const std::string& name : NamesOf<Param>()) {
          const Param q = *ParseParam(name);
          if (p.values.IsSet(q)) out[name.c_str()] = p.values[q];
        }
        return out;
      }, "The values set, by parameter name (SI units, docs/conventions.md).")
      .def_property_readonly("notes", [](const LoadedParameters& p) { return p.notes; },
                             "Where a .tir's values came from.")
      .def_property_readonly("source", &LoadedParameters::Name, "The file it came from, or <dict>.")
      .def("__getitem__", [](const LoadedParameters& p, const std::string& name) {
        const auto q = ParseParam(name);
        if (!q || !p.values.IsSet(*q)) throw py::key_error(name);
        return p.values[*q];
      })
      .def("__repr__", [](const LoadedParameters& p) { return "<ringid.ParameterSet from " + p.Name() + ">"; });
  py::class_<LoadedResponses, std::shared_ptr<LoadedResponses>>(
      m, "ResponseDataset", "The axle's response at the lug orders (ringid-lug-response/1).")
      .def_property_readonly("name", [](const LoadedResponses& d) { return d.data.name; },
                             "The response dataset's name.")
      .def_property_readonly("source", &LoadedResponses::Name, "The file it came from, or <dict>.")
      .def("to_dict", [](const LoadedResponses& d) { return JsonLoads(ResponseDatasetToJson(d.data)); },
           "The response dataset as ringid writes it.");
}

}  // namespace
}  // namespace ringid::python

PYBIND11_MODULE(ringid, m) {
  using namespace ringid;          // NOLINT
  using namespace ringid::python;  // NOLINT
  m.doc() =
      "ringid: rigid-ring tire parameters from modal data, in-process.\n\n"
      "The operations of the command line `ringid` on the same inputs, with its flags as "
      "keyword arguments (same names, defaults and checks: one list of each operation's "
      "options serves both); each result's to_dict() is the JSON report "
      "`ringid COMMAND --output=...` writes. Bad input raises ringid.Error (a ValueError) with "
      "the line the command line prints.";
  m.attr("__version__") = RINGID_VERSION;
  FLAGS_minloglevel = 3;  // as the command line: failed evaluations are in the report
  RegisterError(m);
  BindInputs(m);
  BindIdentify(m);
  BindPredict(m);
  BindResult<IdentifiabilityReport>(m, "IdentifiabilityResult",
                                    "What ringid.identifiability returns: its report.")
      .def_property_readonly("singular_values", [](const Held<IdentifiabilityReport>& h) {
        return h.report.body.result.singular_values;
      }, "The Jacobian's singular values, descending (numpy).")
      .def_property_readonly("correlation", [](const Held<IdentifiabilityReport>& h) {
        return h.report.body.result.correlation;
      }, "The coordinates' correlation matrix (numpy; empty without a covariance).");
  BindResult<CompareReport>(m, "CompareResult", "What ringid.compare returns: its report.");
  BindResult<DiagnoseReport>(m, "DiagnoseResult", "What ringid.diagnose returns: its report.");
  BindResult<ForcesReport>(m, "ForcesResult", "What ringid.forces returns: its report.");
  BindSimulate(m);
  BindOperations(m);
  BindProblem(m);
}
