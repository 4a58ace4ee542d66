// The Python module `ringid` (issue 25): the command line's operations
// in-process, on its typed inputs and reports. Keyword arguments are the
// flags of apps/flags.cc, with their defaults and descriptions; errors are
// ringid.Error with the command line's one line.
#include <cmath>
#include <csignal>
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

#include "apps/flags.h"
#include "apps/forces_command.h"
#include "apps/predict_command.h"
#include "apps/reports.h"
#include "apps/simulate_command.h"
#include "estimation/compare.h"
#include "estimation/diagnose.h"
#include "estimation/identifiability.h"
#include "estimation/identify.h"
#include "estimation/interrupt.h"
#include "python/convert.h"
#include "python/problem.h"
#include "python/results.h"

namespace ringid::python {
namespace {

using IdentifyHeld = Held<IdentifyReport>;

// While alive in the main thread: Ctrl-C stops the fits (estimation/
// interrupt.h) in place of Python's handler, which cannot run without the
// GIL; Raise() then raises KeyboardInterrupt. Signals that came otherwise
// raise as Python says.
class Interruptible {
 public:
  Interruptible() : installed_(InMainThread()) {
    if (!installed_) return;
    ClearInterrupt();
    struct sigaction on_int = {};
    on_int.sa_handler = [](int) { RequestInterrupt(); };
    sigemptyset(&on_int.sa_mask);
    sigaction(SIGINT, &on_int, &previous_);
  }
  ~Interruptible() {
    if (installed_) sigaction(SIGINT, &previous_, nullptr);
  }
  Interruptible(const Interruptible&) = delete;
  Interruptible& operator=(const Interruptible&) = delete;
  void Raise() const {
    if (installed_ && InterruptRequested()) {
      ClearInterrupt();
      PyErr_SetNone(PyExc_KeyboardInterrupt);
      throw py::error_already_set();
    }
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  }
  static bool InMainThread() {
    const py::module_ threading = py::module_::import("threading");
    return threading.attr("current_thread")().is(threading.attr("main_thread")());
  }

