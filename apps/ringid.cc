// ringid: identify rigid-ring tire parameters from modal data.
// A thin layer: parse flags, load, call the library, print, write the report.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "apps/campaign.h"
#include "apps/command_line.h"
#include "apps/data_dir.h"
#include "apps/html_report.h"
#include "apps/interrupt.h"
#include "apps/progress.h"
#include "apps/help.h"
#include "apps/reports.h"
#include "apps/reference_doc.h"
#include "apps/schema_doc.h"
#include "report/report.h"
#include "validation/suites.h"
#include "datasets/dataset.h"
#include "datasets/synthetic.h"
#include "datasets/tir_parameters.h"
#include "estimation/compare.h"
#include "estimation/identifiability.h"
#include "estimation/identify.h"
#include "estimation/parallel.h"
#include "estimation/problem.h"
#include "model/effects.h"
#include "model/spelling.h"
#include "model/rigid_ring_model.h"

// Each flag's meaning, for every command that takes it; which commands take
// it is the table of commands in main(), and `ringid COMMAND --help` shows
// both. The values a named flag takes come from the library (apps/help.cc).
DEFINE_string(dataset, "", "modal dataset (docs/conventions.md §3); a campaign takes FILE,DIR,... (a directory stands for its *.json)");
DEFINE_string(parameters, "", "parameter set (ringid-parameters/1, or an identify report); predict and export also read the rigid-ring part of an MF-Swift FILE.tir (docs/tir.md), the rest given by --set");
DEFINE_string(output, "", "write the JSON report here (simulate: the dataset; report: the HTML page; export: the file, else to standard output)");
DEFINE_string(save_parameters, "", "also write the fitted parameter set (ringid-parameters/1) here");
DEFINE_string(method, ringid::ToString(ringid::IdentifyOptions().method), "how to fit: Levenberg-Marquardt or the Downhill Simplex");
DEFINE_int32(starts, ringid::IdentifyOptions().starts, "number of starts: the dataset's initial point, the point matching the measured frequencies, and points scattered log-uniformly around that");
DEFINE_int32(seed, static_cast<int>(ringid::IdentifyOptions().seed),
             "seed of the random starts, and of the noise in simulate and bench");
DEFINE_string(weighting, ringid::ToString(ringid::ResidualOptions().frequency_weighting),
              "frequency residuals weighted by their sigma, or relative to the frequency (eqs. 19-20)");
DEFINE_double(relative_sigma, ringid::ResidualOptions().relative_sigma,
              "relative frequency sigma where the dataset gives none");
DEFINE_bool(shapes, ringid::ResidualOptions().use_shapes, "fit the measured mode shapes");
DEFINE_bool(damping, ringid::ResidualOptions().use_damping, "fit the measured damping ratios");
DEFINE_string(shape_convention, ringid::ToString(ringid::ResidualOptions().shape_convention),
              "how the measured real shapes were made: as the contract says, or as the paper's Tables 4-5");
DEFINE_string(derivatives, ringid::ToString(ringid::ResidualOptions().derivatives),
              "Jacobians by central differences (numeric) or from eigenvalue and eigenvector derivatives (analytic)");
DEFINE_string(truth, "", "write the truth (effects and every value) here");
DEFINE_string(set, "", "NAME=VALUE,...: parameter values to set over the file's, each in its parameter's domain; an effect's size among them");
DEFINE_double(frequency_noise, ringid::SimulateOptions().frequency_noise,
              "relative frequency noise (sd)");
DEFINE_double(damping_noise, ringid::SimulateOptions().damping_noise,
              "relative damping-ratio noise (sd)");
DEFINE_double(shape_noise, ringid::SimulateOptions().shape_noise,
              "shape component noise (sd, shapes scaled to 1)");
DEFINE_double(shift, 0, "size the one effect of --effects to shift some frequency by this fraction (e.g. 0.04)");
DEFINE_double(prior_spread, 0.1, "log-normal spread of the dataset's initial values around the truth");
DEFINE_string(speeds, "0", "V1,V2,...: speeds in m/s (>= 0), one condition each (0: standing, else drum_V)");
DEFINE_string(loads, "", "F1,F2,...: loads F_cz0 in N (> 0); the conditions are then speeds x loads");
DEFINE_string(suite, "", "the validation suite to run");
DEFINE_int32(replicates, ringid::SuiteOptions().replicates, "Monte Carlo replicates per tire (synthetic, rolling)");
DEFINE_string(markdown, "", "also write the Markdown table here");
DEFINE_string(output_dir, "", "run a campaign: one report per dataset and campaign.json in this directory (made if missing)");
DEFINE_int32(jobs, 1, "campaign: datasets analysed at once (threads)");
DEFINE_string(shard, "0/1", "campaign: I/N, analyse every N-th dataset from the I-th (0-based)");
DEFINE_string(input, "", "a JSON report of ringid");
DEFINE_string(figures_dir, "", "also write each figure as DIR/NAME.svg (the directory made if missing)");
DEFINE_string(bounds, "", "NAME:LO:HI,...: bounds in the parameter's units, in place of a factor 1000 around the start");
DEFINE_string(fix, "", "NAME,...: parameters held at their initial values");
DEFINE_string(effects, "", "EFFECT,...: effects of docs/conventions.md §4 to add to the model (diagnose: to its baseline; the others are tried on top)");
DEFINE_double(level, ringid::DiagnoseOptions().effect_significance,
              "significance level of each effect's likelihood-ratio test and of the verdict's group (the default is Bonferroni-safe for six candidates)");
