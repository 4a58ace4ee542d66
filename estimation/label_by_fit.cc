#include "estimation/label_by_fit.h"

#include <cstdio>
#include <string>
#include <vector>

#include "model/rigid_ring_model.h"

namespace ringid {

bool UffToDatasetLabelledByFit(const UffFile& file, const UffMap& map, const Parameters& guess,
                               const IdentifyOptions& o, UffImport* out, LoadError* error) {
  if (!UffToDataset(file, map, &guess, out, error)) return false;
  if (out->dataset.modes.size() == map.labels.size()) return true;  // the map named them all
  const Dataset at_guess = out->dataset;
  bool settled = false;
  for (int round = 1; round <= 3 && !settled; ++round) {
    IdentifyResult fit;
    Identify(RigidRingModel(), out->dataset, o, &fit);
    if (!fit.status.ok()) {
      out->notes.push_back("labels: by the model at --parameters; the fit to label them by the "
                           "fitted model failed: " + fit.status.message);
      return true;
    }
    UffImport again;
    LoadError why;
    if (!UffToDataset(file, map, &fit.parameters, &again, &why)) {
      out->notes.push_back("labels: by the model at --parameters; at the fitted parameters: " +
                           why.OneLine());
      return true;
    }
    settled = true;
    for (size_t i = 0; i < again.dataset.modes.size(); ++i) {
      settled = settled && again.dataset.modes[i].label == out->dataset.modes[i].label;
    }
    again.dataset.known = at_guess.known;
    again.dataset.initial = at_guess.initial;
    *out = std::move(again);
    char line[200];
    std::snprintf(line, sizeof line, "labels: by the model at the fitted parameters (identify from "
                  "--parameters, cost %.3g; round %d%s)", fit.cost, round,
                  settled ? ", labels unchanged" : "");
    out->notes.push_back(line);
  }
  if (!settled) out->notes.push_back("labels: still changing after 3 rounds; give them in the map");
  for (size_t i = 0; i < at_guess.modes.size(); ++i) {
    const ModeLabel before = at_guess.modes[i].label, now = out->dataset.modes[i].label;
    if (before == now) continue;
    char line[200];
    std::snprintf(line, sizeof line, "labels: mode %zu (%.4g Hz) is %s by the fitted model, %s "
                  "by the model at --parameters", i + 1, at_guess.modes[i].frequency_hz,
                  LabelName(now), LabelName(before));
    out->notes.push_back(line);
  }
  return true;
}

}  // namespace ringid
