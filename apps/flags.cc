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
#include "model/spelling.h"
#include "operations/fit.h"
#include "validation/suites.h"

// Each flag's meaning, for every command that takes it; which commands take
// it is the table of commands in main(), and `ringid COMMAND --help` shows
// both. The values a named flag takes come from the library (apps/help.cc).
// The options of the operations are not here: they are registered from
// their lists (operations/options.h, RegisterOptionFlags below).
DEFINE_string(dataset, "", "modal dataset (docs/conventions.md §3); a campaign takes FILE,DIR,... (a directory stands for its *.json)");
DEFINE_string(parameters, "", "parameter set (ringid-parameters/1, or an identify report)");
DEFINE_string(output, "", "write the JSON report here (simulate, extract: the dataset; report: the HTML page; export: the file, else to standard output)");
DEFINE_string(save_parameters, "", "also write the fitted parameter set (ringid-parameters/1) here");
DEFINE_string(truth, "", "write the truth (effects and every value) here");
DEFINE_string(report, "", "extract: also write the JSON report here (the stabilisation diagram, the poles, each FRF against its synthesis; docs/reports.md)");
DEFINE_string(suite, "", "the validation suite to run");
DEFINE_string(uff, "", "import: a Universal File Format file of a modal test (datasets 55, 58/58b, 15, 18, 82, 151, 164)");
DEFINE_string(map, "", "import: a UFF map (ringid-uff-map/1 or /2): each node and direction a degree of freedom, modes to labels; /2: where the FRFs' nodes are (docs/uff.md)");
DEFINE_int32(replicates, ringid::SuiteOptions().replicates, "Monte Carlo replicates per tire (synthetic, rolling); static: the number of tires");
DEFINE_string(markdown, "", "also write the Markdown table here");
DEFINE_string(output_dir, "", "run a campaign: one report per dataset and campaign.json in this directory (made if missing)");
DEFINE_int32(jobs, 1, "campaign: datasets analysed at once (threads)");
DEFINE_string(shard, "0/1", "campaign: I/N, analyse every N-th dataset from the I-th (0-based); slurm: I and N from the job array's SLURM_ARRAY_TASK_* variables");
DEFINE_bool(force, false, "campaign: fit every dataset again, also those whose report is already there from the same dataset and options");
DEFINE_bool(keep_going, false, "campaign: a dataset that fails to load is a failed row of the summary (exit 1), not the end of the campaign (exit 2)");
DEFINE_string(input, "", "a JSON report of ringid");
DEFINE_string(figures_dir, "", "also write each figure as DIR/NAME.svg (the directory made if missing)");
DEFINE_string(format, "", "what to write: the rigid-ring part of an MF-Swift .tir (docs/tir.md) or a parameter set (ringid-parameters/1 JSON)");

