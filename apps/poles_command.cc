// `ringid poles` (apps/poles_command.h).
#include "apps/poles_command.h"

#include <cmath>
#include <cstdio>

#include "apps/flags.h"
#include "apps/reports.h"
#include "operations/files.h"
#include "operations/poles.h"

namespace ringid {

const std::vector<std::string>& PolesFlags() {
  static const std::vector<std::string> flags =
      Joined({"uff", "map", "dataset", "output", "report"}, OptionNames(OptionsOf<PolesSettings>()));
  return flags;
}

int PolesCommand(int argc, char** argv) {
  std::string error;
  PolesSettings settings;
  if (!ReadSettings(&settings, &error)) return Usage(error);
  if (FLAGS_output.empty()) return Usage("poles needs --output=POLES.json");
  std::vector<std::pair<std::string, std::string>> inputs = Inputs();
  if (!FLAGS_uff.empty()) inputs.emplace_back("uff", FLAGS_uff);
  if (!FLAGS_map.empty()) inputs.emplace_back("map", FLAGS_map);
  if (!CheckOutputs({{"output", FLAGS_output}, {"report", FLAGS_report}}, inputs, &error)) {
    return Usage(error);
  }
  PolesRun run;
  InputError bad;
  if (!FindFilePoles({FLAGS_uff, FLAGS_map, FLAGS_dataset}, settings, &run, &bad)) {
    if (!run.body.status.ok() && !run.body.status.message.empty()) {
      std::fprintf(stderr, "ringid: poles: %s\n", bad.line.c_str());
      return kExitFailure;
    }
    return Usage(bad.line);
  }
  const PolesFile& f = run.file;
  for (size_t c = 0; c < f.conditions.size(); ++c) {
    const PolesCondition& pc = f.conditions[c];
    std::printf("%s: %d FRFs, %d lines %.6g-%.6g Hz, orders 1-%d, noise %s, residues in %s\n",
                pc.name.c_str(), pc.functions, pc.lines, pc.low_hz, pc.high_hz, pc.max_order,
                pc.noise.c_str(), pc.units.c_str());
    std::printf("%12s %10s %9s %9s %7s\n", "Hz", "sd Hz", "zeta", "sd", "stable");
    for (const FoundPole& p : f.poles) {
      if (p.condition != static_cast<int>(c)) continue;
      std::printf("%12.4f %10.4f %9.5f %9.5f %7d\n", p.frequency_hz, p.frequency_sigma_hz.value_or(NAN),
                  p.damping_ratio, p.damping_sigma.value_or(NAN), p.stable_orders);
    }
  }
  for (const std::string& note : f.notes) std::printf("note: %s\n", note.c_str());
  std::vector<std::pair<std::string, std::string>> files = {
      {FLAGS_output, JsonWriter::ToJson(f).dump(2) + "\n"}};
  if (!FLAGS_report.empty()) {
    files.emplace_back(FLAGS_report, ReportText(PolesReport{ThisRun(argc, argv, std::nullopt), run.body}));
  }
  if (!WriteFilesAtomically(files, &error)) return Usage(error);
  std::printf("wrote %s (%zu poles)%s\n", FLAGS_output.c_str(), f.poles.size(),
              FLAGS_report.empty() ? "" : (" and " + FLAGS_report).c_str());
  return kExitOk;
}

}  // namespace ringid
