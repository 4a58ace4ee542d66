// Writes datasets and parameter sets back as the JSON the loader reads
// (docs/conventions.md §3, §7): format 1 where it can hold the dataset.
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "datasets/dataset.h"
#include "datasets/parameter_files.h"

namespace ringid {

using nlohmann::json;

namespace {

json ValuesJson(const std::map<Param, double>& m) {
  json o = json::object();
  for (const auto& [p, v] : m) o[ParamName(p)] = v;
  return o;
}

json ModeJson(const MeasuredMode& m) {
  json o;
  o["label"] = LabelName(m.label);
  o["plane"] = PlaneName(LabelPlane(m.label));
  o["frequency_hz"] = m.frequency_hz;
  if (m.frequency_sigma_hz) o["frequency_sigma_hz"] = *m.frequency_sigma_hz;
  if (m.damping_ratio) o["damping_ratio"] = *m.damping_ratio;
  if (m.damping_sigma) o["damping_sigma"] = *m.damping_sigma;
  if (!m.shape.empty()) {
    json s = json::object();
    for (const auto& [dof, v] : m.shape) s[DofName(dof)] = v;
    o["shape"] = s;
  }
  if (m.shape_sigma) o["shape_sigma"] = *m.shape_sigma;
  return o;
}

// Whether format 1 cannot hold `d`.
bool NeedsFormat2(const Dataset& d) {
  if (d.format == 2 || d.conditions.size() > 1 || !d.priors.empty() ||
      !d.per_condition.empty()) {
    return true;
  }
  if (d.conditions.empty()) return false;
  const Condition& c = d.conditions[0];
  const Condition standing;
  return c.name != standing.name || c.speed_m_s != standing.speed_m_s ||
         !c.known.empty() || !c.initial.empty();
}

}  // namespace

std::string ParameterSetToJson(const Parameters& p, const std::string& name,
                               const std::string& description) {
  ParameterSet set{name, description, {}};
  for (int i = 0; i < kNumParams; ++i) {
    const Param q = ParamAt(i);
    const bool baseline = Info(q).group == Group::kEffect && p[q] == 0;  // the default
    if (p.IsSet(q) && !baseline) set.parameters[q].value = p[q];
  }
  return ParameterSetText(set);
}

std::string DatasetToJson(const Dataset& d) {
  const bool format2 = NeedsFormat2(d);
  json j;
  j["format"] = format2 ? kDatasetFormat2 : kDatasetFormat1;
  j["name"] = d.name;
  if (!d.description.empty()) j["description"] = d.description;
  if (!d.known.empty()) j["known"] = ValuesJson(d.known);
  if (!d.initial.empty()) j["initial"] = ValuesJson(d.initial);
  if (!d.ties.empty()) {
    json t = json::object();
    for (const auto& [a, b] : d.ties) t[ParamName(a)] = ParamName(b);
    j["ties"] = t;
  }
  if (!format2) {
    j["modes"] = json::array();
    for (const MeasuredMode& m : d.modes) j["modes"].push_back(ModeJson(m));
  } else {
    if (!d.priors.empty()) {
      json priors = json::object();
      for (const auto& [p, prior] : d.priors) {
        const bool normal = prior.distribution == PriorDistribution::kNormal;
        json o;
        o["distribution"] = ToString(prior.distribution);
        o[normal ? "mean" : "median"] = prior.center;
        o[normal ? "sigma" : "factor_95"] = prior.spread;
        priors[ParamName(p)] = o;
      }
      j["priors"] = priors;
    }
    if (!d.per_condition.empty()) {
      j["per_condition"] = json::array();
      for (const Param p : d.per_condition) {
        j["per_condition"].push_back(ParamName(p));
      }
    }
    j["conditions"] = json::array();
    for (size_t i = 0; i < d.conditions.size(); ++i) {
      const Condition& c = d.conditions[i];
      json o;
      o["name"] = c.name;
      o["speed_m_s"] = c.speed_m_s;
      if (!c.known.empty()) o["known"] = ValuesJson(c.known);
      if (!c.initial.empty()) o["initial"] = ValuesJson(c.initial);
      o["modes"] = json::array();
      for (const MeasuredMode& m : d.modes) {
        if (m.condition == static_cast<int>(i)) o["modes"].push_back(ModeJson(m));
      }
      j["conditions"].push_back(o);
    }
  }
  // Names may come from file names, which need not be UTF-8.
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace ringid