 private:
  bool installed_;
  struct sigaction previous_ = {};
};

std::shared_ptr<const LoadedDataset> DatasetArg(py::handle dataset) {
  if (py::isinstance<LoadedDataset>(dataset)) return dataset.cast<std::shared_ptr<LoadedDataset>>();
  return LoadDatasetFrom(dataset);
}

// What a fitting command reads from its flags, read and the flags restored
// under the GIL (another thread's call may set them while a fit runs): the
// options, the dataset with --fix applied, --level, and the provenance.
struct FitInputs {
  IdentifyOptions options;
  std::vector<const Effect*> effects;
  Dataset dataset;
  std::string source;
  double level = 0;
  Provenance provenance;
};
FitInputs ReadFit(const char* command, const std::vector<std::string>& extra, py::handle dataset,
                  const py::kwargs& kw) {
  const auto loaded = DatasetArg(dataset);
  FlagScope scope(command, Without(Joined(FitFlags(), extra), {"dataset", "output"}), kw);
  FitInputs in;
  in.source = loaded->Name();
  FLAGS_dataset = in.source;
  std::string error;
  if (!ReadFitOptions(&in.options, &in.effects, &error)) throw Error::Usage(error);
  in.dataset = loaded->dataset;
  if (!ApplyFix(&in.dataset, &error)) throw Error::Usage(error);
  in.level = FLAGS_level;
  FLAGS_dataset = loaded->source;  // the provenance's input: none for a dict
  in.provenance = scope.Run(FLAGS_seed);
  return in;
}

// Runs `analyze` on the model and dataset without the GIL; the report of
// type R around its result, or Error on invalid input.
template <class R, class Analyze>
std::shared_ptr<Held<R>> RunFit(const FitInputs& in, const Analyze& analyze) {
  auto held = std::make_shared<Held<R>>();
  auto& r = held->report.body.result;
  const Interruptible interruptible;
  {
    py::gil_scoped_release release;
    const RigidRingModel model(in.effects);
    analyze(model, &r);
  }
  interruptible.Raise();
  if (r.status.invalid_input()) {
    throw Error{in.source + ": " + r.status.message, in.source, "", r.status.message};
  }
  held->report.provenance = in.provenance;
  held->report.body.dataset = in.dataset.name;
  return held;
}

std::shared_ptr<IdentifyHeld> IdentifyPy(py::handle dataset, const py::kwargs& kw) {
  const FitInputs in = ReadFit("identify", {}, dataset, kw);
  return RunFit<IdentifyReport>(in, [&](const RigidRingModel& model, IdentifyResult* r) {
    Identify(model, in.dataset, in.options, r);
  });
}

std::shared_ptr<Held<IdentifiabilityReport>> IdentifiabilityPy(py::handle dataset,
                                                               const py::kwargs& kw) {
  const FitInputs in = ReadFit("identifiability", {}, dataset, kw);
  IdentifiabilityOptions o;
  o.fit = in.options;
  return RunFit<IdentifiabilityReport>(in, [&](const RigidRingModel& model, IdentifiabilityResult* r) {
    AnalyzeIdentifiability(model, in.dataset, o, r);
  });
}

std::shared_ptr<Held<CompareReport>> ComparePy(py::handle dataset, const py::kwargs& kw) {
  const FitInputs in = ReadFit("compare", {}, dataset, kw);
  CompareOptions o;
  o.fit = in.options;
  return RunFit<CompareReport>(in, [&](const RigidRingModel& model, ComparisonResult* r) {
    CompareMethods(model, in.dataset, o, r);
  });
}

std::shared_ptr<Held<DiagnoseReport>> DiagnosePy(py::handle dataset, const py::kwargs& kw) {
  const FitInputs in = ReadFit("diagnose", {"level"}, dataset, kw);
  if (!(in.level > 0 && in.level < 1)) throw Error::Usage("--level: must lie in (0, 1)");
  DiagnoseOptions o;
  o.fit = in.options;
  o.effect_significance = in.level;
  return RunFit<DiagnoseReport>(in, [&](const RigidRingModel& baseline, DiagnosisResult* r) {
    Diagnose(baseline, in.dataset, o, r);
  });
}

std::vector<const Effect*> EffectsOfFlags() {
  std::vector<const Effect*> effects;
  std::string error;
  if (!ParseEffects(&effects, &error)) throw Error::Usage(error);
  return effects;
}

std::map<Param, double> SetOfFlags() {
  std::map<Param, double> set;
  std::string error;
  if (!ParseSet(&set, &error)) throw Error::Usage(error);
  return set;
}

std::shared_ptr<Held<PredictReport>> PredictPy(py::handle parameters, py::handle dataset,
                                               const py::kwargs& kw) {
  FlagScope scope("predict", Without(PredictFlags(), {"parameters", "dataset", "output"}), kw);
  const std::vector<const Effect*> effects = EffectsOfFlags();
  if (parameters.is_none() == dataset.is_none()) {
    throw Error::Usage("predict needs exactly one of parameters= or dataset=");
  }
  const std::map<Param, double> set = SetOfFlags();
  std::shared_ptr<const LoadedParameters> p;
  std::shared_ptr<const LoadedDataset> d;
  if (!parameters.is_none()) {
    if (py::isinstance<LoadedParameters>(parameters)) {  // loaded before: --set over it
      auto over = std::make_shared<LoadedParameters>(*parameters.cast<std::shared_ptr<LoadedParameters>>());
      for (const auto& [q, v] : set) over->values[q] = v;
      p = over;
    } else {
      p = LoadParametersFrom(parameters, set);
    }
    FLAGS_parameters = p->source;
  } else {
    d = DatasetArg(dataset);
    FLAGS_dataset = d->source;
  }
  auto held = std::make_shared<Held<PredictReport>>();
  std::string solve_error, error;
  if (!PredictBodyOf(p ? p->values : Parameters{}, d ? &d->dataset : nullptr, set, effects,
                     p ? p->Name() : d->Name(), p ? p->notes : std::vector<std::string>{},
                     &held->report.body, &solve_error, &error)) {
    throw Error::Usage(error);
  }
  held->report.provenance = scope.Run(std::nullopt);
  return held;
}

std::shared_ptr<Held<ForcesReport>> ForcesPy(py::handle parameters, py::handle dataset,
                                             const py::kwargs& kw) {
  // The flags are restored before the GIL is released (see ReadFit).
  std::optional<FlagScope> scope;
  scope.emplace("forces", Without(ForcesFlags(), {"parameters", "dataset", "output"}), kw);
  const std::vector<const Effect*> effects = EffectsOfFlags();
  ForceParameters fp;
  std::string source = "<identify result>";
  if (py::isinstance<IdentifyHeld>(parameters)) {
    const IdentifyResult& r = parameters.cast<std::shared_ptr<IdentifyHeld>>()->report.body.result;
    if (!r.status.ok()) {
      throw Error{source + ": status: the identification did not succeed", source, "status",
                  "the identification did not succeed; its values are no estimate"};
    }
    fp = ForceParameters::From(r);
  } else if (py::isinstance<LoadedParameters>(parameters)) {
    const auto p = parameters.cast<std::shared_ptr<LoadedParameters>>();
    source = p->Name();
    fp.shared = p->values;
    fp.source = kParameterSetForces;
  } else {
    const auto path = PathOf(parameters);
    if (!path) throw Error::Usage("forces: parameters= a path, an IdentifyResult or a ParameterSet");
    source = *path;
    LoadError load;
    if (!ReadForceParameters(*path, &fp, &load)) throw Error::Of(load);
    FLAGS_parameters = *path;
  }
  std::shared_ptr<const LoadedResponses> data =
      py::isinstance<LoadedResponses>(dataset) ? dataset.cast<std::shared_ptr<LoadedResponses>>()
                                               : LoadResponsesFrom(dataset);
  FLAGS_dataset = data->source;
  auto held = std::make_shared<Held<ForcesReport>>();
  held->report.provenance = scope->Run(std::nullopt);
  scope.reset();
  std::string error;
  bool ok;
  const Interruptible interruptible;
  {
    py::gil_scoped_release release;
    ok = ForcesOf(fp, data->data, effects, source, data->Name(), &held->report.body.result, &error);
  }
  interruptible.Raise();
  if (!ok) throw Error::Usage(error);
  held->report.body.dataset = data->data.name;
  return held;
}

// simulate's result: the dataset and truth the command line would write.
struct SimulateHeld {
  Simulated simulated;
  std::string output, truth;  // the files they would be written to
};

std::shared_ptr<SimulateHeld> SimulatePy(py::handle parameters, const py::kwargs& kw) {
  FlagScope scope("simulate", Without(SimulateFlags(), {"parameters", "lug_forces", "response_noise"}), kw);
  std::optional<std::string> path = PathOf(parameters);
  if (py::isinstance<LoadedParameters>(parameters)) {
    path = parameters.cast<std::shared_ptr<LoadedParameters>>()->source;
  }
  if (!path || path->empty()) {
    throw Error::Usage("simulate: parameters= a parameter set's path (or a ParameterSet read from one)");
  }
  FLAGS_parameters = *path;
  if (FLAGS_output.empty()) FLAGS_output = "simulated.json";
  if (FLAGS_truth.empty()) FLAGS_truth = "simulated_truth.json";
  auto held = std::make_shared<SimulateHeld>();
  held->output = FLAGS_output;
  held->truth = FLAGS_truth;
  std::string error;
  bool failed = false;
  if (!SimulateFromFlags(false, &held->simulated, &error, &failed)) {
    throw Error::Usage(failed ? "simulate: " + error : error);
  }
  return held;
}

void BindSimulate(py::module_& m) {
  py::class_<SimulateHeld, std::shared_ptr<SimulateHeld>>(
      m, "SimulateResult", "What ringid.simulate returns: the dataset and its truth, not written.")
      .def_property_readonly("dataset", [](const SimulateHeld& h) {
        auto d = std::make_shared<LoadedDataset>();
        d->dataset = h.simulated.dataset;
        return d;
      }, "The simulated dataset, a ringid.Dataset for identify and the others.")
      .def_property_readonly("truth", [](const SimulateHeld& h) { return JsonLoads(TruthText(h.simulated.truth)); },
                             "The truth file's content (every value the simulation used), a dict.")
      .def("to_dict", [](const SimulateHeld& h) {
        py::dict out;
        out["dataset"] = JsonLoads(DatasetToJson(h.simulated.dataset));
        out["truth"] = JsonLoads(TruthText(h.simulated.truth));
        return out;
      }, "{'dataset': the dataset file's JSON, 'truth': the truth file's}, as `ringid simulate` writes them.")
      .def("write", [](const SimulateHeld& h) {
        std::string error;
        if (!WriteFilesAtomically({{h.output, DatasetToJson(h.simulated.dataset)},
                                   {h.truth, TruthText(h.simulated.truth)}}, &error)) {
          throw Error::Usage(error);
        }
      }, "Writes the dataset to output= and the truth to truth=, both or neither.");
}

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

void BindPredict(py::module_& m) {
  using H = Held<PredictReport>;
  BindResult<PredictReport>(m, "PredictResult",
                            "What ringid.predict returns: the predict report of the command line.")
      .def_property_readonly("frequencies", [](const H& h) {
        std::vector<double> f;
        for (const PredictedMode& mode : h.report.body.modes) f.push_back(mode.model_hz);
        return py::array_t<double>(f.size(), f.data());
      }, "Each mode's damped frequency in Hz (numpy), as modes.")
      .def_property_readonly("labels", [](const H& h) {
        std::vector<std::string> labels;
        for (const PredictedMode& mode : h.report.body.modes) labels.push_back(ToString(mode.label));
        return labels;
      }, "Each mode's label, as modes.")
      .def_property_readonly("damping_ratios", [](const H& h) {
        std::vector<double> z;
        for (const PredictedMode& mode : h.report.body.modes) z.push_back(mode.damping_ratio);
        return py::array_t<double>(z.size(), z.data());
      }, "Each mode's damping ratio (numpy), as modes.")
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

std::string Doc(const std::string& signature, const std::string& what,
                const std::vector<std::string>& flags) {
  return signature + "\n\n" + what + "\n\nKeyword arguments (the command line's flags):\n" +
         FlagsDoc(flags);
}

void BindOperations(py::module_& m) {
  const std::vector<std::string> fit = Without(FitFlags(), {"dataset", "output"});
  const std::string dataset_arg =
      "dataset: a path, a dict (the file's JSON) or a ringid.Dataset; raises ringid.Error on "
      "bad input, as `ringid` exits 2.";
  m.def("load_dataset", &LoadDatasetFrom, py::arg("source"),
        "load_dataset(source) -> Dataset\n\nA modal dataset from a path or a dict, checked as "
        "the command line checks --dataset; ringid.Error names the file and field.");
  m.def("load_parameters", [](py::handle source, py::object set) {
    FlagScope scope("load_parameters", {"set"}, set.is_none() ? py::kwargs() : py::kwargs(py::dict(py::arg("set") = set)));
    return LoadParametersFrom(source, SetOfFlags());
  }, py::arg("source"), py::arg("set") = py::none(),
        "load_parameters(source, set=None) -> ParameterSet\n\nA parameter set from a path "
        "(ringid-parameters/1, an identify report or a .tir) or a dict, with set={NAME: VALUE} "
        "(or 'NAME=VALUE,...') over it, as --parameters and --set.");
  m.def("load_responses", &LoadResponsesFrom, py::arg("source"),
        "load_responses(source) -> ResponseDataset\n\nA response dataset "
        "(ringid-lug-response/1) from a path or a dict, for ringid.forces.");
  m.def("identify", &IdentifyPy, py::arg("dataset"),
        Doc("identify(dataset, **options) -> IdentifyResult",
            "Fits the parameters to a dataset, with covariance and identifiability: "
            "`ringid identify`. " + dataset_arg, fit).c_str());
  m.def("identifiability", &IdentifiabilityPy, py::arg("dataset"),
        Doc("identifiability(dataset, **options) -> IdentifiabilityResult",
            "What the data determine at the fitted point: `ringid identifiability`. " + dataset_arg,
            fit).c_str());
  m.def("compare", &ComparePy, py::arg("dataset"),
        Doc("compare(dataset, **options) -> CompareResult",
            "Levenberg-Marquardt and the Downhill Simplex from the same starts: `ringid compare`. " +
                dataset_arg, fit).c_str());
  m.def("diagnose", &DiagnosePy, py::arg("dataset"),
        Doc("diagnose(dataset, **options) -> DiagnoseResult",
            "The gap between the baseline and the data, and the effect that explains it: "
            "`ringid diagnose`. " + dataset_arg, Joined(fit, {"level"})).c_str());
  m.def("predict", &PredictPy, py::arg("parameters") = py::none(), py::arg("dataset") = py::none(),
        Doc("predict(parameters=None, dataset=None, **options) -> PredictResult",
            "The modes of a parameter set (path, dict or ParameterSet) or of a dataset's initial "
            "values, standing and at speeds: `ringid predict`.",
            Without(PredictFlags(), {"parameters", "dataset", "output"})).c_str());
  m.def("simulate", &SimulatePy, py::arg("parameters"),
        Doc("simulate(parameters, **options) -> SimulateResult",
            "A dataset measured from a parameter set (its path), optionally with effects: "
            "`ringid simulate`. output= and truth= name the files it describes and write() "
            "writes (simulated.json and simulated_truth.json when not given).",
            Without(SimulateFlags(), {"parameters", "lug_forces", "response_noise"})).c_str());
  m.def("forces", &ForcesPy, py::arg("parameters"), py::arg("dataset"),
        Doc("forces(parameters, dataset, **options) -> ForcesResult",
            "The lug forces from the axle's response: `ringid forces`. parameters: an identify "
            "report's or parameter set's path, an IdentifyResult or a ParameterSet; dataset: a "
            "response dataset (path, dict or ResponseDataset).",
            Without(ForcesFlags(), {"parameters", "dataset", "output"})).c_str());
}

}  // namespace
}  // namespace ringid::python

PYBIND11_MODULE(ringid, m) {
  using namespace ringid;          // NOLINT
  using namespace ringid::python;  // NOLINT
  m.doc() =
      "ringid: rigid-ring tire parameters from modal data, in-process.\n\n"
      "The operations of the command line `ringid` on the same inputs, with its flags as "
      "keyword arguments (same names and defaults); each result's to_dict() is the JSON report "
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
