#include "apps/import_command.h"

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <map>
#include <string>
#include <utility>

#include "apps/flags.h"
#include "apps/reports.h"
#include "datasets/tir_parameters.h"
#include "datasets/uff_dataset.h"
#include "datasets/uff_frf.h"
#include "estimation/label_by_fit.h"

namespace ringid {
namespace {

// The nodes of the modes (dataset 55) and the directions each holds, as a
// map's channels name them: runs of consecutive nodes alike on one line.
void ListMappable(const UffFile& f) {
  int modes = 0;
  std::map<int, std::pair<size_t, int>> held;  // node -> (values, modes holding it)
  for (const UffModalData& m : f.modal_data) {
    if (!m.IsNormalMode() && !m.IsComplexMode()) continue;
    ++modes;
    for (const UffNodeValues& n : m.nodes) {
      auto& [values, in] = held[n.label];
      values = std::max(values, n.values.size());
      ++in;
    }
  }
  if (held.empty()) return;
  std::printf("nodes of the modes, as a map's channels name them (direction 1-3: x, y, z; "
              "4-6: rotations about them):\n");
  const auto line = [&](int first, int last, std::pair<size_t, int> h) {
    const std::string nodes = first == last ? "node " + std::to_string(first)
                                            : "nodes " + std::to_string(first) + "-" +
                                                  std::to_string(last);
    std::printf("  %-17s directions 1-%zu, in %s\n", nodes.c_str(), h.first,
                h.second == modes ? "every mode"
                                  : (std::to_string(h.second) + " of " + std::to_string(modes) +
                                     " modes").c_str());
  };
  auto run = held.begin();
  int last = run->first;
  for (auto it = std::next(held.begin()); it != held.end(); ++it) {
    if (it->first == last + 1 && it->second == run->second) {
      last = it->first;
      continue;
    }
    line(run->first, last, run->second);
    run = it;
    last = it->first;
  }
  line(run->first, last, run->second);
}

// What the file holds: its datasets, modes, functions, units and nodes.
void List(const UffFile& f) {
  std::map<int, int> read, skipped;
  for (const UffDatasetInfo& d : f.datasets) ++(d.skipped ? skipped : read)[d.number];
  std::printf("%s: %zu datasets\n", f.path.c_str(), f.datasets.size());
  for (const auto& [number, n] : read) std::printf("  dataset %-5d x%d read\n", number, n);
  for (const auto& [number, n] : skipped) std::printf("  dataset %-5d x%d skipped (not read by ringid)\n", number, n);
  for (const UffUnits& u : f.units) {
    std::printf("units (164): %d '%s', length factor %g, force factor %g\n", u.code,
                u.description.c_str(), u.length_factor, u.force_factor);
  }
  for (const UffNodes& n : f.nodes) std::printf("nodes (15): %zu\n", n.nodes.size());
  ListMappable(f);
  if (!f.modal_data.empty()) std::printf("modes (55):\n  %6s %12s %10s %6s %s\n", "mode", "Hz", "zeta", "nodes", "analysis");
  for (const UffModalData& m : f.modal_data) {
    const std::optional<double> hz = m.FrequencyHz(), zeta = m.DampingRatio();
    std::printf("  %6d %12.5g %10.4g %6zu %s\n", m.mode_number, hz.value_or(NAN),
                zeta.value_or(NAN), m.nodes.size(),
                m.IsNormalMode() ? "normal" : m.IsComplexMode() ? "complex" : "not a mode");
  }
  if (!f.functions.empty()) {
    std::printf("functions (58%s): a ringid-uff-map/2's points import the FRFs (type 4), with "
                "sigma from coherences (type 6)\n  %5s %12s %12s %8s %s\n",
                f.functions.front().binary ? "b" : "", "type", "response", "reference", "points",
                "ordinate / abscissa");
  }
  for (const UffFunction& fn : f.functions) {
    std::printf("  %5d %8d:%+d %8d:%+d %8lld %s [%s] / %s [%s]\n", fn.function_type,
                fn.response_node, fn.response_direction, fn.reference_node,
                fn.reference_direction, static_cast<long long>(fn.points),
                fn.ordinate.label.c_str(), fn.ordinate.units_label.c_str(),
                fn.abscissa.label.c_str(), fn.abscissa.units_label.c_str());
  }
}

}  // namespace

int ImportCommand(int argc, char** argv) {
  std::string error;
  if (FLAGS_uff.empty()) return Usage("import needs --uff=FILE");
  if (FLAGS_map.empty() != FLAGS_output.empty()) {
    return Usage("import writes a dataset with --map=FILE and --output=DATASET, and lists the "
                 "file without either");
  }
  if (!CheckOutputs({{"output", FLAGS_output}}, Inputs(), &error)) return Usage(error);
  LoadError load;
  UffFile file;
  if (!LoadUff(FLAGS_uff, &file, &load)) return Usage(load.OneLine());
  if (FLAGS_map.empty()) {
    List(file);
    return kExitOk;
  }
  UffMap map;
  if (!LoadUffMap(FLAGS_map, &map, &load)) return Usage(load.OneLine());
  std::map<Param, double> set;
  if (!ParseSet(&set, &error)) return Usage(error);
  if (!set.empty() && FLAGS_parameters.empty()) return Usage("--set: needs --parameters=FILE");
  Parameters p;
  std::vector<std::string> notes;
  if (!FLAGS_parameters.empty() && !LoadParameters(FLAGS_parameters, set, &p, &load, &notes)) {
    return Usage(load.OneLine());
  }
  for (const std::string& note : notes) std::printf("%s%s\n", kParameterNotePrefix, note.c_str());
  UffImport in;
  IdentifyOptions fit;  // to label by the fitted model (estimation/label_by_fit.h)
  fit.residuals.derivatives = Derivatives::kAnalytic;
  if (!map.channels.empty() &&
      !(FLAGS_parameters.empty() ? UffToDataset(file, map, nullptr, &in, &load)
                                 : UffToDatasetLabelledByFit(file, map, p, fit, &in, &load))) {
    return Usage(load.OneLine());
  }
  if (!map.points.empty()) {  // a ringid-uff-map/2's FRFs (datasets/uff_frf.h)
    if (!AddUffFrfs(file, map, &in, &load)) return Usage(load.OneLine());
    if (map.channels.empty() && !FLAGS_parameters.empty()) WriteUffParameters(p, map, &in.dataset);
  }
  // The dataset written must read back: the loader's rules are the test.
  const std::string text = DatasetToJson(in.dataset);
  Dataset back;
  if (!ParseDataset(text, FLAGS_output, &back, &load)) return Usage(load.OneLine());
  for (const std::string& note : in.notes) std::printf("%s\n", note.c_str());
  for (const std::string& w : in.warnings) std::printf("warning: %s\n", w.c_str());
  const int rc = Write(FLAGS_output, text);
  size_t frfs = 0, conditions = 0;
  for (const Condition& c : in.dataset.conditions) {
    if (c.frf) frfs += c.frf->functions.size();
    conditions += c.frf.has_value();
  }
  if (rc == kExitOk && frfs == 0) {
    std::printf("wrote %s (%zu modes from %s)\n", FLAGS_output.c_str(), in.dataset.modes.size(),
                FLAGS_uff.c_str());
  } else if (rc == kExitOk) {
    std::printf("wrote %s (%zu FRF%s in %zu condition%s%s from %s)\n", FLAGS_output.c_str(), frfs,
                frfs == 1 ? "" : "s", conditions, conditions == 1 ? "" : "s",
                in.dataset.modes.empty()
                    ? ""
                    : (", and " + std::to_string(in.dataset.modes.size()) + " modes").c_str(),
                FLAGS_uff.c_str());
  }
  (void)argc;
  (void)argv;
  return rc;
}

}  // namespace ringid
