// The operations of the module: keyword arguments read into the typed
// options of operations/options.h (python/convert.h), the library's
// operations run on them, and their reports held as results.
#include "python/operations.h"

#include <csignal>
#include <map>
#include <optional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/stl.h>

#include "estimation/compare.h"
#include "estimation/diagnose.h"
#include "estimation/identifiability.h"
#include "estimation/identify.h"
#include "estimation/interrupt.h"
#include "operations/extract.h"
#include "operations/poles.h"
#include "operations/files.h"
#include "operations/fit.h"
#include "operations/forces.h"
#include "operations/predict.h"
#include "python/convert.h"
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

// The library's options of a fitting operation, as the command line makes
// them for one dataset.
bool LibraryOptions(const FitSettings& s, IdentifyOptions* o, std::string* error) {
  return FitOptionsOf(s, 1, o, error);
}
bool LibraryOptions(const DiagnoseSettings& s, DiagnoseOptions* o, std::string* error) {
  return DiagnoseOptionsOf(s, 1, o, error);
}
bool LibraryOptions(const IdentifiabilitySettings& s, IdentifiabilityOptions* o,
                    std::string* error) {
  return IdentifiabilityOptionsOf(s, 1, o, error);
}
const FitSettings& FitOf(const FitSettings& s) { return s; }
const FitSettings& FitOf(const DiagnoseSettings& s) { return s.fit; }
const FitSettings& FitOf(const IdentifiabilitySettings& s) { return s.fit; }

// What a fitting operation reads: its settings (S) and the library's options
// (O) from them, the dataset with fix applied, and the provenance.
template <class S, class O>
struct FitInputs {
  S settings;
  O options;
  Dataset dataset;
  std::string source;
  Provenance provenance;
};
template <class S, class O>
FitInputs<S, O> ReadFit(const char* command, py::handle dataset, const py::kwargs& kw) {
  FitInputs<S, O> in;
  std::vector<std::string> argv;
  in.settings = ReadOptions<S>(command, kw, &argv);
  std::string error;
  if (!LibraryOptions(in.settings, &in.options, &error)) throw Error::Usage(error);
  const auto loaded = DatasetArg(dataset);
  in.source = loaded->Name();
  in.dataset = loaded->dataset;
  const FitSettings& fit = FitOf(in.settings);
  if (!ApplyFix(fit.fix, &in.dataset, &error)) throw Error::Usage(error);
  in.provenance = RunOf(argv, {{"dataset", loaded->source}}, fit.seed, fit.derivatives);
  return in;
}

