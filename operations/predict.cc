#include "operations/predict.h"

#include <algorithm>

#include "datasets/obstacle.h"
#include "model/campbell.h"
#include "model/lug_excitation.h"
#include "operations/model_parameters.h"

namespace ringid {
namespace {

// The modes at each of s.speeds and, with lugs_per_revolution, the critical
// speeds of the orders up to max_order, into body.
bool AtSpeeds(const RigidRingModel& model, const Parameters& p, const PredictSettings& s,
              PredictBody* body, std::string* error) {
  if (s.lugs_per_revolution < 0) {
    *error = "--lugs_per_revolution: must not be negative";
    return false;
  }
  if (s.max_order < 1 || s.max_order > kMaxOrders) {
    *error = "--max_order: must lie in [1, " + std::to_string(kMaxOrders) + "]";
    return false;
  }
  std::vector<double> speeds = s.speeds.values;
  std::sort(speeds.begin(), speeds.end());
  if (speeds == std::vector<double>{0}) {  // standing: the modes above
    if (s.lugs_per_revolution > 0) {
      *error = "--lugs_per_revolution: needs --speeds (the lug orders meet the modes at speed)";
      return false;
    }
    return true;
  }
  body->speeds.emplace();
  for (double v : speeds) {
    SpeedModes at;
    at.speed_m_s = v;
    for (const Mode& m : model.Solve(p, v).modes) at.modes[m.label] = {m.frequency_hz, m.damping_ratio};
    body->speeds->push_back(at);
  }
  if (s.lugs_per_revolution > 0) {
    body->lugs_per_revolution = s.lugs_per_revolution;
    body->r_e0 = p[Param::r_e0];
    body->max_order = s.max_order;
    body->critical_speeds = CriticalSpeeds(model, p, s.lugs_per_revolution, speeds, s.max_order);
  }
  return true;
}

// The modes of every condition of `d`, each with its per-condition values.
std::vector<SpeedModes> ByCondition(const RigidRingModel& model, const Dataset& d,
                                    const ParameterValues& set) {
  std::vector<SpeedModes> out;
  for (size_t c = 0; c < d.conditions.size(); ++c) {
    Parameters p = InitialParameters(d, static_cast<int>(c));
    for (const auto& [q, v] : set) p[q] = v;
    SpeedModes at{d.conditions[c].name, d.conditions[c].speed_m_s, {}};
    for (const Mode& m : model.Solve(p, at.speed_m_s).modes) {
      at.modes[m.label] = {m.frequency_hz, m.damping_ratio};
    }
    out.push_back(at);
  }
  return out;
}

// With s.lug_profile: the lugs' excitation at each of s.speeds, into body.
bool LugsAtSpeeds(const RigidRingModel& model, const Parameters& p, const PredictSettings& s,
                  PredictBody* body, InputError* error) {
  if (s.lug_profile.empty()) return true;
  ObstacleProfile lugs;
  LoadError load;
  if (!LoadLugProfile(s.lug_profile, &lugs, &load)) {
    *error = InputError::Of(load);
    return false;
  }
  for (double v : s.speeds.values) {
    if (!(v >= kSlowestRoll)) {
      *error = InputError::Option("--lug_profile: the lugs roll: every speed of --speeds must be "
                                  "at least 0.001 m/s");
      return false;
    }
  }
  body->lug_profile = FieldsOf(lugs);
  body->max_order = s.max_order;
  body->lug_excitation.emplace();
  std::vector<double> speeds = s.speeds.values;
  std::sort(speeds.begin(), speeds.end());
  for (double v : speeds) {
    LugExcitation e;
    std::string why;
    if (!LugExcitationOf(model, p, lugs, v, s.max_order, &e, &why)) {
      *error = InputError::Option("--lug_profile: " + why);
      return false;
    }
    body->lug_excitation->push_back(std::move(e));
  }
  return true;
}

}  // namespace

bool PredictBodyOf(const Parameters& parameters, const Dataset* d, const PredictSettings& s,
                   const std::string& source, const std::vector<std::string>& notes,
                   PredictBody* body, std::string* solve_error, InputError* error) {
  Parameters p = parameters;
  if (d) {
    p = InitialParameters(*d);
    for (const auto& [q, v] : s.set) p[q] = v;
  }
  const RigidRingModel model(s.effects);
  const std::vector<Param> missing = Missing(model, p);
  if (!missing.empty()) {
    *error = MissingParameters(source, missing, notes);
    return false;
  }
  const ModalSolution solution = model.Solve(p);
  *body = PredictBody::From(solution);
  if (!notes.empty()) body->parameter_notes = notes;
  if (d && d->conditions.size() > 1) body->conditions = ByCondition(model, *d, s.set);
  std::string line;
  if (!AtSpeeds(model, p, s, body, &line)) {
    *error = InputError::Option(line);
    return false;
  }
  if (!s.lug_profile.empty()) {
    std::vector<Param> cam;
    for (Param q : CamParameters()) {
      if (!p.IsSet(q)) cam.push_back(q);
    }
    if (!cam.empty()) {
      *error = MissingParameters(source, cam, notes);
      return false;
    }
  }
  if (!LugsAtSpeeds(model, p, s, body, error)) return false;
  solve_error->clear();
  if (!solution.ok) {
    *solve_error = solution.error.empty() ? std::string("the model cannot be solved") : solution.error;
  }
  return true;
}

}  // namespace ringid