DEFINE_int32(threads, 0, "starts (diagnose: and candidate effects) fitted at once; 0: the cores, shared among --jobs");
DEFINE_string(format, "", "what to write: the rigid-ring part of an MF-Swift .tir (docs/tir.md) or a parameter set (ringid-parameters/1 JSON)");

namespace ringid {

namespace {

int Usage(const std::string& line) {
  std::fprintf(stderr, "ringid: %s\n", line.c_str());
  return kExitUsage;
}

bool ParseEffects(std::vector<const Effect*>* effects, std::string* error) {
  std::stringstream list(FLAGS_effects);
  std::string name;
  while (std::getline(list, name, ',')) {
    if (name.empty()) continue;
    const Effect* e = FindEffect(name);
    if (!e) {
      *error = "--effects: " + UnknownName("effect", name, FlagValues("effects"));
      return false;
    }
    effects->push_back(e);
  }
  return true;
}

int Write(const std::string& path, const std::string& text) {
  std::string error;
  if (!WriteFileAtomically(path, text, &error)) {
    return Usage(error);
  }
  return kExitOk;
}

// The input files the flags name, as (flag, path): each goes into the
// provenance, and no output may overwrite one. A campaign names each report's
// own dataset file.
std::vector<std::pair<std::string, std::string>> Inputs(const std::string& dataset = FLAGS_dataset) {
  return {{"dataset", dataset}, {"parameters", FLAGS_parameters}, {"input", FLAGS_input}};
}

// This process's provenance, with the inputs its flags named.
Provenance ThisRun(int argc, char** argv, std::optional<long> seed,
                   const std::string& dataset = FLAGS_dataset) {
  Provenance p = MakeProvenance(argc, argv, Inputs(dataset), seed);
  // Checked by every command that fits before it runs.
  p.derivatives = FromString<Derivatives>(FLAGS_derivatives).value_or(Derivatives::kNumeric);
  return p;
}

// A number that is the whole of `text`.
bool ParseNumber(const std::string& text, double* v) {
  char* end = nullptr;
  *v = std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size() && std::isfinite(*v);
}

// --set=NAME=VALUE,...: each a parameter of the catalogue (the nearest named
// when it is not one) and a finite number in the parameter's domain
// (docs/conventions.md §1), the last of a name given twice winning. The one
// reading of --set for simulate, predict and export.
bool ParseSet(std::map<Param, double>* set, std::string* error) {
  std::stringstream list(FLAGS_set);
  for (std::string item; std::getline(list, item, ',');) {
    if (item.empty()) continue;
    const size_t eq = item.find('=');
    if (eq == std::string::npos) {
      *error = "--set: bad item '" + item + "' (NAME=VALUE)";
      return false;
    }
    const std::string name = item.substr(0, eq);
    const std::optional<Param> p = ParseParam(name);
    if (!p) {
      *error = "--set: " + UnknownName("parameter", name, NamesOf<Param>());
      return false;
    }
    const std::string text = item.substr(eq + 1);
    double v = 0;
    if (!ParseNumber(text, &v)) {
      *error = "--set: " + name + ": bad value '" + text + "' (a finite number)";
      return false;
    }
    const Domain d = Info(*p).domain;
    if ((d == Domain::kPositive && !(v > 0)) || (d == Domain::kNonNegative && v < 0)) {
      *error = "--set: " + name + ": bad value '" + text + "' (" +
               (d == Domain::kPositive ? "a positive number" : "a number not negative") + ")";
      return false;
    }
    const std::string problem = ParameterValueProblem(*p, v);
    if (!problem.empty()) {
      *error = "--set: " + name + ": bad value '" + text + "' (" + problem + ")";
      return false;
    }
    (*set)[*p] = v;
  }
  return true;
}

// The effect of the catalogue that `p` belongs to, or null for a parameter
// of the baseline.
const Effect* EffectOf(Param p) {
  for (const Effect* e : EffectCatalogue()) {
    const std::vector<Param> own = e->parameters();
    if (std::find(own.begin(), own.end(), p) != own.end()) return e;
  }
  return nullptr;
}

// The one line for the parameters the model needs and neither `source` (a
// parameter set, a dataset or a .tir) nor --set gives, `missing` in the
// model's order: the first named with where it could come from. An effect's
// parameter comes from --set (the file of a tire need not know the effect); a
// .tir's, from the key that would give it or, when a .tir cannot hold it,
// from --set, and the others missing are named too.
std::string MissingParameters(const std::string& source, const std::vector<Param>& missing) {
  const Param q = missing[0];
  const std::string name = ParamName(q);
  if (const Effect* e = EffectOf(q)) {
    return "--effects: " + std::string(e->name()) + " needs " + name + ": give --set=" + name +
           "=VALUE";
  }
  if (!IsTirPath(source)) return source + ": parameters." + name + ": missing (the model needs it)";
  const std::string key = TirKeyFor(q);
  std::string line = source + ": " + name + ": missing (the model needs it; " +
                     (key.empty() ? std::string("a .tir cannot hold it") : "the .tir has no " + key) +
                     "): give --set=" + name + "=VALUE";
  for (size_t i = 1; i < missing.size(); ++i) {
    line += (i == 1 ? "; also missing: " : ", ") + std::string(ParamName(missing[i]));
  }
  return line;
}

// The parameters of `model` that `p` does not set, in the model's order.
std::vector<Param> Missing(const RigidRingModel& model, const Parameters& p) {
  std::vector<Param> missing;
  for (Param q : model.parameters()) {
    if (!p.IsSet(q)) missing.push_back(q);
  }
  return missing;
}

int Predict(int argc, char** argv) {
  std::string error;
  std::vector<const Effect*> effects;
  if (!ParseEffects(&effects, &error)) return Usage(error);
  if (FLAGS_parameters.empty() == FLAGS_dataset.empty()) {
    return Usage("predict needs exactly one of --parameters=FILE or --dataset=FILE");
  }
  if (!CheckOutputs({{"output", FLAGS_output}}, Inputs(), &error)) return Usage(error);
  std::map<Param, double> set;
  if (!ParseSet(&set, &error)) return Usage(error);
  Parameters p;
  LoadError load;
  if (!FLAGS_parameters.empty()) {  // a .tir by its extension
    if (!LoadParameters(FLAGS_parameters, &p, &load)) return Usage(load.OneLine());
  } else {
    Dataset d;
    if (!LoadDataset(FLAGS_dataset, &d, &load)) return Usage(load.OneLine());
    p = InitialParameters(d);
  }
  for (const auto& [q, v] : set) p[q] = v;
  const RigidRingModel model(effects);
  const std::string& source = FLAGS_parameters.empty() ? FLAGS_dataset : FLAGS_parameters;
  const std::vector<Param> missing = Missing(model, p);
  if (!missing.empty()) return Usage(MissingParameters(source, missing));
  const ModalSolution s = model.Solve(p);
  if (!s.ok) {
    std::fprintf(stderr, "ringid: predict: %s\n", s.error.c_str());
  } else {
    std::printf("%-22s %-13s %10s %8s\n", "mode", "plane", "Hz", "zeta");
    for (const Mode& m : s.modes) {
      std::printf("%-22s %-13s %10.3f %8.4f\n", LabelName(m.label),
                  PlaneName(m.plane()), m.frequency_hz, m.damping_ratio);
    }
    for (ModeLabel l : s.vanished) {
      std::printf("%-22s overdamped: no oscillating mode\n", LabelName(l));
    }
  }
  if (!FLAGS_output.empty()) {
    const int rc =
        Write(FLAGS_output, ReportText(PredictReport{ThisRun(argc, argv, std::nullopt),
                                                     PredictBody::From(s)}));
    if (rc != kExitOk) return rc;
  }
  return s.ok ? kExitOk : kExitFailure;
}

// --bounds=NAME:LO:HI,...
bool ParseBounds(Bounds* bounds, std::string* error) {
  std::stringstream list(FLAGS_bounds);
  std::string item;
  while (std::getline(list, item, ',')) {
    if (item.empty()) continue;
    std::vector<std::string> part;
    std::stringstream fields(item);
    for (std::string f; std::getline(fields, f, ':');) part.push_back(f);
    Bound b;
    if (part.size() != 3 || !ParseNumber(part[1], &b.lower) || !ParseNumber(part[2], &b.upper)) {
      *error = "--bounds: bad item '" + item + "' (NAME:LO:HI)";
      return false;
    }
    const std::optional<Param> p = ParseParam(part[0]);
    if (!p) {
      *error = "--bounds: " + UnknownName("parameter", part[0], NamesOf<Param>());
      return false;
    }
    (*bounds)[*p] = b;
  }
  return true;
}

// --fix=NAME,... applied to a loaded dataset.
bool ApplyFix(Dataset* d, std::string* error) {
  std::vector<Param> fixed;
  std::stringstream list(FLAGS_fix);
  for (std::string name; std::getline(list, name, ',');) {
    if (name.empty()) continue;
    const std::optional<Param> p = ParseParam(name);
    if (!p) {
      *error = "--fix: " + UnknownName("parameter", name, NamesOf<Param>());
      return false;
    }
    fixed.push_back(*p);
  }
  if (!FixParameters(fixed, d, error)) {
    *error = "--" + *error;
    return false;
  }
  return true;
}

// --NAME=VALUE of an enum flag; the valid names on error.
template <class E>
bool ParseFlag(const char* name, const std::string& value, E* e, std::string* error) {
  const std::optional<E> parsed = FromString<E>(value);
  if (parsed) *e = *parsed;
  else *error = std::string("--") + name + ": " + UnknownName("value", value, NamesOf<E>());
  return parsed.has_value();
}

// The flags every fitting command shares, read into options and the model's
// effects; false with a one-line message on bad input.
bool ReadFitOptions(IdentifyOptions* o, std::vector<const Effect*>* effects,
                    std::string* error) {
  if (!ParseFlag("method", FLAGS_method, &o->method, error) ||
      !ParseFlag("weighting", FLAGS_weighting, &o->residuals.frequency_weighting, error) ||
      !ParseFlag("shape_convention", FLAGS_shape_convention, &o->residuals.shape_convention,
                 error) ||
      !ParseFlag("derivatives", FLAGS_derivatives, &o->residuals.derivatives, error)) {
    return false;
  }
  o->starts = FLAGS_starts;
  o->threads = FLAGS_threads ? FLAGS_threads
                             : std::max(1, internal::ThreadsFor(0) / std::max(1, FLAGS_jobs));
  o->seed = static_cast<unsigned>(FLAGS_seed);
  o->residuals.relative_sigma = FLAGS_relative_sigma;
  o->residuals.use_shapes = FLAGS_shapes;
  o->residuals.use_damping = FLAGS_damping;
  if (!ParseBounds(&o->bounds, error)) return false;
  if (!o->IsValid(error)) { *error = "bad option: " + *error; return false; }
  if (!ParseEffects(effects, error)) return false;
  if (FLAGS_dataset.empty()) { *error = "needs --dataset=FILE"; return false; }
  return true;
}

// The same and the one dataset of --dataset.
bool ReadFitInputs(IdentifyOptions* o, std::vector<const Effect*>* effects,
                   Dataset* d, std::string* error) {
  if (!ReadFitOptions(o, effects, error)) return false;
  if (!CheckOutputs({{"output", FLAGS_output}, {"save_parameters", FLAGS_save_parameters}},
                    Inputs(), error)) {
    return false;
  }
  LoadError load;
  if (!LoadDataset(FLAGS_dataset, d, &load)) { *error = load.OneLine(); return false; }
  return ApplyFix(d, error);
}

// --output_dir: a campaign of `command` over --dataset (apps/campaign.h).
int Campaign(int argc, char** argv, ReportKind command, const ModalModel& model,
             const CampaignWork& work) {
  if (!FLAGS_output.empty()) return Usage("--output: a campaign writes to --output_dir");
  CampaignRequest request{command, FLAGS_dataset, FLAGS_output_dir, FLAGS_shard, FLAGS_jobs};
  request.prepare = ApplyFix;
  request.provenance = [&](const std::vector<std::pair<std::string, std::string>>& inputs) {
    return MakeProvenance(argc, argv, inputs, FLAGS_seed);
  };
  std::string error;
  const int rc = RunCampaign(request, model, work, &error);
  return rc == kExitUsage ? Usage(error) : rc;
}

// The end of an analysis of one dataset: bad input is exit 2; otherwise its
// text, its report of type R at --output, and exit 0 or 1 by its status.
template <class R, class Result>
int Finish(int argc, char** argv, const Dataset& d, const Result& r) {
  if (r.status.invalid_input()) return Usage(FLAGS_dataset + ": " + r.status.message);
  std::printf("%s", r.FullReport().c_str());
  if (!FLAGS_output.empty()) {
    const int rc = Write(FLAGS_output, ReportText(R{ThisRun(argc, argv, FLAGS_seed), {d.name, r}}));
    if (rc != kExitOk) return rc;
  }
  return r.status.ok() ? kExitOk : kExitFailure;
}

int IdentifyCommand(int argc, char** argv) {
  std::string error;
  IdentifyOptions o;
  std::vector<const Effect*> effects;
  if (!FLAGS_output_dir.empty()) {
    if (!ReadFitOptions(&o, &effects, &error)) return Usage(error);
    if (!FLAGS_save_parameters.empty()) return Usage("--save_parameters: not in a campaign");
    const RigidRingModel model(effects);
    return Campaign(
        argc, argv, ReportKind::kIdentify, model,
        [&](const Dataset& d, const std::string& file) {
          IdentifySummary s;
          Identify(model, d, o, &s);
          CampaignItem item;
          item.report = ReportText(IdentifyReport{ThisRun(argc, argv, FLAGS_seed, file), {d.name, s}});
          item.row.status = s.status;
          item.row.converged = s.converged;
          item.row.cost = s.cost;
          item.row.relative_error_in_plane_eq19 = s.relative_error_in_plane;
          item.row.relative_error_out_of_plane_eq20 = s.relative_error_out_of_plane;
          item.row.seconds = s.seconds;
          return item;
        });
  }
  Dataset d;
  if (!ReadFitInputs(&o, &effects, &d, &error)) return Usage(error);
  const RigidRingModel model(effects);
  IdentifySummary s;
  Identify(model, d, o, &s);
  if (s.status.invalid_input()) return Usage(FLAGS_dataset + ": " + s.status.message);
  std::printf("%s", s.FullReport().c_str());
  std::vector<std::pair<std::string, std::string>> files;
  if (!FLAGS_output.empty()) {
    files.emplace_back(FLAGS_output,
                       ReportText(IdentifyReport{ThisRun(argc, argv, FLAGS_seed), {d.name, s}}));
  }
  if (!FLAGS_save_parameters.empty() && s.status.ok()) {
    files.emplace_back(FLAGS_save_parameters,
                       JsonText(ParameterSetJson(s, d.name, "identified by ringid from " + FLAGS_dataset)));
  }
  if (!WriteFilesAtomically(files, &error)) return Usage(error);
  return s.status.ok() ? kExitOk : kExitFailure;
}

int IdentifiabilityCommand(int argc, char** argv) {
  std::string error;
  IdentifiabilityOptions o;
  std::vector<const Effect*> effects;
  Dataset d;
  if (!ReadFitInputs(&o.fit, &effects, &d, &error)) return Usage(error);
  const RigidRingModel model(effects);
  IdentifiabilityReport r;
  AnalyzeIdentifiability(model, d, o, &r);
  return Finish<IdentifiabilityFile>(argc, argv, d, r);
}

int CompareCommand(int argc, char** argv) {
  std::string error;
  CompareOptions o;
  std::vector<const Effect*> effects;
  Dataset d;
  if (!ReadFitInputs(&o.fit, &effects, &d, &error)) return Usage(error);
  const RigidRingModel model(effects);
  ComparisonReport r;
  {
    Progress progress("compare", 2 * o.fit.starts);
    o.on_fit = [&] { progress.Add(); };
    CompareMethods(model, d, o, &r);
  }
  return Finish<CompareReport>(argc, argv, d, r);
}

// --NAME=X1,X2,...: finite numbers, each >= 0 (or > 0 when `positive`),
// none twice. False with a one-line message naming the flag.
bool ParseNumberList(const char* name, const std::string& text, bool positive, const char* unit,
                     std::vector<double>* values, std::string* error) {
  const std::string flag = std::string("--") + name;
  const std::string rule = std::string(positive ? "a number > 0" : "a number >= 0") + " in " + unit;
  if (text.empty()) {
    *error = flag + ": needs a comma-separated list, each item " + rule;
    return false;
  }
  for (size_t start = 0;;) {
    const size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? comma : comma - start);
    char* end = nullptr;
    const double v = item.empty() ? NAN : std::strtod(item.c_str(), &end);
    if (item.empty() || !end || *end != '\0' || !std::isfinite(v) || !(positive ? v > 0 : v >= 0)) {
      *error = flag + ": bad item '" + item + "' (each must be " + rule + ")";
      return false;
    }
    if (std::find(values->begin(), values->end(), v) != values->end()) {
      *error = flag + ": '" + item + "' is listed twice";
      return false;
    }
    values->push_back(v);
    if (comma == std::string::npos) return true;
    start = comma + 1;
  }
}

// simulate: every effect of --effects has a size (non-zero, from --set, the
// parameter file or --shift), and every effect size in --set has its effect
// in --effects. Either alone would simulate the baseline while the truth file
// names an effect, or drop the size without a word. (An effect's other
// parameters, m_a, may be set for any run: scripts/campaign_demo.sh sets it
// for every case.)
bool CheckEffectSizes(const std::vector<const Effect*>& effects,
                      const std::map<Param, double>& set, const Parameters& file,
                      std::string* error) {
  for (const auto& [p, v] : set) {
    const Effect* e = EffectOf(p);
    if (e && e->size() == p && std::find(effects.begin(), effects.end(), e) == effects.end()) {
      *error = std::string("--set: ") + ParamName(p) + " is the size of the effect " +
               e->name() + ", which --effects does not list; add --effects=" + e->name();
      return false;
    }
  }
  if (FLAGS_shift != 0) {
    if (!(FLAGS_shift > 0 && FLAGS_shift < 0.5)) {
      *error = "--shift: must be in (0, 0.5)";
      return false;
    }
    if (effects.size() != 1) {
      *error = "--shift: needs exactly one effect in --effects, whose size it sets";
      return false;
    }
    if (set.count(effects[0]->size())) {
      *error = std::string("--shift: sizes ") + ParamName(effects[0]->size()) +
               ", which --set gives too; give one of them";
      return false;
    }
    return true;
  }
  for (const Effect* e : effects) {
    const Param size = e->size();
    const auto it = set.find(size);
    const double value = it != set.end() ? it->second : file[size];
    if (value == 0 || !std::isfinite(value)) {
      *error = std::string("--effects: ") + e->name() + " has no size: give --set=" +
               ParamName(size) + "=VALUE (not 0) or --shift=FRACTION";
      return false;
    }
  }
  return true;
}

int SimulateCommand(int argc, char** argv) {
  std::string error;
  std::vector<double> speeds, loads;
  if (!ParseNumberList("speeds", FLAGS_speeds, false, "m/s", &speeds, &error)) return Usage(error);
  if (!gflags::GetCommandLineFlagInfoOrDie("loads").is_default &&
      !ParseNumberList("loads", FLAGS_loads, true, "N", &loads, &error)) {
    return Usage(error);
  }
  std::vector<const Effect*> effects;
  if (!ParseEffects(&effects, &error)) return Usage(error);
  if (FLAGS_parameters.empty() || FLAGS_output.empty() || FLAGS_truth.empty()) {
    return Usage("simulate needs --parameters=FILE, --output=DATASET and --truth=FILE");
  }
  for (double v : {FLAGS_frequency_noise, FLAGS_damping_noise, FLAGS_shape_noise, FLAGS_prior_spread}) {
    if (!(v >= 0) || !std::isfinite(v)) return Usage("noise levels and --prior_spread must be finite and not negative");
  }
  if (!CheckOutputs({{"output", FLAGS_output}, {"truth", FLAGS_truth}}, Inputs(), &error)) {
    return Usage(error);
  }
  Parameters truth;
  LoadError load;
  if (!LoadParameterSet(FLAGS_parameters, &truth, &load)) return Usage(load.OneLine());
  std::map<Param, double> set;
  if (!ParseSet(&set, &error) || !CheckEffectSizes(effects, set, truth, &error)) {
    return Usage(error);
  }
  for (const auto& [p, v] : set) truth[p] = v;
  if (FLAGS_shift != 0) truth[effects[0]->size()] = 0;  // set below
  const RigidRingModel model(effects);
  const std::vector<Param> missing = Missing(model, truth);
  if (!missing.empty()) return Usage(MissingParameters(FLAGS_parameters, missing));
  if (FLAGS_shift != 0) {
    const Param p = effects[0]->size();
    truth[p] = ValueForShift(truth, *effects[0], p, FLAGS_shift);
    if (!(LargestShift(truth, *effects[0], p, truth[p]) < 2 * FLAGS_shift)) {
      std::fprintf(stderr, "ringid: simulate: %s cannot shift a frequency by %g\n",
                   effects[0]->name(), FLAGS_shift);
      return kExitFailure;
    }
  }
  std::mt19937_64 rng(static_cast<unsigned>(FLAGS_seed));
  Dataset d = PlanSimulation(truth, FLAGS_prior_spread, speeds, loads, &rng);
  d.name = std::filesystem::path(FLAGS_output).stem().string();
  d.description = "simulated by ringid from " + FLAGS_parameters + "; the truth is in a separate file";
  SimulateOptions so;
  so.frequency_noise = FLAGS_frequency_noise;
  so.damping_noise = FLAGS_damping_noise;
  so.shape_noise = FLAGS_shape_noise;
  if (!Simulate(model, truth, so, &rng, &d, &error)) {
    std::fprintf(stderr, "ringid: simulate: %s\n", error.c_str());
    return kExitFailure;
  }
  nlohmann::json t;
  t["format"] = "ringid-truth/1";
  t["dataset"] = FLAGS_output;
  std::string names;
  for (const Effect* e : effects) names += (names.empty() ? "" : ",") + std::string(e->name());
  t["effect"] = names.empty() ? "none" : names;
  for (Param q : model.parameters()) {
    if (!d.IsPerCondition(q)) t["parameters"][ParamName(q)] = {{"value", truth[q]}};
  }
  for (const Condition& c : d.conditions) {  // per-condition values as NAME@CONDITION
    for (const auto& [q, v] : c.known) {
      t["parameters"][std::string(ParamName(q)) + "@" + c.name] = {{"value", v}};
    }
  }
  if (!WriteFilesAtomically({{FLAGS_output, DatasetToJson(d)}, {FLAGS_truth, JsonText(t)}},
                            &error)) {
    return Usage(error);
  }
  const std::string modes = d.conditions.size() == 1
                                ? std::to_string(d.modes.size()) + " modes"
                                : std::to_string(d.modes.size()) + " modes in " +
                                      std::to_string(d.conditions.size()) + " conditions";
  std::printf("wrote %s (%s) and %s (effect %s)\n", FLAGS_output.c_str(), modes.c_str(),
              FLAGS_truth.c_str(), t["effect"].get<std::string>().c_str());
  return kExitOk;
}

int DiagnoseCommand(int argc, char** argv) {
  std::string error;
  DiagnoseOptions o;
  if (!(FLAGS_level > 0 && FLAGS_level < 1)) return Usage("--level: must lie in (0, 1)");
  o.effect_significance = FLAGS_level;
  std::vector<const Effect*> effects;
  if (!FLAGS_output_dir.empty()) {
    if (!ReadFitOptions(&o.fit, &effects, &error)) return Usage(error);
    const RigidRingModel baseline(effects);
    return Campaign(
        argc, argv, ReportKind::kDiagnose, baseline,
        [&](const Dataset& d, const std::string& file) {
          DiagnosisReport r;
          Diagnose(baseline, d, o, &r);
          CampaignItem item;
          item.report = ReportText(DiagnoseReport{ThisRun(argc, argv, FLAGS_seed, file), {d.name, r}});
          item.row.status = r.status;
          item.row.seconds = r.seconds;
          if (r.status.ok()) {
            item.row.verdict = r.verdict;
            item.row.indistinguishable = r.indistinguishable;
            item.row.gap_before = item.row.gap_after = r.gap_before;
            item.row.shrink = 0;
            for (const EffectFit& f : r.ranking) {
              if (f.effect == r.verdict) item.row.gap_after = f.gap_after, item.row.shrink = f.shrink;
            }
          }
          return item;
        });
  }
  Dataset d;
  if (!ReadFitInputs(&o.fit, &effects, &d, &error)) return Usage(error);
  const RigidRingModel baseline(effects);
  DiagnosisReport r;
  Diagnose(baseline, d, o, &r);
  return Finish<DiagnoseReport>(argc, argv, d, r);
}

int BenchCommand(int argc, char** argv) {
  std::string error;
  if (FLAGS_replicates < 1) return Usage("--replicates: must be at least 1");
  if (!CheckOutputs({{"output", FLAGS_output}, {"markdown", FLAGS_markdown}}, {}, &error)) {
    return Usage(error);
  }
  SuiteOptions o;
  if (!ParseFlag("derivatives", FLAGS_derivatives, &o.derivatives, &error)) return Usage(error);
  o.replicates = FLAGS_replicates;
  o.seed = static_cast<unsigned>(FLAGS_seed);
  o.source_dir = DataDir();  // from any working directory
  Progress progress(FLAGS_suite + " suite");
  o.on_case = [&](int done, int total) { progress.Set(done, total); };
  const SuiteEntry* suite = nullptr;
  for (const SuiteEntry& s : Suites()) {
    if (FLAGS_suite == s.name) suite = &s;
  }
  if (FLAGS_suite.empty()) return Usage("bench needs --suite=" + OneOf(FlagValues("suite")));
  if (!suite) {
    return Usage("--suite: " + UnknownName("suite", FLAGS_suite, FlagValues("suite")));
  }
  const SuiteOutput r = suite->run(o, ThisRun(argc, argv, FLAGS_seed));
  if (r.status.invalid_input()) return Usage("--suite: " + r.status.message);
  if (!r.status.ok()) {
    std::fprintf(stderr, "ringid: bench: %s\n", r.status.message.c_str());
    return kExitFailure;
  }
  std::printf("%s", r.markdown.c_str());
  std::vector<std::pair<std::string, std::string>> files;
  if (!FLAGS_output.empty()) files.emplace_back(FLAGS_output, r.json);
  if (!FLAGS_markdown.empty()) files.emplace_back(FLAGS_markdown, r.markdown);
  if (!WriteFilesAtomically(files, &error)) return Usage(error);
  return kExitOk;
}

int ReportCommand(int argc, char** argv) {
  std::string error;
  if (FLAGS_input.empty() || FLAGS_output.empty()) {
    return Usage("report needs --input=REPORT.json and --output=FILE.html");
  }
  if (!CheckOutputs({{"output", FLAGS_output}}, Inputs(), &error)) return Usage(error);
  // Made only when the page is written, like --output_dir, so that a failed
  // run leaves nothing behind.
  if (!FLAGS_figures_dir.empty() && !CanMakeDirectory(FLAGS_figures_dir, &error)) {
    return Usage("--figures_dir: " + error);
  }
  Json report;
  if (!LoadReport(FLAGS_input, &report, &error)) return Usage(error);
  std::string html;
  std::vector<HtmlFigure> figures;
  if (!RenderHtmlReport(report, FLAGS_input, &html, &error, &figures)) {
    std::fprintf(stderr, "ringid: report: %s\n", error.c_str());
    return kExitFailure;
  }
  std::vector<std::pair<std::string, std::string>> files;
  for (const HtmlFigure& f : figures) {
    if (FLAGS_figures_dir.empty()) break;
    files.emplace_back((std::filesystem::path(FLAGS_figures_dir) / (f.name + ".svg")).string(), f.svg);
  }
  files.emplace_back(FLAGS_output, html);
  const auto hold = HoldInterruption();  // the figures' directory and the files, or none
  std::vector<std::string> made;
  if (!FLAGS_figures_dir.empty() && !MakeDirectory(FLAGS_figures_dir, &made, &error)) {
    return Usage("--figures_dir: " + error);
  }
  if (!WriteFilesAtomically(files, &error)) {
    RemoveMade(made);  // all or none: the directory too
    return Usage(error);
  }
  std::printf("wrote %s (%zu figure(s))\n", FLAGS_output.c_str(), figures.size());
  return kExitOk;
}

// export: a parameter set (ringid-parameters/1 or a .tir), with --set over
// it, as the rigid-ring part of an MF-Swift .tir or as ringid-parameters/1
// (docs/tir.md); to --output, else to standard output.
int ExportCommand(int, char**) {
  std::string error;
  if (FLAGS_parameters.empty()) {
    return Usage("export needs --parameters=FILE (ringid-parameters/1 or .tir)");
  }
  const std::vector<std::string> formats = FlagValues("format");
  if (FLAGS_format.empty()) return Usage("export needs --format=" + OneOf(formats));
  if (std::find(formats.begin(), formats.end(), FLAGS_format) == formats.end()) {
    return Usage("--format: " + UnknownName("format", FLAGS_format, formats));
  }
  if (!CheckOutputs({{"output", FLAGS_output}}, Inputs(), &error)) return Usage(error);
  std::map<Param, double> set;
  if (!ParseSet(&set, &error)) return Usage(error);
  Parameters p;
  LoadError load;
  Undetermined undetermined;  // from an identify report's or --save_parameters' classes
  if (!LoadParameters(FLAGS_parameters, &p, &load, &undetermined)) return Usage(load.OneLine());
  for (const auto& [q, v] : set) {
    p[q] = v;
    undetermined.erase(q);  // given by hand
  }
  const std::string source =
      FLAGS_parameters + (FLAGS_set.empty() ? "" : " with --set=" + FLAGS_set);
  const std::string name = std::filesystem::path(FLAGS_parameters).stem().string();
  std::string text;
  if (FLAGS_format == "json") {
    text = ParameterSetToJson(p, name, "exported by ringid from " + source);
  } else if (!ParametersToTir(p, name, source, &text, &load, undetermined)) {
    return Usage(load.OneLine());
  }
  if (FLAGS_output.empty()) {
    std::fputs(text.c_str(), stdout);
    return kExitOk;
  }
  const int rc = Write(FLAGS_output, text);
  if (rc == kExitOk) std::printf("wrote %s\n", FLAGS_output.c_str());
  return rc;
}

// The flags every fitting command takes, and a campaign's.
const std::vector<std::string> kFitFlags = {
    "dataset", "output", "method", "starts", "seed", "weighting", "relative_sigma",
    "shapes", "damping", "shape_convention", "derivatives", "effects", "bounds", "fix", "threads"};
const std::vector<std::string> kCampaignFlags = {"output_dir", "jobs", "shard"};

std::vector<std::string> Joined(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

int SchemaCommand(int, char**) {
  std::fputs(ReportsMarkdown().c_str(), stdout);
  return kExitOk;
}

int ReferenceCommand(int, char**) {
  std::fputs(ReferenceMarkdown().c_str(), stdout);
  return kExitOk;
}

// Every command: what it needs, what it does, the flags it takes (the one list
// SetFlags and --help read) and what runs it.
const std::vector<Command>& Commands() {
  static const std::vector<Command> commands = {
      {"predict", "--parameters=FILE | --dataset=FILE",
       "modes of a parameter set, as a table and JSON; a FILE.tir is read as\n"
       "MF-Swift's rigid-ring part (docs/tir.md), the rest given by --set",
       {"parameters", "dataset", "set", "effects", "output"}, Predict},
      {"identify", "--dataset=FILE",
       "fit parameters to a dataset, with covariance and identifiability;\n"
       "with --output_dir, a campaign over many datasets (--dataset=FILE,DIR,...):\n"
       "one report per dataset, a summary table and DIR/campaign.json\n"
       "(campaign.I-of-N.json for a --shard)",
       Joined(Joined(kFitFlags, {"save_parameters"}), kCampaignFlags), IdentifyCommand},
      {"identifiability", "--dataset=FILE",
       "what the data determine at the fitted point: rank, classes, Wald and\n"
       "profile intervals, free combinations, collinear pairs, identifiable\n"
       "subset, experiment advice",
       kFitFlags, IdentifiabilityCommand},
      {"compare", "--dataset=FILE",
       "Levenberg-Marquardt and the Downhill Simplex from the same --starts:\n"
       "success rate, final costs, evaluations, time per fit",
       kFitFlags, CompareCommand},
      {"simulate", "--parameters=FILE --output=DATASET --truth=FILE",
       "a dataset measured from a parameter set, optionally with effects (each\n"
       "sized by --set or --shift), and a separate truth file; one condition per\n"
       "speed and load, and several give a format-2 dataset",
       {"parameters", "output", "truth", "effects", "set", "shift", "frequency_noise",
        "damping_noise", "shape_noise", "prior_spread", "seed", "speeds", "loads"},
       SimulateCommand},
      {"diagnose", "--dataset=FILE",
       "the gap between the calibrated baseline and the data: where it lies,\n"
       "which effect explains it, how far it shrinks; --effects puts effects in\n"
       "the baseline and the others are tried on top; with --output_dir, a\n"
       "campaign as for identify",
       Joined(Joined(kFitFlags, {"level"}), kCampaignFlags), DiagnoseCommand},
      {"bench", "--suite=NAME",
       "the accuracy, conditioning and speed suites, on the paper's data installed\n"
       "with ringid, here in " + DataDir() + "/datasets/paper; speed times numeric\n"
       "and analytic derivatives side by side, whatever --derivatives says",
       {"suite", "replicates", "seed", "derivatives", "output", "markdown"}, BenchCommand},
      {"report", "--input=REPORT.json --output=FILE.html",
       "any JSON report of ringid as one self-contained HTML page: tables and\n"
       "figures (SVG drawn by gnuplot, package gnuplot-nox)",
       {"input", "output", "figures_dir"}, ReportCommand},
      {"export", "--parameters=FILE --format=tir|json",
       "a parameter set (ringid-parameters/1 or a .tir), with --set over it, as\n"
       "the rigid-ring part of an MF-Swift .tir or as ringid-parameters/1 JSON;\n"
       "what maps to what and what a .tir cannot hold: docs/tir.md",
       {"parameters", "set", "format", "output"}, ExportCommand},
      {"schema", "", "every report's fields and their types, as Markdown (docs/reports.md)", {},
       SchemaCommand},
      {"reference", "",
       "parameters, degrees of freedom, labels and effects with their units, as\n"
       "Markdown (docs/reference.md)",
       {}, ReferenceCommand},
  };
  return commands;
}

std::string UnknownCommand(const std::string& name) {
  std::vector<std::string> names = {"help"};
  for (const Command& c : Commands()) names.push_back(c.name);
  return UnknownName("command", name, names) + "; see 'ringid help'";
}

// `ringid help [COMMAND]`.
int HelpCommand(int argc, char** argv) {
  if (argc <= 2) {
    std::fputs(Help(Commands()).c_str(), stdout);
    return kExitOk;
  }
  if (argc > 3) return Usage("help takes at most one command (see 'ringid help')");
  const Command* c = FindCommand(Commands(), argv[2]);
  if (!c) return Usage(UnknownCommand(argv[2]));
  std::fputs(CommandHelp(*c).c_str(), stdout);
  return kExitOk;
}

// Runs argv[1] with the flags of argv[2..].
int Run(int argc, char** argv) {
  const std::string name = argc > 1 ? argv[1] : "help";
  if (name == "help" || name == "--help" || name == "-h") return HelpCommand(argc, argv);
  const Command* command = FindCommand(Commands(), name);
  if (!command) return Usage(UnknownCommand(name));
  if (WantsHelp(argc, argv)) {
    std::fputs(CommandHelp(*command).c_str(), stdout);
    return kExitOk;
  }
  std::string error;
  if (!SetFlags(argc, argv, *command, Commands(), &error)) return Usage(error);
  return command->run(argc, argv);
}

}  // namespace
}  // namespace ringid

int main(int argc, char** argv) {
  ringid::ExitOnInterrupt();  // first: its thread must exist before any other
  FLAGS_logtostderr = true;
  FLAGS_minloglevel = 3;  // Ceres reports failed evaluations at ERROR; the report says why
  google::InitGoogleLogging(argv[0]);
  gflags::SetUsageMessage("see 'ringid help'");
  return ringid::Run(argc, argv);
}
