#include "apps/forces_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>

#include "apps/flags.h"
#include "apps/reports.h"
#include "datasets/file_kind.h"
#include "datasets/response_dataset.h"
#include "datasets/tir_parameters.h"
#include "estimation/forces.h"
#include "report/report.h"

namespace ringid {

bool ReadForceParameters(const std::string& path, ForceParameters* fp, LoadError* error,
                         const std::map<Param, double>& set, std::vector<std::string>* notes) {
  std::string text;
  Json json;
  if (!ReadInputFile(path, &text, error)) return false;
  if (ParseJsonInput(text, &json, error) && SniffJson(json).kind == FileKind::kReport) {
    if (!set.empty()) {  // the values and their covariance are the fit's
      error->file = "--set";
      error->message = "not over an identify report (" + path + "): its values carry the fit's "
                       "covariance; give a parameter set or a .tir";
      return false;
    }
    IdentifyReport report;
    std::string why;
    if (!ReadReport(json, &report, &why)) {
      SetArchiveError(why, error);
      return false;
    }
    if (!report.body.result.status.ok()) {  // a failed fit's values are not an estimate
      error->field = "status";
      error->message = "the identification did not succeed (" +
                       std::string(ToString(report.body.result.status.outcome)) + ": " +
                       report.body.result.status.message + "); its values are no estimate";
      return false;
    }
    *fp = ForceParameters::From(report.body.result);
    return true;
  }
  *fp = ForceParameters{};
  if (!LoadParameters(path, set, &fp->shared, error, notes)) return false;
  fp->source = kParameterSetForces;
  return true;
}

int SimulateResponsesCommand(int argc, char** argv) {
  std::string error;
  std::vector<const Effect*> effects;
  if (!ParseEffects(&effects, &error)) return Usage(error);
  if (FLAGS_parameters.empty() || FLAGS_output.empty()) {
    return Usage("simulate --lug_forces needs --parameters=FILE and --output=RESPONSE");
  }
  if (!FLAGS_truth.empty()) {
    return Usage("--truth: the file of --lug_forces is the truth of a response simulation");
  }
  if (!(FLAGS_response_noise > 0) || !std::isfinite(FLAGS_response_noise)) {
    return Usage("--response_noise: must be positive (it is each channel's sigma)");
  }
  // Its default, 0 (standing), has no lug order: the drum speeds are asked for.
  if (gflags::GetCommandLineFlagInfoOrDie("speeds").is_default) {
    return Usage("simulate --lug_forces needs --speeds=V1,V2,... (drum speeds in m/s, each > 0: "
                 "a lug order exists only rolling)");
  }
  std::vector<double> speeds;
  if (!ParseNumberList("speeds", FLAGS_speeds, true, "m/s", &speeds, &error)) {
    return Usage(error + " (a lug order exists only rolling)");
  }
  if (!CheckOutputs({{"output", FLAGS_output}}, Inputs(), &error)) return Usage(error);
  std::map<Param, double> set;
  if (!ParseSet(&set, &error)) return Usage(error);
  LoadError load;
  Parameters p;
  if (!LoadParameters(FLAGS_parameters, set, &p, &load)) return Usage(load.OneLine());
  LugForceSpectrum spectrum;
  if (!LoadLugForces(FLAGS_lug_forces, &spectrum, &load)) return Usage(load.OneLine());
  const RigidRingModel model(effects);
  const std::vector<Param> missing = Missing(model, p);
  if (!missing.empty()) return Usage(MissingParameters(FLAGS_parameters, missing));
  ResponseDataset data;
  data.name = spectrum.name + "_response";
  data.description = "The axle's response to the lug forces of " + FLAGS_lug_forces + " under " +
                     FLAGS_parameters + ", simulated by ringid (noise " +
                     std::to_string(FLAGS_response_noise) + " of each amplitude, seed " +
                     std::to_string(FLAGS_seed) + ").";
  const int orders = spectrum.orders.rbegin()->first;
  std::mt19937_64 rng(FLAGS_seed);
  const std::vector<AxleChannel> all = {AxleChannel::kForceX, AxleChannel::kForceZ,
                                        AxleChannel::kForceY, AxleChannel::kMomentX,
                                        AxleChannel::kMomentZ};
  const auto forces = [&](int k) {
    const auto it = spectrum.orders.find(k);
    return it == spectrum.orders.end() ? std::array<Complex, kNumLugForces>{} : it->second;
  };
  if (!SimulateResponses(model, p, spectrum.lugs_per_revolution, speeds, orders, all, forces,
                         FLAGS_response_noise, &rng, &data, &error)) {
    return Usage(FLAGS_parameters + ": the model cannot respond: " + error);
  }
  const int rc = Write(FLAGS_output, ResponseDatasetToJson(data));
  if (rc != kExitOk) return rc;
  std::printf("wrote %s: %zu conditions, %zu orders, 5 channels\n", FLAGS_output.c_str(),
              data.conditions.size(), spectrum.orders.size());
  return kExitOk;
}

bool ForcesOf(const ForceParameters& fp, const ResponseDataset& data,
              const std::vector<const Effect*>& effects, const std::string& parameters,
              const std::string& dataset, ForcesResult* r, std::string* error,
              const std::vector<std::string>& notes) {
  const RigidRingModel model(effects);
  // The forces need the model that was fitted: an effect the parameters move
  // off its baseline (0; m_a, the hub's mass, has none) asks for that effect.
  for (const Effect* e : EffectCatalogue()) {
    if (std::find(effects.begin(), effects.end(), e) != effects.end()) continue;
    for (Param q : e->parameters()) {
      if (Info(q).domain == Domain::kPositive || !std::isfinite(fp.shared[q]) || fp.shared[q] == 0) {
        continue;
      }
      *error = parameters + ": parameters." + ParamName(q) + ": a parameter of " + e->name() +
               ", which the model lacks; give --effects=" + e->name() +
               " (the forces use the model that was fitted)";
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
    *error = dataset + ": conditions[" + std::to_string(i) + "].known." + ParamName(missing[0]) +
             ": missing: " + parameters + " fitted " + ParamName(missing[0]) +
             " per condition (" + fitted + "); name the condition '" + c.name +
             "' as one of those, or give its value in known";
    return false;
  }
  EstimateForces(model, fp, data, ForcesOptions{}, r);
  return true;
}

int ForcesCommand(int argc, char** argv) {
  std::string error;
  std::vector<const Effect*> effects;
  if (!ParseEffects(&effects, &error)) return Usage(error);
  if (FLAGS_parameters.empty() || FLAGS_dataset.empty()) {
    return Usage("forces needs --parameters=FILE (a parameter set or an identify report) and "
                 "--dataset=FILE (a response dataset, ringid-lug-response/1)");
  }
  if (!CheckOutputs({{"output", FLAGS_output}}, Inputs(), &error)) return Usage(error);
  std::map<Param, double> set;
  if (!ParseSet(&set, &error)) return Usage(error);
  LoadError load;
  ForceParameters fp;
  std::vector<std::string> notes;  // where a .tir's values came from
  if (!ReadForceParameters(FLAGS_parameters, &fp, &load, set, &notes)) return Usage(load.OneLine());
  ResponseDataset data;
  if (!LoadResponseDataset(FLAGS_dataset, &data, &load)) return Usage(load.OneLine());
  ForcesResult r;
  if (!ForcesOf(fp, data, effects, FLAGS_parameters, FLAGS_dataset, &r, &error, notes)) {
    return Usage(error);
  }
  for (const std::string& note : notes) std::printf("parameters: %s\n", note.c_str());
  return Finish<ForcesReport>(argc, argv, data, r);
}

}  // namespace ringid
