#include "operations/model_parameters.h"

#include <algorithm>
#include <cmath>

#include "datasets/tir_parameters.h"

namespace ringid {

const Effect* EffectOwning(Param p) {
  for (const Effect* e : EffectCatalogue()) {
    const std::vector<Param> own = e->parameters();
    if (std::find(own.begin(), own.end(), p) != own.end()) return e;
  }
  return nullptr;
}

std::vector<Param> Missing(const RigidRingModel& model, const Parameters& p) {
  std::vector<Param> missing;
  for (Param q : model.parameters()) {
    if (!p.IsSet(q)) missing.push_back(q);
  }
  return missing;
}

// An effect's parameter comes from --set (the file of a tire need not know
// the effect); a .tir's, from the key that would give it or, when a .tir
// cannot hold it, from --set, and the others missing are named too.
InputError MissingParameters(const std::string& source, const std::vector<Param>& missing,
                             const std::vector<std::string>& notes) {
  const Param q = missing[0];
  const std::string name = ParamName(q);
  std::string reason;  // what reading the file said of it
  for (const std::string& note : notes) {
    if (note.rfind(name + " not derived: ", 0) == 0) reason = note.substr(name.size() + 14);
  }
  if (const Effect* e = EffectOwning(q)) {
    return InputError::Option("--effects: " + std::string(e->name()) + " needs " + name +
                              ": give --set=" + name + "=VALUE");
  }
  if (!IsTirPath(source)) {
    return InputError::Of({source, "parameters." + name, "missing (the model needs it)"});
  }
  const std::string key = TirKeyFor(q);
  if (reason.empty()) {
    reason = key.empty() ? std::string("a .tir cannot hold it") : "the .tir has no " + key;
  }
  if (q == Param::I_ay) {
    reason = "a .tir describes the tire, not the wheel: give the rim's own inertia (the tire's "
             "IYY - BELT_IYY, where the file gives them, is added)";
  }
  std::string message =
      "missing (the model needs it; " + reason + "): give --set=" + name + "=VALUE";
  for (size_t i = 1; i < missing.size(); ++i) {
    message += (i == 1 ? "; also missing: " : ", ") + std::string(ParamName(missing[i]));
  }
  return InputError::Of({source, name, message});
}

// Either check alone would simulate the baseline while the truth file names
// an effect, or drop the size without a word. (An effect's other parameters,
// m_a, may be set for any run: scripts/campaign_demo.sh sets it for every
// case.)
bool CheckEffectSizes(const std::vector<const Effect*>& effects, const ParameterValues& set,
                      const Parameters& file, double shift, std::string* error) {
  for (const auto& [p, v] : set) {
    const Effect* e = EffectOwning(p);
    if (e && e->size() == p && std::find(effects.begin(), effects.end(), e) == effects.end()) {
      *error = std::string("--set: ") + ParamName(p) + " is the size of the effect " +
               e->name() + ", which --effects does not list; add --effects=" + e->name();
      return false;
    }
  }
  if (shift != 0) {
    if (!(shift > 0 && shift < 0.5)) {
      *error = "--shift: must be in (0, 0.5)";
      return false;
    }
    if (effects.size() != 1) {
      *error = "--shift: needs exactly one effect in --effects, whose size it sets";
      return false;
    }
    if (set.count(effects[0]->size())) {
      *error = std::string("--shift: sizes ") + ParamName(effects[0]->size()) +
               ", which --set gives too; give one of them";
      return false;
    }
    return true;
  }
  for (const Effect* e : effects) {
    const Param size = e->size();
    const auto it = set.find(size);
    const double value = it != set.end() ? it->second : file[size];
    if (value == 0 || !std::isfinite(value)) {
      *error = std::string("--effects: ") + e->name() + " has no size: give --set=" +
               ParamName(size) + "=VALUE (not 0) or --shift=FRACTION";
      return false;
    }
  }
  return true;
}

}  // namespace ringid