// Runs `analyze` on the model and dataset without the GIL; the report of
// type R around its result, or Error on invalid input.
template <class R, class S, class O, class Analyze>
std::shared_ptr<Held<R>> RunFit(const FitInputs<S, O>& in, const Analyze& analyze) {
  auto held = std::make_shared<Held<R>>();
  auto& r = held->report.body.result;
  const Interruptible interruptible;
  {
    py::gil_scoped_release release;
    const RigidRingModel model(FitOf(in.settings).effects);
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
  const auto in = ReadFit<FitSettings, IdentifyOptions>("identify", dataset, kw);
  return RunFit<IdentifyReport>(in, [&](const RigidRingModel& model, IdentifyResult* r) {
    Identify(model, in.dataset, in.options, r);
  });
}

std::shared_ptr<Held<IdentifiabilityReport>> IdentifiabilityPy(py::handle dataset,
                                                               const py::kwargs& kw) {
  const auto in =
      ReadFit<IdentifiabilitySettings, IdentifiabilityOptions>("identifiability", dataset, kw);
  return RunFit<IdentifiabilityReport>(in, [&](const RigidRingModel& model, IdentifiabilityResult* r) {
    AnalyzeIdentifiability(model, in.dataset, in.options, r);
  });
}

std::shared_ptr<Held<CompareReport>> ComparePy(py::handle dataset, const py::kwargs& kw) {
  const auto in = ReadFit<FitSettings, IdentifyOptions>("compare", dataset, kw);
  CompareOptions o;
  o.fit = in.options;
  return RunFit<CompareReport>(in, [&](const RigidRingModel& model, ComparisonResult* r) {
    CompareMethods(model, in.dataset, o, r);
  });
}

std::shared_ptr<Held<DiagnoseReport>> DiagnosePy(py::handle dataset, const py::kwargs& kw) {
  const auto in = ReadFit<DiagnoseSettings, DiagnoseOptions>("diagnose", dataset, kw);
  return RunFit<DiagnoseReport>(in, [&](const RigidRingModel& baseline, DiagnosisResult* r) {
    Diagnose(baseline, in.dataset, in.options, r);
  });
}

std::shared_ptr<Held<PredictReport>> PredictPy(py::handle parameters, py::handle dataset,
                                               const py::kwargs& kw) {
  std::vector<std::string> argv;
  const PredictSettings s = ReadOptions<PredictSettings>("predict", kw, &argv);
  if (parameters.is_none() == dataset.is_none()) {
    throw Error::Usage("predict needs exactly one of parameters= or dataset=");
  }
  std::shared_ptr<const LoadedParameters> p;
  std::shared_ptr<const LoadedDataset> d;
  if (!parameters.is_none()) {
    if (py::isinstance<LoadedParameters>(parameters)) {  // loaded before: set over it
      auto over = std::make_shared<LoadedParameters>(*parameters.cast<std::shared_ptr<LoadedParameters>>());
      for (const auto& [q, v] : s.set) over->values[q] = v;
      p = over;
    } else {
      p = LoadParametersFrom(parameters, s.set);
    }
  } else {
    d = DatasetArg(dataset);
  }
  auto held = std::make_shared<Held<PredictReport>>();
  std::string solve_error;
  InputError error;
  if (!PredictBodyOf(p ? p->values : Parameters{}, d ? &d->dataset : nullptr, s,
                     p ? p->Name() : d->Name(), p ? p->notes : std::vector<std::string>{},
                     &held->report.body, &solve_error, &error)) {
    throw Error::Of(error);
  }
  held->report.provenance =
      RunOf(argv, {{"dataset", d ? d->source : ""}, {"parameters", p ? p->source : ""}},
            std::nullopt);
  return held;
}

// forces' parameters: a fit held, a parameter set held or a file's path,
// s.set over them; `path` the file's.
ForceParameters ForceParametersOf(py::handle parameters, const ForcesSettings& s,
                                  std::string* source, std::string* path) {
  ForceParameters fp;
  *source = "<identify result>";
  if (py::isinstance<IdentifyHeld>(parameters)) {
    const IdentifyResult& r = parameters.cast<std::shared_ptr<IdentifyHeld>>()->report.body.result;
    if (!r.status.ok()) {
      throw Error{*source + ": status: the identification did not succeed", *source, "status",
                  "the identification did not succeed; its values are no estimate"};
    }
    InputError bad;
    if (!NoSetOverFit(s.set, *source, &bad)) throw Error::Of(bad);
    fp = ForceParameters::From(r);
  } else if (py::isinstance<LoadedParameters>(parameters)) {
    const auto p = parameters.cast<std::shared_ptr<LoadedParameters>>();
    *source = p->Name();
    fp.shared = p->values;
    for (const auto& [q, v] : s.set) fp.shared[q] = v;
    fp.source = kParameterSetForces;
  } else {
    const auto file = PathOf(parameters);
    if (!file) throw Error::Usage("forces: parameters= a path, an IdentifyResult or a ParameterSet");
    *source = *path = *file;
    InputError bad;
    if (!ReadForceParameters(*file, s.set, &fp, &bad)) throw Error::Of(bad);
  }
  return fp;
}

std::shared_ptr<Held<ForcesReport>> ForcesPy(py::handle parameters, py::handle dataset,
                                             const py::kwargs& kw) {
  std::vector<std::string> argv;
  const ForcesSettings s = ReadOptions<ForcesSettings>("forces", kw, &argv);
  std::string source, path;
  const ForceParameters fp = ForceParametersOf(parameters, s, &source, &path);
  std::shared_ptr<const LoadedResponses> data =
      py::isinstance<LoadedResponses>(dataset) ? dataset.cast<std::shared_ptr<LoadedResponses>>()
                                               : LoadResponsesFrom(dataset);
  auto held = std::make_shared<Held<ForcesReport>>();
  held->report.provenance =
      RunOf(argv, {{"dataset", data->source}, {"parameters", path}}, std::nullopt);
  InputError error;
  bool ok;
  const Interruptible interruptible;
  {
    py::gil_scoped_release release;
    ok = ForcesOf(fp, data->data, s, source, data->Name(), &held->report.body.result, &error);
  }
  interruptible.Raise();
  if (!ok) throw Error::Of(error);
  held->report.body.dataset = data->data.name;
  return held;
}

// A file's name given as output= or truth=, or `otherwise`.
std::string FileArg(const char* name, py::handle value, const std::string& otherwise) {
  if (value.is_none()) return otherwise;
  const auto path = PathOf(value);
  if (!path) throw Error::Usage(std::string(name) + ": a path (str or os.PathLike)");
  return *path;
}

std::shared_ptr<SimulateHeld> SimulatePy(py::handle parameters, py::handle output,
                                         py::handle truth, const py::kwargs& kw) {
  std::vector<std::string> argv;
  const SimulateSettings s = ReadOptions<SimulateSettings>("simulate", kw, &argv);
  std::optional<std::string> path = PathOf(parameters);
  if (py::isinstance<LoadedParameters>(parameters)) {
    path = parameters.cast<std::shared_ptr<LoadedParameters>>()->source;
  }
  if (!path || path->empty()) {
    throw Error::Usage("simulate: parameters= a parameter set's path (or a ParameterSet read from one)");
  }
  auto held = std::make_shared<SimulateHeld>();
  InputError error;
  if (!s.lug_forces.empty()) {
    if (!truth.is_none()) {
      throw Error::Usage("truth: the file of lug_forces is the truth of a response simulation");
    }
    held->output = FileArg("output", output, "simulated_response.json");
    LugForceSpectrum spectrum;
    held->response.emplace();
    if (!SimulateResponse(*path, s, &spectrum, &*held->response, &error)) throw Error::Of(error);
    return held;
  }
  held->output = FileArg("output", output, "simulated.json");
  held->truth = FileArg("truth", truth, "simulated_truth.json");
  bool failed = false;
  held->simulated.emplace();
  if (!SimulateDataset(*path, held->output, s, &*held->simulated, &error, &failed)) {
    throw failed ? Error::Usage("simulate: " + error.line) : Error::Of(error);
  }
  return held;
}

std::shared_ptr<ExtractResult> ExtractPy(py::handle dataset, py::handle parameters,
                                         const py::kwargs& kw) {
  std::vector<std::string> argv;
  const ExtractSettings s = ReadOptions<ExtractSettings>("extract", kw, &argv);
  const auto loaded = DatasetArg(dataset);
  std::optional<Parameters> guess;
  if (py::isinstance<LoadedParameters>(parameters)) {
    guess = parameters.cast<std::shared_ptr<LoadedParameters>>()->values;
  } else if (!parameters.is_none()) {
    guess = LoadParametersFrom(parameters, {})->values;
  }
  auto held = std::make_shared<ExtractResult>();
  InputError error;
  bool ok = false;
  {
    py::gil_scoped_release release;
    ok = ExtractDataset(loaded->dataset, loaded->Name(), s, held.get(), &error,
                        guess ? &*guess : nullptr);
  }
  if (!ok && !held->status.invalid_input()) throw Error::Usage("extract: " + error.line);
  if (!ok) throw Error::Of(error);
  return held;
}

// POLES.json of `ringid poles` as a dict.
py::object PolesPy(py::handle uff, py::handle dataset, py::handle map, const py::kwargs& kw) {
  std::vector<std::string> argv;
  const PolesSettings s = ReadOptions<PolesSettings>("poles", kw, &argv);
  const auto path = [](const char* name, py::handle value) {
    return value.is_none() ? std::string() : FileArg(name, value, "");
  };
  const PolesInputs in{path("uff", uff), path("map", map), path("dataset", dataset)};
  PolesRun run;
  InputError error;
  bool ok = false;
  {
    py::gil_scoped_release release;
    ok = FindFilePoles(in, s, &run, &error);
  }
  if (!ok && !run.body.status.ok() && !run.body.status.message.empty()) {
    throw Error::Usage("poles: " + error.line);
  }
  if (!ok) throw Error::Of(error);
  return JsonLoads(JsonWriter::ToJson(run.file).dump());
}

// "signature\n\nwhat\n\nKeyword arguments ...": the options of S.
template <class S>
std::string Doc(const std::string& signature, const std::string& what) {
  return signature + "\n\n" + what +
         "\n\nKeyword arguments (the command line's flags, operations/options.h):\n" +
         OptionsDoc(OptionsOf<S>());
}

}  // namespace

