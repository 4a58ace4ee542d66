#include "operations/simulate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>

#include "datasets/synthetic.h"
#include "operations/model_parameters.h"

namespace ringid {

bool SimulateDataset(const std::string& parameters, const std::string& output,
                     const SimulateSettings& s, Simulated* out, InputError* error, bool* failed) {
  *failed = false;
  const auto Fail = [&](const std::string& line) {
    *error = InputError::Option(line);
    return false;
  };
  for (double v : {s.frequency_noise, s.damping_noise, s.shape_noise, s.static_noise,
                   s.prior_spread}) {
    if (!(v >= 0) || !std::isfinite(v)) {
      return Fail("noise levels and --prior_spread must be finite and not negative");
    }
  }
  Parameters truth;
  LoadError load;
  if (!LoadParameterSet(parameters, &truth, &load)) {
    *error = InputError::Of(load);
    return false;
  }
  std::string line;
  if (!CheckEffectSizes(s.effects, s.set, truth, s.shift, &line)) return Fail(line);
  for (const auto& [p, v] : s.set) truth[p] = v;
  if (s.shift != 0) truth[s.effects[0]->size()] = 0;  // set below
  const RigidRingModel model(s.effects);
  const std::vector<Param> missing = Missing(model, truth);
  if (!missing.empty()) {
    *error = MissingParameters(parameters, missing);
    return false;
  }
  if (s.shift != 0) {
    const Param p = s.effects[0]->size();
    truth[p] = ValueForShift(truth, *s.effects[0], p, s.shift);
    if (!(LargestShift(truth, *s.effects[0], p, truth[p]) < 2 * s.shift)) {
      *failed = true;
      char text[200];
      std::snprintf(text, sizeof text, "%s cannot shift a frequency by %g", s.effects[0]->name(),
                    s.shift);
      return Fail(text);
    }
  }
  std::mt19937_64 rng(static_cast<unsigned>(s.seed));
  Dataset d = PlanSimulation(truth, s.prior_spread, s.speeds.values, s.loads.values, &rng);
  for (Param q : s.fix) {  // written known, at the truth
    if (Info(q).group == Group::kEffect ||
        std::find(d.per_condition.begin(), d.per_condition.end(), q) != d.per_condition.end()) {
      return Fail("--fix: simulate writes " + std::string(ParamName(q)) + " known already");
    }
    d.known[q] = truth[q];
    d.initial.erase(q);
    d.ties.erase(q);
  }
  d.name = std::filesystem::path(output).stem().string();
  d.description = "simulated by ringid from " + parameters + "; the truth is in a separate file";
  SimulateOptions so;
  so.frequency_noise = s.frequency_noise;
  so.damping_noise = s.damping_noise;
  so.shape_noise = s.shape_noise;
  so.static_noise = s.static_noise;
  so.statics = s.statics;
  if (!Simulate(model, truth, so, &rng, &d, &line)) {
    *failed = true;
    return Fail(line);
  }
  out->truth = MakeTruth(model, truth, d, output);
  out->effects = s.effects;
  out->dataset = std::move(d);
  return true;
}

}  // namespace ringid
