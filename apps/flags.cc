// The flags of ringid and what they become: options, effects, datasets,
// provenance. Each command in apps/ringid.cc reads them through these.
#include "apps/flags.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "apps/help.h"
#include "apps/reports.h"
#include "datasets/synthetic.h"
#include "datasets/tir_parameters.h"
#include "estimation/parallel.h"
#include "model/spelling.h"
#include "validation/suites.h"

// Each flag's meaning, for every command that takes it; which commands take
// it is the table of commands in main(), and `ringid COMMAND --help` shows
// both. The values a named flag takes come from the library (apps/help.cc).
DEFINE_string(dataset, "", "modal dataset (docs/conventions.md §3); a campaign takes FILE,DIR,... (a directory stands for its *.json)");
DEFINE_string(parameters, "", "parameter set (ringid-parameters/1, or an identify report)");
DEFINE_string(output, "", "write the JSON report here (simulate: the dataset; report: the HTML page; export: the file, else to standard output)");
DEFINE_string(save_parameters, "", "also write the fitted parameter set (ringid-parameters/1) here");
DEFINE_string(method, ringid::ToString(ringid::IdentifyOptions().method), "how to fit: Levenberg-Marquardt or the Downhill Simplex");
DEFINE_int32(starts, ringid::IdentifyOptions().starts, "number of starts: the dataset's initial point, the point matching the measured frequencies, and points scattered log-uniformly around that");
DEFINE_int32(max_iterations, ringid::IdentifyOptions().max_iterations,
             "Levenberg-Marquardt iterations per start (and per profile refit) before it stops "
             "unconverged");
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
DEFINE_string(speeds, "0", "V1,V2,...: speeds in m/s (>= 0); simulate: one condition each (0: standing, else drum_V); predict: the modes at each (a Campbell diagram)");
DEFINE_string(loads, "", "F1,F2,...: loads F_cz0 in N (> 0); the conditions are then speeds x loads");
DEFINE_string(suite, "", "the validation suite to run");
DEFINE_string(uff, "", "import: a Universal File Format file of a modal test (datasets 55, 58/58b, 15, 18, 82, 151, 164)");
DEFINE_string(map, "", "import: a UFF map (ringid-uff-map/1): each node and direction a degree of freedom, modes to labels");
DEFINE_string(lug_forces, "",
              "simulate: a lug-force file (ringid-lug-forces/1); writes the axle's response to "
              "those forces at --speeds, a response dataset (ringid-lug-response/1)");
DEFINE_double(response_noise, 1 / (10 * std::sqrt(2.0)),
              "simulate --lug_forces: noise on re and on im of each channel, a share of its "
              "amplitude (the default is 20 dB)");
DEFINE_int32(lugs_per_revolution, 0,
             "predict: lug impacts per wheel turn; with --speeds, the lug orders meet the modes "
             "at the critical speeds listed (0: none)");
DEFINE_int32(max_order, 5,
             "predict --lugs_per_revolution: the highest lug order whose critical speeds are "
             "listed (at most 200). The default keeps the orders a lug-force measurement reads "
             "(docs/forces.md) and a list of a few dozen lines: order k meets a mode of f Hz at "
             "2 pi r_e0 f / (k lugs) m/s, so slow speeds alone would add hundreds of orders");