void BindSimulate(py::module_& m) {
  py::class_<SimulateHeld, std::shared_ptr<SimulateHeld>>(
      m, "SimulateResult",
      "What ringid.simulate returns: the dataset and its truth (with lug_forces: the response "
      "dataset), not written.")
      .def_property_readonly("dataset", [](const SimulateHeld& h) -> py::object {
        if (h.response) {
          auto r = std::make_shared<LoadedResponses>();
          r->data = *h.response;
          return py::cast(r);
        }
        auto d = std::make_shared<LoadedDataset>();
        d->dataset = h.simulated->dataset;
        return py::cast(d);
      }, "The simulated dataset, a ringid.Dataset for identify and the others (with "
         "lug_forces: a ringid.ResponseDataset for forces).")
      .def_property_readonly("truth", [](const SimulateHeld& h) -> py::object {
        if (h.response) return py::none();
        return JsonLoads(TruthText(h.simulated->truth));
      }, "The truth file's content (every value the simulation used), a dict; None with "
         "lug_forces, whose file is the truth.")
      .def("to_dict", [](const SimulateHeld& h) {
        py::dict out;
        if (h.response) {
          out["dataset"] = JsonLoads(ResponseDatasetToJson(*h.response));
          return out;
        }
        out["dataset"] = JsonLoads(DatasetToJson(h.simulated->dataset));
        out["truth"] = JsonLoads(TruthText(h.simulated->truth));
        return out;
      }, "{'dataset': the dataset file's JSON, 'truth': the truth file's}, as `ringid simulate` "
         "writes them (with lug_forces: {'dataset': the response dataset's}).")
      .def("write", [](const SimulateHeld& h) {
        std::string error;
        const bool ok =
            h.response ? WriteFileAtomically(h.output, ResponseDatasetToJson(*h.response), &error)
                       : WriteFilesAtomically({{h.output, DatasetToJson(h.simulated->dataset)},
                                               {h.truth, TruthText(h.simulated->truth)}},
                                              &error);
        if (!ok) throw Error::Usage(error);
      }, "Writes the dataset to output= and the truth to truth=, both or neither (with "
         "lug_forces: the response dataset to output=).");
}

