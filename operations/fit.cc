#include "operations/fit.h"

#include <algorithm>

#include "estimation/parallel.h"

namespace ringid {

bool FitOptionsOf(const FitSettings& s, int jobs, IdentifyOptions* o, std::string* error) {
  *o = IdentifyOptions{};
  o->method = s.method;
  o->starts = s.starts;
  if (s.max_iterations < 1) {
    *error = "--max_iterations: must be at least 1";
    return false;
  }
  o->max_iterations = s.max_iterations;
  o->seed = static_cast<unsigned>(s.seed);
  o->residuals.frequency_weighting = s.weighting;
  o->residuals.relative_sigma = s.relative_sigma;
  o->residuals.use_shapes = s.shapes;
  o->residuals.use_damping = s.damping;
  o->residuals.shape_convention = s.shape_convention;
  o->residuals.derivatives = s.derivatives;
  if (!s.band.values.empty()) {
    const std::vector<double>& b = s.band.values;
    if (b.size() != 2 || !(b[0] < b[1])) {
      *error = "--band: LO,HI in Hz with LO < HI";
      return false;
    }
    o->residuals.band_low_hz = b[0];
    o->residuals.band_high_hz = b[1];
  }
  o->bounds = s.bounds;
  if (s.threads < 0 || s.threads > IdentifyOptions::kMaxThreads) {
    *error = "--threads: must lie in [0, " + std::to_string(IdentifyOptions::kMaxThreads) +
             "] (0: the cores)";
    return false;
  }
  o->threads = s.threads ? s.threads : std::max(1, internal::ThreadsFor(0) / std::max(1, jobs));
  if (!o->IsValid(error)) {
    *error = "bad option: " + *error;
    return false;
  }
  return true;
}

bool DiagnoseOptionsOf(const DiagnoseSettings& s, int jobs, DiagnoseOptions* o,
                       std::string* error) {
  if (!(s.level > 0 && s.level < 1)) {
    *error = "--level: must lie in (0, 1)";
    return false;
  }
  if (!(s.screen > 0 && s.screen <= 1)) {
    *error = "--screen: must lie in (0, 1]";
    return false;
  }
  *o = DiagnoseOptions{};
  o->effect_significance = s.level;
  o->screen_significance = s.screen;
  return FitOptionsOf(s.fit, jobs, &o->fit, error);
}

bool IdentifiabilityOptionsOf(const IdentifiabilitySettings& s, int jobs,
                              IdentifiabilityOptions* o, std::string* error) {
  *o = IdentifiabilityOptions{};
  o->profiles = s.profiles;
  return FitOptionsOf(s.fit, jobs, &o->fit, error);
}

bool ApplyFix(const std::vector<Param>& fix, Dataset* d, std::string* error) {
  if (!FixParameters(fix, d, error)) {
    *error = "--" + *error;
    return false;
  }
  return true;
}

ParameterSet IdentifiedParameterSet(const IdentifyResult& s, const std::string& name,
                                    const std::string& description) {
  ParameterSet set{name, description, {}};
  for (const ParameterEstimate& e : s.estimates) {
    if (!e.key.condition.empty()) continue;  // a set holds one tire's shared values
    ParameterValue& q = set.parameters[e.param()];
    q.value = e.value;
    q.std = e.std;
    // What the data determined, which export marks in a .tir (LoadParameterSet).
    if (e.free || e.tied_to) q.identifiable = ToString(e.identifiable);
    q.condition = e.Condition();
  }
  return set;
}

}  // namespace ringid
