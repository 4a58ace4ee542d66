#include "operations/forces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "datasets/file_kind.h"
#include "datasets/parameter_files.h"
#include "datasets/tir_parameters.h"
#include "operations/model_parameters.h"
#include "operations/option_text.h"
#include "report/report.h"

namespace ringid {

bool ReadForceParameters(const std::string& path, const ParameterValues& set,
                         ForceParameters* fp, InputError* error,
                         std::vector<std::string>* notes) {
  std::string text;
  Json json;
  LoadError load;
  if (!ReadInputFile(path, &text, &load)) {
    *error = InputError::Of(load);
    return false;
  }
  if (ParseJsonInput(text, &json, &load) && SniffJson(json).kind == FileKind::kReport) {
    if (!NoSetOverFit(set, path, error)) return false;
    IdentifyReport report;
    std::string why;
    if (!ReadReport(json, &report, &why)) {
      SetArchiveError(why, &load);
      *error = InputError::Of(load);
      return false;
    }
    if (!report.body.result.status.ok()) {  // a failed fit's values are not an estimate
      load.field = "status";
      load.message = "the identification did not succeed (" +
                     std::string(ToString(report.body.result.status.outcome)) + ": " +
                     report.body.result.status.message + "); its values are no estimate";
      *error = InputError::Of(load);
      return false;
    }
    *fp = ForceParameters::From(report.body.result);
    return true;
  }
  *fp = ForceParameters{};
  load = LoadError{};
  if (!LoadParameters(path, set, &fp->shared, &load, notes)) {
    *error = InputError::Of(load);
    return false;
  }
  fp->source = kParameterSetForces;
  return true;
}

bool NoSetOverFit(const ParameterValues& set, const std::string& source, InputError* error) {
  if (set.empty()) return true;
  *error = InputError::Option("--set: not over an identify report (" + source +
                              "): its values carry the fit's covariance; give a parameter set "
                              "or a .tir");
  return false;
}

bool ForcesOf(const ForceParameters& fp, const ResponseDataset& data, const ForcesSettings& s,
              const std::string& parameters, const std::string& dataset, ForcesResult* r,
              InputError* error, const std::vector<std::string>& notes) {
  const RigidRingModel model(s.effects);
  // The forces need the model that was fitted: an effect the parameters move
  // off its baseline (0; m_a, the hub's mass, has none) asks for that effect.
  for (const Effect* e : EffectCatalogue()) {
    if (std::find(s.effects.begin(), s.effects.end(), e) != s.effects.end()) continue;
    for (Param q : e->parameters()) {
      if (Info(q).domain == Domain::kPositive || !std::isfinite(fp.shared[q]) || fp.shared[q] == 0) {
        continue;
      }
      *error = InputError::Of({parameters, "parameters." + std::string(ParamName(q)),
                               "a parameter of " + std::string(e->name()) +
                                   ", which the model lacks; give --effects=" + e->name() +
                                   " (the forces use the model that was fitted)"});
      return false;
    }
  }
  for (size_t i = 0; i < data.conditions.size(); ++i) {
    const ResponseCondition& c = data.conditions[i];
    const std::vector<Param> missing = Missing(model, fp.In(c));
    if (missing.empty()) continue;
    // A value the fit has per condition, in none of this name.
    std::string fitted;
    for (const auto& [name, values] : fp.by_condition) {
      if (values.IsSet(missing[0])) fitted += (fitted.empty() ? "" : ", ") + name;
    }
    if (fitted.empty()) {
      *error = MissingParameters(parameters, missing, notes);
      return false;
    }
    const std::string q = ParamName(missing[0]);
    *error = InputError::Of({dataset, "conditions[" + std::to_string(i) + "].known." + q,
                             "missing: " + parameters + " fitted " + q + " per condition (" +
                                 fitted + "); name the condition '" + c.name +
                                 "' as one of those, or give its value in known"});
    return false;
  }
  EstimateForces(model, fp, data, ForcesOptions{}, r);
  return true;
}

bool SimulateResponse(const std::string& parameters, const SimulateSettings& s,
                      LugForceSpectrum* spectrum, ResponseDataset* data, InputError* error) {
  if (!(s.response_noise > 0) || !std::isfinite(s.response_noise)) {
    *error = InputError::Option("--response_noise: must be positive (it is each channel's sigma)");
    return false;
  }
  for (double v : s.speeds.values) {
    if (!(v > 0)) {
      *error = InputError::Option("--speeds: bad item '" + OptionText(v) +
                                  "' (each must be a number > 0 in m/s) (a lug order exists "
                                  "only rolling)");
      return false;
    }
  }
  LoadError load;
  Parameters p;
  if (!LoadParameters(parameters, s.set, &p, &load)) {
    *error = InputError::Of(load);
    return false;
  }
  if (!LoadLugForces(s.lug_forces, spectrum, &load)) {
    *error = InputError::Of(load);
    return false;
  }
  const RigidRingModel model(s.effects);
  const std::vector<Param> missing = Missing(model, p);
  if (!missing.empty()) {
    *error = MissingParameters(parameters, missing);
    return false;
  }
  *data = ResponseDataset{};
  data->name = spectrum->name + "_response";
  data->description = "The axle's response to the lug forces of " + s.lug_forces + " under " +
                      parameters + ", simulated by ringid (noise " +
                      std::to_string(s.response_noise) + " of each amplitude, seed " +
                      std::to_string(s.seed) + ").";
  const int orders = spectrum->orders.rbegin()->first;
  std::mt19937_64 rng(s.seed);
  const std::vector<AxleChannel> all = {AxleChannel::kForceX, AxleChannel::kForceZ,
                                        AxleChannel::kForceY, AxleChannel::kMomentX,
                                        AxleChannel::kMomentZ};
  const auto forces = [&](int k) {
    const auto it = spectrum->orders.find(k);
    return it == spectrum->orders.end() ? std::array<Complex, kNumLugForces>{} : it->second;
  };
  std::string why;
  if (!SimulateResponses(model, p, spectrum->lugs_per_revolution, s.speeds.values, orders, all,
                         forces, s.response_noise, &rng, data, &why)) {
    *error = {parameters + ": the model cannot respond: " + why, parameters, "",
              "the model cannot respond: " + why};
    return false;
  }
  return true;
}

}  // namespace ringid