void BindExtract(py::module_& m) {
  py::class_<ExtractResult, std::shared_ptr<ExtractResult>>(
      m, "ExtractResult", "What ringid.extract returns: the modal dataset and every pole found.")
      .def_property_readonly("dataset", [](const ExtractResult& x) {
        auto d = std::make_shared<LoadedDataset>();
        d->dataset = x.dataset;
        return d;
      }, "The modes as a ringid.Dataset, for identify and the others.")
      .def_property_readonly("poles", [](const ExtractResult& x) {
        return JsonLoads(JsonWriter::ToJson(x.poles).dump());  // the report's field list
      }, "Every physical pole of every condition: condition, frequency_hz, damping_ratio, their "
         "standard errors frequency_sigma_hz and damping_sigma (absent without), stable_orders, label "
         "(None where not kept) and shape (whether the outputs gave one).")
      .def_property_readonly("routes", [](const ExtractResult& x) {
        return JsonLoads(JsonWriter::ToJson(x.routes).dump());
      }, "The two routes side by side: per parameter both class identifiable, identify on the "
         "FRFs (direct, direct_std) and on the extracted modes (modal, modal_std), their "
         "difference in combined standard errors and the ratio of the errors.")
      .def_property_readonly("notes", [](const ExtractResult& x) { return x.notes; },
                             "What the dataset assumes (the masses made known, no sigma).");
}

