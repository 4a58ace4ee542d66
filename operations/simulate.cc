#include "operations/simulate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>

#include "datasets/frf_spec.h"
#include "datasets/obstacle.h"
#include "datasets/synthetic.h"
#include "model/frequency_response.h"
#include "model/time_response.h"
#include "operations/model_parameters.h"

namespace ringid {
namespace {

// The field of `spec` (its inputs' or outputs' `coordinates`) naming a
// coordinate `model` lacks, with why; empty where none does.
LoadError LackedCoordinate(const ModalModel& model, const Frf& frf, const std::string& spec) {
  const auto Lacked = [&](const DofCombination& c, const std::optional<FrfPoint>& point,
                          const std::string& field) -> LoadError {
    const bool on_rim = point && point->on == FrfBody::kRim;
    const auto dof = MissingCoordinate(model, Coordinates(c.begin(), c.end()), on_rim);
    if (!dof) return {};
    return {spec, field, std::string("names ") + DofName(*dof) +
                             ", which the model lacks (hub_compliance gives the hub x_a, z_a, "
                             "y_a)"};
  };
  for (size_t i = 0; i < frf.inputs.size(); ++i) {
    LoadError e = Lacked(frf.inputs[i].coordinates, frf.inputs[i].point,
                         "inputs[" + std::to_string(i) + "].coordinates");
    if (!e.message.empty()) return e;
  }
  for (size_t i = 0; i < frf.outputs.size(); ++i) {
    LoadError e = Lacked(frf.outputs[i].coordinates, frf.outputs[i].point,
                         "outputs[" + std::to_string(i) + "].coordinates");
    if (!e.message.empty()) return e;
  }
  return {};
}

// Each condition of `d` given the FRFs the spec at `path` lays out, where
// contract §9 takes them at its speed and the model has their coordinates;
// the spec's noise, if it gives one, in `noise`.
bool PlanFrfs(const std::string& path, const ModalModel& model, Dataset* d, double* noise,
              InputError* error) {
  FrfSpec spec;
  LoadError load;
  if (!LoadFrfSpec(path, &spec, &load)) {
    *error = InputError::Of(load);
    return false;
  }
  for (Condition& c : d->conditions) {
    Frf frf;
    if (!FrfOfSpec(spec, c.speed_m_s, &frf, &load)) {
      load.message += " (condition " + c.name + ")";
      *error = InputError::Of(load);
      return false;
    }
    if (load = LackedCoordinate(model, frf, path); !load.message.empty()) {
      *error = InputError::Of(load);
      return false;
    }
    c.frf = std::move(frf);
  }
  *noise = spec.noise.value_or(*noise);
  d->description += "; the FRFs laid out by " + path;
  return true;
}

// The obstacle conditions of the spec at `path` after d's own (contract
// §11), the tandem cam known at the truth; its warnings on stderr.
bool AddObstacles(const std::string& path, const std::string& parameters,
                  const RigidRingModel& model, const Parameters& truth,
                  const std::vector<double>& loads, std::mt19937_64* rng, Dataset* d,
                  InputError* error) {
  ObstacleSpec spec;
  LoadError load;
  if (!LoadObstacleSpec(path, &spec, &load)) {
    *error = InputError::Of(load);
    return false;
  }
  std::vector<Param> cam;
  for (Param q : CamParameters()) {
    if (!truth.IsSet(q)) cam.push_back(q);
    d->known[q] = truth[q];
  }
  if (!cam.empty()) {
    *error = MissingParameters(parameters, cam);
    return false;
  }
  const double values = 8.0 * spec.samples * static_cast<double>(spec.outputs.size()) *
                        static_cast<double>(spec.speeds_m_s.size() * std::max<size_t>(1, loads.size()));
  if (values > kMaxFileBytes) {
    *error = InputError::Option("--obstacle: " + path + " with --loads lays out more samples than a "
                                "dataset of at most " + std::to_string(kMaxFileBytes) + " bytes holds");
    return false;
  }
  std::vector<Condition> conditions;
  std::vector<std::string> warnings;
  if (!SimulateObstacles(model, truth, spec, loads, rng, &conditions, &warnings, &load)) {
    *error = InputError::Of(load);
    return false;
  }
  for (const std::string& w : warnings) std::fprintf(stderr, "warning: %s: %s\n", path.c_str(), w.c_str());
  for (Condition& c : conditions) d->conditions.push_back(std::move(c));  // "obstacle_V": new names
  d->format = 3;
  d->description += "; the obstacle tests laid out by " + path;
  return true;
}

}  // namespace

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
  if (s.frf_modes && s.frf.empty()) {
    return Fail("--frf_modes: only with --frf (without it simulate writes the modes alone)");
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
  if (!s.frf.empty()) FreeMasses(truth, s.prior_spread, &rng, &d);  // FRFs weigh them
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
  so.modes = s.frf.empty() || s.frf_modes;  // an FRF test's dataset holds its FRFs
  if (!s.frf.empty() && !PlanFrfs(s.frf, model, &d, &so.frf_noise, error)) return false;
  if (!Simulate(model, truth, so, &rng, &d, &line)) {
    *failed = true;
    return Fail(line);
  }
  if (!s.obstacle.empty() && !AddObstacles(s.obstacle, parameters, model, truth, s.loads.values,
                                            &rng, &d, error)) {
    return false;
  }
  const bool large = !s.frf.empty() || !s.obstacle.empty();
  if (const size_t bytes = large ? DatasetToJson(d).size() : 0; bytes > kMaxFileBytes) {
    std::string spec = s.frf.empty() ? "" : "--frf: " + s.frf;
    if (!s.obstacle.empty()) spec += (spec.empty() ? "" : " and ") + ("--obstacle: " + s.obstacle);
    return Fail(spec + " lays out a dataset of " + std::to_string(bytes) + " bytes, more than the " +
                std::to_string(kMaxFileBytes) + " a dataset may have: fewer samples, " +
                "channels or conditions");
  }
  out->truth = MakeTruth(model, truth, d, output);
  out->effects = s.effects;
  out->dataset = std::move(d);
  return true;
}

}  // namespace ringid
