#include "apps/report_command.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "apps/command_line.h"
#include "apps/flags.h"
#include "apps/help.h"
#include "apps/html_report.h"
#include "apps/interrupt.h"
#include "apps/reports.h"
#include "datasets/parameter_files.h"
#include "datasets/tir_parameters.h"
#include "model/spelling.h"

namespace ringid {

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
  ParameterValues set;
  if (!ParseSet(&set, &error)) return Usage(error);
  Parameters p;
  LoadError load;
  Undetermined undetermined;  // from an identify report's or --save_parameters' classes
  std::vector<std::string> notes;
  if (!LoadParameters(FLAGS_parameters, set, &p, &load, &notes, &undetermined)) {
    return Usage(load.OneLine());
  }
  // Notes, not errors: beside "wrote", or on standard error when standard
  // output is the file.
  for (const std::string& note : notes) {
    std::fprintf(FLAGS_output.empty() ? stderr : stdout, "%s%s\n", kParameterNotePrefix,
                 note.c_str());
  }
  const std::string set_text = FlagText("set");
  const std::string source =
      FLAGS_parameters + (set_text.empty() ? "" : " with --set=" + set_text);
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

}  // namespace ringid