void BindOperations(py::module_& m) {
  BindExtract(m);
  const std::string dataset_arg =
      "dataset: a path, a dict (the file's JSON) or a ringid.Dataset; raises ringid.Error on "
      "bad input, as `ringid` exits 2.";
  m.def("load_dataset", &LoadDatasetFrom, py::arg("source"),
        "load_dataset(source) -> Dataset\n\nA modal dataset from a path or a dict, checked as "
        "the command line checks --dataset; ringid.Error names the file and field.");
  m.def("load_parameters", [](py::handle source, py::object set) {
    ParameterValues values;
    std::string error;
    if (!set.is_none() && !OptionFromText("set", OptionTextOf("set", set), &values, &error)) {
      throw Error::Usage(error);
    }
    return LoadParametersFrom(source, values);
  }, py::arg("source"), py::arg("set") = py::none(),
        "load_parameters(source, set=None) -> ParameterSet\n\nA parameter set from a path "
        "(ringid-parameters/1, an identify report or a .tir) or a dict, with set={NAME: VALUE} "
        "(or 'NAME=VALUE,...') over it, as --parameters and --set.");
  m.def("load_responses", &LoadResponsesFrom, py::arg("source"),
        "load_responses(source) -> ResponseDataset\n\nA response dataset "
        "(ringid-lug-response/1) from a path or a dict, for ringid.forces.");
  m.def("identify", &IdentifyPy, py::arg("dataset"),
        Doc<FitSettings>("identify(dataset, **options) -> IdentifyResult",
                         "Fits the parameters to a dataset, with covariance and identifiability: "
                         "`ringid identify`. " + dataset_arg).c_str());
  m.def("identifiability", &IdentifiabilityPy, py::arg("dataset"),
        Doc<IdentifiabilitySettings>("identifiability(dataset, **options) -> IdentifiabilityResult",
                         "What the data determine at the fitted point: `ringid identifiability`. " +
                             dataset_arg).c_str());
  m.def("compare", &ComparePy, py::arg("dataset"),
        Doc<FitSettings>("compare(dataset, **options) -> CompareResult",
                         "Levenberg-Marquardt and the Downhill Simplex from the same starts: "
                         "`ringid compare`. " + dataset_arg).c_str());
  m.def("diagnose", &DiagnosePy, py::arg("dataset"),
        Doc<DiagnoseSettings>("diagnose(dataset, **options) -> DiagnoseResult",
                              "The gap between the baseline and the data, and the effect that "
                              "explains it: `ringid diagnose`. " + dataset_arg).c_str());
  m.def("predict", &PredictPy, py::arg("parameters") = py::none(), py::arg("dataset") = py::none(),
        Doc<PredictSettings>("predict(parameters=None, dataset=None, **options) -> PredictResult",
                             "The modes of a parameter set (path, dict or ParameterSet) or of a "
                             "dataset's initial values, standing and at speeds: `ringid predict`.")
            .c_str());
  m.def("simulate", &SimulatePy, py::arg("parameters"), py::kw_only(),
        py::arg("output") = py::none(), py::arg("truth") = py::none(),
        Doc<SimulateSettings>(
            "simulate(parameters, output=None, truth=None, **options) -> SimulateResult",
            "A dataset measured from a parameter set (its path), optionally with effects: "
            "`ringid simulate`. output= and truth= name the files it describes and write() "
            "writes (simulated.json and simulated_truth.json when not given). With lug_forces=, "
            "the axle's response to those lug forces at speeds= instead, a ResponseDataset "
            "(output= simulated_response.json when not given; no truth).").c_str());
  m.def("extract", &ExtractPy, py::arg("dataset"), py::kw_only(),
        py::arg("parameters") = py::none(),
        Doc<ExtractSettings>("extract(dataset, parameters=None, **options) -> ExtractResult",
                             "The modes in a dataset's FRFs as a modal dataset, labelled by fit "
                             "from its initial values (parameters=: a parameter set's path or "
                             "ParameterSet in their place, as --parameters), masses made known: "
                             "`ringid extract`. " + dataset_arg).c_str());
  m.def("poles", &PolesPy, py::kw_only(), py::arg("uff") = py::none(),
        py::arg("dataset") = py::none(), py::arg("map") = py::none(),
        Doc<PolesSettings>("poles(*, uff=None, dataset=None, map=None, **options) -> dict",
                           "The physical poles of a UFF file's (uff=, with map= for its units "
                           "and averages) or a format-3 dataset's (dataset=) FRFs, without a "
                           "tire model: POLES.json of `ringid poles` as a dict (format, source, "
                           "conditions, poles, notes). Paths; raises ringid.Error on bad input, "
                           "as `ringid` exits 2.").c_str());
  m.def("forces", &ForcesPy, py::arg("parameters"), py::arg("dataset"),
        Doc<ForcesSettings>(
            "forces(parameters, dataset, **options) -> ForcesResult",
            "The lug forces from the axle's response: `ringid forces`. parameters: an identify "
            "report's or parameter set's path (or a .tir's, set= giving what it lacks), an "
            "IdentifyResult or a ParameterSet; dataset: a response dataset (path, dict or "
            "ResponseDataset).").c_str());
}

}  // namespace ringid::python