DEFINE_int32(replicates, ringid::SuiteOptions().replicates, "Monte Carlo replicates per tire (synthetic, rolling)");
DEFINE_string(markdown, "", "also write the Markdown table here");
DEFINE_string(output_dir, "", "run a campaign: one report per dataset and campaign.json in this directory (made if missing)");
DEFINE_int32(jobs, 1, "campaign: datasets analysed at once (threads)");
DEFINE_string(shard, "0/1", "campaign: I/N, analyse every N-th dataset from the I-th (0-based); slurm: I and N from the job array's SLURM_ARRAY_TASK_* variables");
DEFINE_bool(force, false, "campaign: fit every dataset again, also those whose report is already there from the same dataset and options");
DEFINE_bool(keep_going, false, "campaign: a dataset that fails to load is a failed row of the summary (exit 1), not the end of the campaign (exit 2)");
DEFINE_string(input, "", "a JSON report of ringid");
DEFINE_string(figures_dir, "", "also write each figure as DIR/NAME.svg (the directory made if missing)");
DEFINE_string(bounds, "", "NAME:LO:HI,...: bounds in the parameter's units, in place of a factor 1000 around the start");
DEFINE_string(fix, "", "NAME,...: parameters held at their initial values (simulate: written known, at the truth)");
DEFINE_string(effects, "", "EFFECT,...: effects of docs/conventions.md §4 to add to the model (diagnose: to its baseline; the others are tried on top)");
DEFINE_double(level, ringid::DiagnoseOptions().effect_significance,
              "significance level of each effect's likelihood-ratio test and of the verdict's group (the default is Bonferroni-safe for six candidates)");
DEFINE_int32(threads, 0, "starts (diagnose: and candidate effects) fitted at once; 0: the cores, shared among --jobs");
DEFINE_string(format, "", "what to write: the rigid-ring part of an MF-Swift .tir (docs/tir.md) or a parameter set (ringid-parameters/1 JSON)");