namespace ringid {
namespace {

// A flag of type T, as DEFINE_* makes one: gflags keeps the name and the
// meaning (EveryOption's, never freed) and both values for the life of the
// process.
template <class T>
void Register(const OptionInfo& o, const T& value) {
  gflags::FlagRegisterer(o.name.c_str(), o.help.c_str(), __FILE__, new T(value), new T(value));
}

// Each option of operations/options.h as a flag of its kind, with the
// default and meaning its list gives; at start-up, as DEFINE_* would.
bool RegisterOptionFlags() {
  for (const OptionInfo& o : EveryOption()) {
    std::string error;
    switch (o.kind) {
      case OptionKind::kBool: {
        bool v = false;
        OptionFromText(o.name, o.default_text, &v, &error);
        Register(o, v);
        break;
      }
      case OptionKind::kInteger: {
        int v = 0;
        OptionFromText(o.name, o.default_text, &v, &error);
        Register(o, static_cast<gflags::int32>(v));
        break;
      }
      case OptionKind::kNumber: {
        double v = 0;
        OptionFromText(o.name, o.default_text, &v, &error);
        Register(o, v);
        break;
      }
      case OptionKind::kText:
        Register(o, o.default_text);
        break;
    }
  }
  return true;
}
const bool kOptionFlags = RegisterOptionFlags();

std::vector<std::string> OptionNames(const std::vector<OptionInfo>& options) {
  std::vector<std::string> names;
  for (const OptionInfo& o : options) names.push_back(o.name);
  return names;
}

}  // namespace

const std::vector<std::string>& ResultFlags() {
  static const std::vector<std::string> flags = [] {
    std::vector<std::string> names = OptionNames(OptionsOf<FitSettings>());
    names.erase(std::find(names.begin(), names.end(), "threads"));
    return names;
  }();
  return flags;
}

const std::vector<std::string>& FitFlags() {
  static const std::vector<std::string> flags =
      Joined({"dataset", "output"}, OptionNames(OptionsOf<FitSettings>()));
  return flags;
}

const std::vector<std::string>& PredictFlags() {
  static const std::vector<std::string> flags =
      Joined(Joined({"parameters", "dataset"}, OptionNames(OptionsOf<PredictSettings>())), {"output"});
  return flags;
}

const std::vector<std::string>& SimulateFlags() {
  static const std::vector<std::string> flags =
      Joined({"parameters", "output", "truth"}, OptionNames(OptionsOf<SimulateSettings>()));
  return flags;
}

const std::vector<std::string>& ExtractFlags() {
  static const std::vector<std::string> flags =
      Joined({"dataset", "parameters", "output", "report"}, OptionNames(OptionsOf<ExtractSettings>()));
  return flags;
}

const std::vector<std::string>& ForcesFlags() {
  static const std::vector<std::string> flags =
      Joined(Joined({"parameters", "dataset"}, OptionNames(OptionsOf<ForcesSettings>())), {"output"});
  return flags;
}

int Usage(const std::string& line) {
  std::fprintf(stderr, "ringid: %s\n", line.c_str());
  return kExitUsage;
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
  Derivatives derivatives = FitSettings().derivatives;
  std::string ignored;
  p.derivatives = ReadFlag("derivatives", &derivatives, &ignored) ? derivatives
                                                                  : FitSettings().derivatives;
  if (!FLAGS_output_dir.empty()) p.options = CampaignOptions();
  return p;
}

std::string FlagText(const std::string& name) {
  std::string value;
  gflags::GetCommandLineOption(name.c_str(), &value);
  return value;
}

int SeedFlag() {
  int seed = FitSettings().seed;
  std::string ignored;
  ReadFlag("seed", &seed, &ignored);
  return seed;
}

bool ParseSet(ParameterValues* set, std::string* error) { return ReadFlag("set", set, error); }

const std::vector<std::string>& DiagnoseFlags() {
  static const std::vector<std::string> flags = {"level", "screen"};
  return flags;
}

std::vector<std::string> CampaignOptions() {
  std::vector<std::string> options;
  for (const std::string& name : Joined(ResultFlags(), DiagnoseFlags())) {
    options.push_back(name + "=" + FlagText(name));
  }
  return options;
}

namespace {

// The datasets fitted at once: a campaign's --jobs share the cores.
int Jobs() { return FLAGS_output_dir.empty() ? 1 : std::max(1, FLAGS_jobs); }

bool NeedsDataset(std::string* error) {
  if (FLAGS_dataset.empty()) *error = "needs --dataset=FILE";
  return !FLAGS_dataset.empty();
}

}  // namespace

bool ReadFitOptions(FitSettings* s, IdentifyOptions* o, std::string* error) {
  return ReadSettings(s, error) && FitOptionsOf(*s, Jobs(), o, error) && NeedsDataset(error);
}

bool ReadIdentifiabilityOptions(IdentifiabilitySettings* s, IdentifiabilityOptions* o,
                                std::string* error) {
  return ReadSettings(s, error) && IdentifiabilityOptionsOf(*s, Jobs(), o, error) &&
         NeedsDataset(error);
}

bool ReadDiagnoseOptions(DiagnoseSettings* s, DiagnoseOptions* o, std::string* error) {
  return ReadSettings(s, error) && DiagnoseOptionsOf(*s, Jobs(), o, error) &&
         NeedsDataset(error);
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

bool ReadFitDataset(const FitSettings& s, Dataset* d, std::string* error, bool campaigns) {
  if (!OneDatasetFile(campaigns, error)) return false;
  if (!CheckOutputs({{"output", FLAGS_output}, {"save_parameters", FLAGS_save_parameters}},
                    Inputs(), error)) {
    return false;
  }
  LoadError load;
  if (!LoadDataset(FLAGS_dataset, d, &load)) {
    *error = load.OneLine();
    return false;
  }
  return ApplyFix(s.fix, d, error);
}

// --output_dir: a campaign of `command` over --dataset (apps/campaign.h).
int Campaign(int argc, char** argv, ReportKind command, const ModalModel& model,
             const FitSettings& s, const CampaignWork& work) {
  if (!FLAGS_output.empty()) return Usage("--output: a campaign writes to --output_dir");
  CampaignRequest request{command, FLAGS_dataset, FLAGS_output_dir, FLAGS_shard, FLAGS_jobs};
  request.options = CampaignOptions();
  request.force = FLAGS_force;
  request.keep_going = FLAGS_keep_going;
  const std::vector<Param> fix = s.fix;
  request.prepare = [fix](Dataset* d, std::string* error) { return ApplyFix(fix, d, error); };
  const int seed = s.seed;
  request.provenance = [&, seed](const std::vector<std::pair<std::string, std::string>>& inputs) {
    return MakeProvenance(argc, argv, inputs, seed);
  };
  std::string error;
  const int rc = RunCampaign(request, model, work, &error);
  return rc == kExitUsage ? Usage(error) : rc;
}

}  // namespace ringid
