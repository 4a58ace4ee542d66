#include "estimation/label_by_fit.h"

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "model/rigid_ring_model.h"

namespace ringid {
namespace {

// A warning where the labels kept rest on a poor fit (label_by_fit.h): the
// fit's p-value, and each mode the model named by a shape it hardly matches.
// `numbers`: the modes' UFF numbers.
void PoorLabels(const std::vector<int>& numbers, const std::optional<FitQuality>& fit,
                UffImport* out) {
  std::string poor;
  char item[200];
  if (fit && fit->p_value && *fit->p_value < kPoorLabelFitP) {
    std::snprintf(item, sizeof item, "the labelling fit's chi-square is %.4g on %d degrees of "
                  "freedom (p = %.2g < %g)", fit->chi_square, fit->degrees_of_freedom,
                  *fit->p_value, kPoorLabelFitP);
    poor = item;
  }
  for (const UffModelLabel& l : out->by_model) {
    if (!l.mac || *l.mac >= kPoorLabelMac) continue;
    const MeasuredMode& m = out->dataset.modes[l.mode];
    std::snprintf(item, sizeof item, "mode %d (%.4g Hz) is named %s by a shape of MAC %.3f < %g",
                  l.mode < static_cast<int>(numbers.size()) ? numbers[l.mode] : l.mode + 1,
                  m.frequency_hz, LabelName(m.label), *l.mac, kPoorLabelMac);
    poor += (poor.empty() ? "" : "; ") + std::string(item);
  }
  if (poor.empty()) return;
  out->warnings.push_back("the labels rest on a poor match: " + poor +
                          ". Check the map's nodes, directions and signs against the test, or "
                          "give the labels you know in the map");
}

}  // namespace

bool UffToDatasetLabelledByFit(const UffFile& file, const UffMap& map, const Parameters& guess,
                               const IdentifyOptions& o, UffImport* out, LoadError* error) {
  const ShapeConvention convention = o.residuals.shape_convention;
  if (!UffToDataset(file, map, &guess, out, error, convention)) return false;
  if (out->dataset.modes.size() == map.labels.size()) return true;  // the map named them all
  Dataset checked;  // the loader's rules before anything is fitted
  if (!ParseDataset(DatasetToJson(out->dataset), file.path, &checked, error)) return false;
  const Dataset at_guess = out->dataset;
  std::vector<std::string> said;  // every round's, kept past the rounds' own notes
  std::optional<FitQuality> last;  // of the fit that named the labels kept
  bool settled = false;
  for (int round = 1; round <= 3 && !settled; ++round) {
    const std::string names = round == 1 ? "the model's at --parameters"
                                         : "round " + std::to_string(round - 1) + "'s";
    IdentifyResult fit;
    Identify(RigidRingModel(), out->dataset, o, &fit);
    UffImport again;
    LoadError why;
    if (!fit.status.ok()) {
      said.push_back("labels: the fit of round " + std::to_string(round) + " failed (" +
                     fit.status.message + "); the names are " + names);
      break;
    }
    if (!UffToDataset(file, map, &fit.parameters, &again, &why, convention)) {
      said.push_back("labels: at round " + std::to_string(round) + "'s fitted parameters, " +
                     why.OneLine() + "; the names are " + names);
      break;
    }
    settled = true;
    for (size_t i = 0; i < again.dataset.modes.size(); ++i) {
      settled = settled && again.dataset.modes[i].label == out->dataset.modes[i].label;
    }
    again.dataset.known = at_guess.known;
    again.dataset.initial = at_guess.initial;
    *out = std::move(again);
    last = fit.fit;
    char line[200];
    std::snprintf(line, sizeof line, "labels: round %d, by the model at the parameters fitted "
                  "from --parameters (cost %.3g)%s", round, fit.cost,
                  settled ? ": no name changed" : "");
    said.push_back(line);
    if (!settled && round == 3) said.push_back("labels: still changing after 3 rounds; give them in the map");
  }
  out->notes.insert(out->notes.end(), said.begin(), said.end());
  // By the UFF mode number, as the map's labels name modes.
  std::vector<int> numbers;
  for (const UffModalData& m : file.modal_data) {
    if (m.IsNormalMode() || m.IsComplexMode()) numbers.push_back(m.mode_number);
  }
  PoorLabels(numbers, last, out);
  for (size_t i = 0; i < at_guess.modes.size() && i < numbers.size(); ++i) {
    const ModeLabel before = at_guess.modes[i].label, now = out->dataset.modes[i].label;
    if (before == now) continue;
    char line[200];
    std::snprintf(line, sizeof line, "labels: mode %d (%.4g Hz) is %s, %s by the model at "
                  "--parameters", numbers[i], at_guess.modes[i].frequency_hz, LabelName(now),
                  LabelName(before));
    out->notes.push_back(line);
  }
  return true;
}

}  // namespace ringid