namespace ringid {

const std::vector<std::string>& ResultFlags() {
  static const std::vector<std::string> flags = {
      "method", "starts", "max_iterations", "seed", "weighting", "relative_sigma", "shapes", "damping",
      "shape_convention", "derivatives", "effects", "bounds", "fix"};
  return flags;
}

const std::vector<std::string>& FitFlags() {
  static const std::vector<std::string> flags =
      Joined(Joined({"dataset", "output"}, ResultFlags()), {"threads"});
  return flags;
}

const std::vector<std::string>& PredictFlags() {
  static const std::vector<std::string> flags = {
      "parameters", "dataset", "set", "effects", "speeds", "lugs_per_revolution", "max_order",
      "output"};
  return flags;
}

const std::vector<std::string>& SimulateFlags() {
  static const std::vector<std::string> flags = {
      "parameters", "output", "truth", "effects", "set", "shift", "frequency_noise",
      "damping_noise", "shape_noise", "prior_spread", "fix", "seed", "speeds", "loads",
      "lug_forces", "response_noise"};
  return flags;
}

const std::vector<std::string>& ForcesFlags() {
  static const std::vector<std::string> flags = {"parameters", "set", "dataset", "effects",
                                                 "output"};
  return flags;
}

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
std::vector<std::pair<std::string, std::string>> Inputs(const std::string& dataset) {
  return {{"dataset", dataset}, {"parameters", FLAGS_parameters}, {"input", FLAGS_input}};
}

// This process's provenance, with the inputs its flags named.
Provenance ThisRun(int argc, char** argv, std::optional<long> seed,
                   const std::string& dataset) {
  Provenance p = MakeProvenance(argc, argv, Inputs(dataset), seed);
  // Checked by every command that fits before it runs.
  p.derivatives = FromString<Derivatives>(FLAGS_derivatives).value_or(Derivatives::kNumeric);
  if (!FLAGS_output_dir.empty()) p.options = CampaignOptions();
  return p;
}

std::vector<std::string> CampaignOptions() {
  std::vector<std::string> options;
  for (const std::string& name : Joined(ResultFlags(), {"level"})) {
    std::string value;
    gflags::GetCommandLineOption(name.c_str(), &value);
    options.push_back(name + "=" + value);
  }
  return options;
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
const Effect* EffectOwning(Param p) {
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
std::string MissingParameters(const std::string& source, const std::vector<Param>& missing,
                              const std::vector<std::string>& notes) {
  const Param q = missing[0];
  const std::string name = ParamName(q);
  std::string reason;  // what reading the file said of it
  for (const std::string& note : notes) {
    if (note.rfind(name + " not derived: ", 0) == 0) reason = note.substr(name.size() + 14);
  }
  if (const Effect* e = EffectOwning(q)) {
    return "--effects: " + std::string(e->name()) + " needs " + name + ": give --set=" + name +
           "=VALUE";
  }
  if (!IsTirPath(source)) return source + ": parameters." + name + ": missing (the model needs it)";
  const std::string key = TirKeyFor(q);
  if (reason.empty()) {
    reason = key.empty() ? std::string("a .tir cannot hold it") : "the .tir has no " + key;
  }
  if (q == Param::I_ay) {
    reason = "a .tir describes the tire, not the wheel: give the rim's own inertia (the tire's "
             "IYY - BELT_IYY, where the file gives them, is added)";
  }
  std::string line = source + ": " + name + ": missing (the model needs it; " + reason +
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

bool ParseFix(std::vector<Param>* fixed, std::string* error) {
  std::stringstream list(FLAGS_fix);
  for (std::string name; std::getline(list, name, ',');) {
    if (name.empty()) continue;
    const std::optional<Param> p = ParseParam(name);
    if (!p) {
      *error = "--fix: " + UnknownName("parameter", name, NamesOf<Param>());
      return false;
    }
    fixed->push_back(*p);
  }
  return true;
}

// --fix=NAME,... applied to a loaded dataset.
bool ApplyFix(Dataset* d, std::string* error) {
  std::vector<Param> fixed;
  if (!ParseFix(&fixed, error)) return false;
  if (!FixParameters(fixed, d, error)) {
    *error = "--" + *error;
    return false;
  }
  return true;
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
  if (FLAGS_max_iterations < 1) {
    *error = "--max_iterations: must be at least 1";
    return false;
  }
  o->max_iterations = FLAGS_max_iterations;
  if (FLAGS_threads < 0 || FLAGS_threads > IdentifyOptions::kMaxThreads) {
    *error = "--threads: must lie in [0, " + std::to_string(IdentifyOptions::kMaxThreads) +
             "] (0: the cores)";
    return false;
  }
  // The cores are shared among a campaign's jobs.
  const int jobs = FLAGS_output_dir.empty() ? 1 : std::max(1, FLAGS_jobs);
  o->threads = FLAGS_threads ? FLAGS_threads : std::max(1, internal::ThreadsFor(0) / jobs);
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

// --dataset names one file, not a directory or a list (a campaign's).
bool OneDatasetFile(bool campaigns, std::string* error) {
  std::error_code ec;
  const bool directory = std::filesystem::is_directory(FLAGS_dataset, ec);
  const bool list = FLAGS_dataset.find(',') != std::string::npos &&
                    !std::filesystem::exists(FLAGS_dataset, ec);
  if (!directory && !list) return true;
  *error = "--dataset: " + FLAGS_dataset + " is " +
           (directory ? "a directory" : "a list") + " of datasets, " +
           (campaigns ? "a campaign: give --output_dir=DIR for its reports (one per dataset and "
                        "DIR/campaign.json)"
                      : "and this command reads one dataset file (campaigns: identify and "
                        "diagnose with --output_dir)");
  return false;
}

// The same and the one dataset of --dataset.
bool ReadFitInputs(IdentifyOptions* o, std::vector<const Effect*>* effects,
                   Dataset* d, std::string* error, bool campaigns) {
  if (!ReadFitOptions(o, effects, error)) return false;
  if (!OneDatasetFile(campaigns, error)) return false;
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
  std::vector<Param> fixed;  // a mistake in --fix is the command's, not each dataset's
  std::string bad;
  if (!ParseFix(&fixed, &bad)) return Usage(bad);
  request.options = CampaignOptions();
  request.force = FLAGS_force;
  request.keep_going = FLAGS_keep_going;
  request.prepare = ApplyFix;
  request.provenance = [&](const std::vector<std::pair<std::string, std::string>>& inputs) {
    return MakeProvenance(argc, argv, inputs, FLAGS_seed);
  };
  std::string error;
  const int rc = RunCampaign(request, model, work, &error);
  return rc == kExitUsage ? Usage(error) : rc;
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
    const Effect* e = EffectOwning(p);
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

}  // namespace ringid
