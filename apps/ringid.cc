// ringid: identify rigid-ring tire parameters from modal data.
// A thin layer: parse flags, load, call the library, print, write the report.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gflags/gflags.h>
#include <glog/logging.h>

#include "apps/campaign.h"
#include "apps/command_line.h"
#include "apps/data_dir.h"
#include "apps/flags.h"
#include "apps/forces_command.h"
#include "apps/poles_command.h"
#include "apps/import_command.h"
#include "apps/merge_command.h"
#include "apps/predict_command.h"
#include "apps/report_command.h"
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
#include "datasets/parameter_files.h"
#include "datasets/synthetic.h"
#include "datasets/tir_parameters.h"
#include "estimation/compare.h"
#include "estimation/identifiability.h"
#include "estimation/identify.h"
#include "model/effects.h"
#include "model/spelling.h"
#include "model/rigid_ring_model.h"
#include "operations/extract.h"
#include "operations/fit.h"
#include "operations/simulate.h"

namespace ringid {
namespace {

int IdentifyCommand(int argc, char** argv) {
  std::string error;
  FitSettings settings;
  IdentifyOptions o;
  if (!FLAGS_output_dir.empty()) {
    if (!ReadFitOptions(&settings, &o, &error)) return Usage(error);
    if (!FLAGS_save_parameters.empty()) return Usage("--save_parameters: not in a campaign");
    const RigidRingModel model(settings.effects);
    return Campaign(
        argc, argv, ReportKind::kIdentify, model, settings,
        [&](const Dataset& d, const std::string& file) {
          IdentifyResult s;
          Identify(model, d, o, &s);
          return CampaignItem{
              ReportText(IdentifyReport{ThisRun(argc, argv, settings.seed, file), {d.name, s}}),
              IdentifyRow(s)};
        });
  }
  Dataset d;
  if (!ReadFitOptions(&settings, &o, &error) || !ReadFitDataset(settings, &d, &error, true)) {
    return Usage(error);
  }
  const RigidRingModel model(settings.effects);
  IdentifyResult s;
  Identify(model, d, o, &s);
  if (s.status.invalid_input()) return Usage(FLAGS_dataset + ": " + s.status.message);
  std::printf("%s", s.FullReport().c_str());
  std::vector<std::pair<std::string, std::string>> files;
  if (!FLAGS_output.empty()) {
    files.emplace_back(FLAGS_output,
                       ReportText(IdentifyReport{ThisRun(argc, argv, settings.seed), {d.name, s}}));
  }
  if (!FLAGS_save_parameters.empty() && s.status.ok()) {
    files.emplace_back(FLAGS_save_parameters,
                       ParameterSetText(IdentifiedParameterSet(s, d.name, "identified by ringid from " + FLAGS_dataset)));
  }
  if (!WriteFilesAtomically(files, &error)) return Usage(error);
  return s.status.ok() ? kExitOk : kExitFailure;
}

int IdentifiabilityCommand(int argc, char** argv) {
  std::string error;
  IdentifiabilitySettings settings;
  IdentifiabilityOptions o;
  Dataset d;
  if (!ReadIdentifiabilityOptions(&settings, &o, &error) ||
      !ReadFitDataset(settings.fit, &d, &error)) {
    return Usage(error);
  }
  const RigidRingModel model(settings.fit.effects);
  IdentifiabilityResult r;
  {
    Progress progress("identifiability", 0, kProgressAfterSeconds);
    o.on_step = [&](int done, int total) { progress.Set(done, total); };
    AnalyzeIdentifiability(model, d, o, &r);
  }
  return Finish<IdentifiabilityReport>(argc, argv, d, r);
}

int CompareCommand(int argc, char** argv) {
  std::string error;
  FitSettings settings;
  CompareOptions o;
  Dataset d;
  if (!ReadFitOptions(&settings, &o.fit, &error) || !ReadFitDataset(settings, &d, &error)) {
    return Usage(error);
  }
  const RigidRingModel model(settings.effects);
  ComparisonResult r;
  {
    Progress progress("compare", 2 * o.fit.starts);
    o.on_fit = [&] { progress.Add(); };
    CompareMethods(model, d, o, &r);
  }
  return Finish<CompareReport>(argc, argv, d, r);
}

int SimulateCommand(int, char**) {
  std::string error;
  SimulateSettings settings;
  if (!ReadSettings(&settings, &error)) return Usage(error);
  if (!settings.lug_forces.empty()) return SimulateResponsesCommand(settings);
  if (FLAGS_parameters.empty() || FLAGS_output.empty() || FLAGS_truth.empty()) {
    return Usage("simulate needs --parameters=FILE, --output=DATASET and --truth=FILE");
  }
  auto inputs = Inputs();
  inputs.emplace_back("frf", settings.frf);
  inputs.emplace_back("obstacle", settings.obstacle);
  if (!CheckOutputs({{"output", FLAGS_output}, {"truth", FLAGS_truth}}, inputs, &error)) {
    return Usage(error);
  }
  Simulated s;
  InputError bad;
  bool failed = false;
  if (!SimulateDataset(FLAGS_parameters, FLAGS_output, settings, &s, &bad, &failed)) {
    if (!failed) return Usage(bad.line);
    std::fprintf(stderr, "ringid: simulate: %s\n", bad.line.c_str());
    return kExitFailure;
  }
  const Dataset& d = s.dataset;
  if (!WriteFilesAtomically({{FLAGS_output, DatasetToJson(d)},
                             {FLAGS_truth, TruthText(s.truth)}},
                            &error)) {
    return Usage(error);
  }
  size_t frfs = 0;
  for (const Condition& c : d.conditions) frfs += c.frf ? c.frf->functions.size() : 0;
  std::string modes = frfs == 0 || !d.modes.empty() ? std::to_string(d.modes.size()) + " modes" : "";
  if (frfs > 0) modes += (modes.empty() ? "" : ", ") + std::to_string(frfs) + " FRFs";
  if (!d.statics.empty()) modes += ", " + std::to_string(d.statics.size()) + " static stiffnesses";
  size_t runs = 0, series = 0;
  for (const Condition& c : d.conditions) {
    runs += c.obstacle.has_value();
    series += c.obstacle ? c.obstacle->channels.size() : 0;
  }
  if (runs > 0) {
    modes += ", " + std::to_string(runs) + (runs == 1 ? " obstacle run" : " obstacle runs") +
             " (" + std::to_string(series) + " channels in all)";
  }
  if (d.conditions.size() > 1) modes += " in " + std::to_string(d.conditions.size()) + " conditions";
  std::printf("wrote %s (%s) and %s (effect %s)\n", FLAGS_output.c_str(), modes.c_str(),
              FLAGS_truth.c_str(), EffectList(s.effects).c_str());
  return kExitOk;
}

int ExtractCommand(int argc, char** argv) {
  std::string error;
  ExtractSettings settings;
  if (!ReadSettings(&settings, &error)) return Usage(error);
  if (FLAGS_dataset.empty() || FLAGS_output.empty()) {
    return Usage("extract needs --dataset=FRF.json and --output=MODES.json");
  }
  if (!CheckOutputs({{"output", FLAGS_output}, {"report", FLAGS_report}}, Inputs(), &error)) {
    return Usage(error);
  }
  Parameters guess;
  if (!FLAGS_parameters.empty()) {
    LoadError load;
    std::vector<std::string> notes;
    if (!LoadParameters(FLAGS_parameters, {}, &guess, &load, &notes)) return Usage(load.OneLine());
    for (const std::string& note : notes) std::printf("%s%s\n", kParameterNotePrefix, note.c_str());
  }
  ExtractResult x;
  InputError bad;
  if (!ExtractDataset(FLAGS_dataset, settings, &x, &bad,
                      FLAGS_parameters.empty() ? nullptr : &guess)) {
    if (x.status.invalid_input()) return Usage(bad.line);
    std::fprintf(stderr, "ringid: extract: %s\n", bad.line.c_str());
    return kExitFailure;
  }
  std::printf("%9s %10s %7s %8s %7s %7s %-22s %s\n", "condition", "Hz", "sd Hz", "zeta", "sd",
              "stable", "label", "shape");
  for (const ExtractedPole& p : x.poles) {
    std::printf("%9d %10.3f %7.3f %8.4f %7.4f %7d %-22s %s\n", p.condition, p.frequency_hz,
                p.frequency_sigma_hz.value_or(NAN), p.damping_ratio, p.damping_sigma.value_or(NAN),
                p.stable_orders, p.label ? LabelName(*p.label) : "(not kept)",
                !p.label ? "" : p.shape ? "on the model's coordinates" : "none: the outputs do not determine it");
  }
  for (const std::string& note : x.notes) std::printf("note: %s\n", note.c_str());
  if (!x.routes.empty()) {
    std::printf("\nthe two routes: identify on the FRFs and on these modes (masses known)\n"
                "%-12s %12s %10s %12s %10s %8s %7s\n", "parameter", "direct", "std", "modal",
                "std", "diff/sd", "ratio");
    for (const RouteRow& r : x.routes) {
      std::printf("%-12s %12.5g %10.3g %12.5g %10.3g %8.2f %7.2g\n", r.parameter.c_str(), r.direct,
                  r.direct_std, r.modal, r.modal_std, r.DifferenceSd(), r.StdRatio());
    }
  }
  std::vector<std::pair<std::string, std::string>> files = {{FLAGS_output, DatasetToJson(x.dataset)}};
  if (!FLAGS_report.empty()) {
    files.emplace_back(FLAGS_report, ReportText(ExtractReport{ThisRun(argc, argv, std::nullopt),
                                                              ExtractBodyOf(x, FLAGS_dataset)}));
  }
  if (!WriteFilesAtomically(files, &error)) return Usage(error);
  const std::string report = FLAGS_report.empty() ? "" : " and " + FLAGS_report;
  std::printf("wrote %s (%zu modes from %s)%s\n", FLAGS_output.c_str(), x.dataset.modes.size(),
              FLAGS_dataset.c_str(), report.c_str());
  return kExitOk;
}

int DiagnoseCommand(int argc, char** argv) {
  std::string error;
  DiagnoseSettings settings;
  DiagnoseOptions o;
  if (!ReadDiagnoseOptions(&settings, &o, &error)) return Usage(error);
  if (!FLAGS_output_dir.empty()) {
    const RigidRingModel baseline(settings.fit.effects);
    return Campaign(
        argc, argv, ReportKind::kDiagnose, baseline, settings.fit,
        [&](const Dataset& d, const std::string& file) {
          DiagnosisResult r;
          Diagnose(baseline, d, o, &r);
          return CampaignItem{
              ReportText(DiagnoseReport{ThisRun(argc, argv, settings.fit.seed, file), {d.name, r}}),
              DiagnoseRow(r)};
        });
  }
  Dataset d;
  if (!ReadFitDataset(settings.fit, &d, &error, true)) return Usage(error);
  const RigidRingModel baseline(settings.fit.effects);
  DiagnosisResult r;
  {
    Progress progress("diagnose", 0, kProgressAfterSeconds);
    o.on_step = [&](int done, int total) { progress.Set(done, total); };
    Diagnose(baseline, d, o, &r);
  }
  return Finish<DiagnoseReport>(argc, argv, d, r);
}

int BenchCommand(int argc, char** argv) {
  std::string error;
  if (FLAGS_replicates < 1) return Usage("--replicates: must be at least 1");
  if (!CheckOutputs({{"output", FLAGS_output}, {"markdown", FLAGS_markdown}}, {}, &error)) {
    return Usage(error);
  }
  SuiteOptions o;
  if (!ReadFlag("derivatives", &o.derivatives, &error)) return Usage(error);
  if (!ReadFlag("starts", &o.starts, &error)) return Usage(error);
  o.replicates = FLAGS_replicates;
  o.seed = static_cast<unsigned>(SeedFlag());
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
  const SuiteOutput r = suite->run(o, ThisRun(argc, argv, SeedFlag()));
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

// A campaign's flags.
const std::vector<std::string> kCampaignFlags = {"output_dir", "jobs", "shard", "force",
                                                 "keep_going"};

int SchemaCommand(int, char**) {
  std::fputs(ReportsMarkdown().c_str(), stdout);
  return kExitOk;
}

int InputsCommand(int, char**) {
  std::fputs(InputsMarkdown().c_str(), stdout);
  return kExitOk;
}

int ReferenceCommand(int, char**) {
  std::fputs(ReferenceMarkdown().c_str(), stdout);
  return kExitOk;
}

const std::vector<Command>& Commands();

// As any installation says it: where this one found the paper's data (bench's
// summary) is PREFIX/share/ringid/datasets/paper.
int CommandsCommand(int, char**) {
  std::string md = CommandsMarkdown(Commands());
  const std::string here = DataDir() + "/datasets/paper";
  const std::string any = "PREFIX/share/ringid/datasets/paper";
  for (size_t at = md.find(here); at != std::string::npos; at = md.find(here, at + any.size())) {
    md.replace(at, here.size(), any);
  }
  std::fputs(md.c_str(), stdout);
  return kExitOk;
}

// Every command: what it needs, what it does, the flags it takes (the one list
// SetFlags and --help read) and what runs it.
const std::vector<Command>& Commands() {
  static const std::vector<Command> commands = {
      {"predict", "--parameters=FILE | --dataset=FILE",
       "modes of a parameter set, as a table and JSON; a FILE.tir is read as\n"
       "MF-Swift's rigid-ring part (docs/tir.md), the rest given by --set",
       PredictFlags(), Predict, ""},
      {"identify", "--dataset=FILE",
       "fit parameters to a dataset, with covariance and identifiability;\n"
       "with --output_dir, a campaign over many datasets (--dataset=FILE,DIR,...):\n"
       "one report per dataset, a summary table and DIR/campaign.json\n"
       "(campaign.I-of-N.json for a --shard)",
       Joined(Joined(FitFlags(), {"save_parameters"}), kCampaignFlags), IdentifyCommand},
      {"identifiability", "--dataset=FILE",
       "what the data determine at the fitted point: rank, classes, Wald and\n"
       "profile intervals, free combinations, collinear pairs, identifiable\n"
       "subset, experiment advice",
       Joined(FitFlags(), {"profiles"}), IdentifiabilityCommand},
      {"compare", "--dataset=FILE",
       "Levenberg-Marquardt and the Downhill Simplex from the same --starts:\n"
       "success rate, final costs, evaluations, time per fit",
       FitFlags(), CompareCommand},
      {"simulate", "--parameters=FILE --output=DATASET --truth=FILE",
       "a dataset measured from a parameter set, optionally with effects (each\n"
       "sized by --set or --shift), and a separate truth file; one condition per\n"
       "speed and load, and several give a format-2 dataset. With --frf=SPEC, each\n"
       "condition's FRFs as the spec lays them out (format 3). With --lug_forces=FILE,\n"
       "the axle's response to those lug forces at --speeds (docs/forces.md)",
       SimulateFlags(), SimulateCommand, "lug_forces"},
      {"extract", "--dataset=FRF.json --output=MODES.json",
       "the modes in a dataset's FRFs (pLSCF's stabilisation diagram and physical\n"
       "poles, refined by maximum likelihood with standard errors) as a modal\n"
       "dataset identify reads, named as the model names them at the fit to the\n"
       "FRFs from the dataset's initial values (or --parameters: weighed masses,\n"
       "say); masses made known (modes carry no modal mass); the two routes side\n"
       "by side. --report=FILE: the diagram, the poles and each FRF against its\n"
       "LSFD synthesis with its FRAC (ringid report draws it)",
       ExtractFlags(), ExtractCommand, ""},
      {"poles", "--uff=FILE|--dataset=FILE --output=POLES.json",
       "the physical poles of a test's FRFs alone, without a tire model or labels:\n"
       "frequency, damping ratio and their standard errors, residues and shape per\n"
       "pole (pLSCF's stabilisation diagram at the order the data need, refined by\n"
       "maximum likelihood). --map: units and averages of a UFF file. --report=FILE:\n"
       "the diagram and each FRF against its synthesis (ringid report draws it)",
       PolesFlags(), PolesCommand},
      {"diagnose", "--dataset=FILE",
       "the gap between the calibrated baseline and the data: where it lies,\n"
       "which effect explains it, how far it shrinks; --effects puts effects in\n"
       "the baseline and the others are tried on top; with --output_dir, a\n"
       "campaign as for identify",
       Joined(Joined(FitFlags(), DiagnoseFlags()), kCampaignFlags), DiagnoseCommand},
      {"bench", "--suite=NAME",
       "the accuracy, conditioning and speed suites, on the paper's data installed\n"
       "with ringid, here in " + DataDir() + "/datasets/paper; speed times numeric\n"
       "and analytic derivatives side by side, whatever --derivatives says",
       {"suite", "replicates", "seed", "derivatives", "starts", "output", "markdown"},
       BenchCommand},
      {"report", "--input=REPORT.json --output=FILE.html",
       "any JSON report of ringid as one self-contained HTML page: tables and\n"
       "figures (SVG drawn by gnuplot, package gnuplot-nox)",
       {"input", "output", "figures_dir"}, ReportCommand},
      {"export", "--parameters=FILE --format=tir|json",
       "a parameter set (ringid-parameters/1 or a .tir), with --set over it, as\n"
       "the rigid-ring part of an MF-Swift .tir or as ringid-parameters/1 JSON;\n"
       "what maps to what and what a .tir cannot hold: docs/tir.md",
       {"parameters", "set", "format", "output"}, ExportCommand, ""},
      {"import", "--uff=FILE [--map=FILE --output=DATASET]",
       "a test lab's UFF modes (dataset 55) as a dataset, by a map of nodes to\n"
       "degrees of freedom; without --map, what the file holds (docs/uff.md)",
       {"uff", "map", "parameters", "set", "output"}, ImportCommand, ""},
      {"merge", "--output_dir=DIR",
       "the shard summaries DIR/campaign.I-of-N.json of one campaign as\n"
       "DIR/campaign.json and its page DIR/campaign.html",
       {"output_dir"}, MergeCommand},
      {"forces", "--parameters=FILE --dataset=FILE",
       "the lug forces at the contact from the axle's response at the lug orders\n"
       "(a response dataset, ringid-lug-response/1); FILE of --parameters an identify\n"
       "report (its covariance gives std_total), a parameter set or a .tir (the rest\n"
       "by --set): docs/forces.md",
       ForcesFlags(), ForcesCommand, ""},
      {"schema", "", "every report's fields and their types, as Markdown (docs/reports.md)", {},
       SchemaCommand},
      {"inputs", "", "every input file's fields and their types, as Markdown (docs/inputs.md)", {},
       InputsCommand},
      {"reference", "",
       "parameters, degrees of freedom, labels and effects with their units, as\n"
       "Markdown (docs/reference.md)",
       {}, ReferenceCommand},
      {"commands", "", "every command with its flags, as Markdown (docs/commands.md)", {},
       CommandsCommand},
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
  std::fputs(CommandHelp(*c, Commands()).c_str(), stdout);
  return kExitOk;
}

// Runs argv[1] with the flags of argv[2..].
int Run(int argc, char** argv) {
  const std::string name = argc > 1 ? argv[1] : "help";
  if (name == "help" || name == "--help" || name == "-h") return HelpCommand(argc, argv);
  const Command* command = FindCommand(Commands(), name);
  if (!command) return Usage(UnknownCommand(name));
  if (WantsHelp(argc, argv)) {
    std::fputs(CommandHelp(*command, Commands()).c_str(), stdout);
    return kExitOk;
  }
  std::string error;
  if (!SetFlags(argc, argv, *command, Commands(), &error)) return Usage(error);
  try {
    return command->run(argc, argv);
  } catch (const std::exception& e) {  // out of memory, say: one line, no file half-written
    std::fprintf(stderr, "ringid: %s\n", e.what());
    return kExitFailure;
  }
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
