// `ringid simulate` (without --lug_forces): a dataset measured from a
// parameter set, and its truth.
#include "apps/simulate_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <random>

#include "apps/flags.h"
#include "apps/reports.h"
#include "datasets/synthetic.h"

namespace ringid {

bool SimulateFromFlags(bool need_files, Simulated* out, std::string* error, bool* failed) {
  *failed = false;
  const auto Fail = [&](const std::string& line) {
    *error = line;
    return false;
  };
  std::vector<double> speeds, loads;
  if (!ParseNumberList("speeds", FLAGS_speeds, false, "m/s", &speeds, error)) return false;
  if (!gflags::GetCommandLineFlagInfoOrDie("loads").is_default &&
      !ParseNumberList("loads", FLAGS_loads, true, "N", &loads, error)) {
    return false;
  }
  std::vector<const Effect*> effects;
  if (!ParseEffects(&effects, error)) return false;
  if (FLAGS_parameters.empty() || (need_files && (FLAGS_output.empty() || FLAGS_truth.empty()))) {
    return Fail("simulate needs --parameters=FILE, --output=DATASET and --truth=FILE");
  }
  for (double v : {FLAGS_frequency_noise, FLAGS_damping_noise, FLAGS_shape_noise, FLAGS_prior_spread}) {
    if (!(v >= 0) || !std::isfinite(v)) return Fail("noise levels and --prior_spread must be finite and not negative");
  }
  if (need_files &&
      !CheckOutputs({{"output", FLAGS_output}, {"truth", FLAGS_truth}}, Inputs(), error)) {
    return false;
  }
  Parameters truth;
  LoadError load;
  if (!LoadParameterSet(FLAGS_parameters, &truth, &load)) return Fail(load.OneLine());
  std::map<Param, double> set;
  if (!ParseSet(&set, error) || !CheckEffectSizes(effects, set, truth, error)) {
    return false;
  }
  for (const auto& [p, v] : set) truth[p] = v;
  if (FLAGS_shift != 0) truth[effects[0]->size()] = 0;  // set below
  const RigidRingModel model(effects);
  const std::vector<Param> missing = Missing(model, truth);
  if (!missing.empty()) return Fail(MissingParameters(FLAGS_parameters, missing));
  if (FLAGS_shift != 0) {
    const Param p = effects[0]->size();
    truth[p] = ValueForShift(truth, *effects[0], p, FLAGS_shift);
    if (!(LargestShift(truth, *effects[0], p, truth[p]) < 2 * FLAGS_shift)) {
      *failed = true;
      char line[200];
      std::snprintf(line, sizeof line, "%s cannot shift a frequency by %g", effects[0]->name(),
                    FLAGS_shift);
      return Fail(line);
    }
  }
  std::mt19937_64 rng(static_cast<unsigned>(FLAGS_seed));
  Dataset d = PlanSimulation(truth, FLAGS_prior_spread, speeds, loads, &rng);
  std::vector<Param> fixed;  // written known, at the truth
  if (!ParseFix(&fixed, error)) return false;
  for (Param q : fixed) {
    if (Info(q).group == Group::kEffect ||
        std::find(d.per_condition.begin(), d.per_condition.end(), q) != d.per_condition.end()) {
      return Fail("--fix: simulate writes " + std::string(ParamName(q)) + " known already");
    }
    d.known[q] = truth[q];
    d.initial.erase(q);
    d.ties.erase(q);
  }
  d.name = std::filesystem::path(FLAGS_output).stem().string();
  d.description = "simulated by ringid from " + FLAGS_parameters + "; the truth is in a separate file";
  SimulateOptions so;
  so.frequency_noise = FLAGS_frequency_noise;
  so.damping_noise = FLAGS_damping_noise;
  so.shape_noise = FLAGS_shape_noise;
  if (!Simulate(model, truth, so, &rng, &d, error)) {
    *failed = true;
    return false;
  }
  out->truth = MakeTruth(model, truth, d, FLAGS_output);
  out->effects = effects;
  out->dataset = std::move(d);
  return true;
}

}  // namespace ringid
