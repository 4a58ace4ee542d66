// Writes datasets and parameter sets back as the JSON the loader reads
// (docs/conventions.md §3, §7): format 1 where it can hold the dataset.
#include <algorithm>
#include <map>
#include <string>

#include "datasets/dataset.h"
#include "datasets/dataset_file.h"
#include "datasets/parameter_files.h"

namespace ringid {

namespace {

NamedValues ValuesOf(const std::map<Param, double>& m) {
  NamedValues o;
  for (const auto& [p, v] : m) o[ParamName(p)] = v;
  return o;
}

// Absent where empty, as a reader would leave it out.
std::optional<NamedValues> GivenValues(const std::map<Param, double>& m) {
  if (m.empty()) return std::nullopt;
  return ValuesOf(m);
}

ModeFields FieldsOf(const MeasuredMode& m) {
  ModeFields o;
  o.label = LabelName(m.label);
  o.plane = PlaneName(LabelPlane(m.label));
  o.frequency_hz = m.frequency_hz;
  o.frequency_sigma_hz = m.frequency_sigma_hz;
  o.damping_ratio = m.damping_ratio;
  o.damping_sigma = m.damping_sigma;
  if (!m.shape.empty()) {
    o.shape.emplace();
    for (const auto& [dof, v] : m.shape) (*o.shape)[DofName(dof)] = v;
  }
  o.shape_sigma = m.shape_sigma;
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

// Whether formats 1 and 2 cannot hold `d`.
bool NeedsFormat3(const Dataset& d) {
  return d.format == 3 || !d.statics.empty() ||
         std::any_of(d.conditions.begin(), d.conditions.end(),
                     [](const Condition& c) { return c.frf || c.obstacle; });
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

DatasetFields FieldsOf(const Dataset& d) {
  DatasetFields j;
  j.format = NeedsFormat3(d)   ? kDatasetFormat3
             : NeedsFormat2(d) ? kDatasetFormat2
                               : kDatasetFormat1;
  j.name = d.name;
  if (!d.description.empty()) j.description = d.description;
  j.known = GivenValues(d.known);
  j.initial = GivenValues(d.initial);
  if (!d.ties.empty()) {
    j.ties.emplace();
    for (const auto& [a, b] : d.ties) (*j.ties)[ParamName(a)] = ParamName(b);
  }
  if (j.format == kDatasetFormat1) {
    for (const MeasuredMode& m : d.modes) j.modes.push_back(FieldsOf(m));
    return j;
  }
  if (!d.priors.empty()) {
    j.priors.emplace();
    for (const auto& [p, prior] : d.priors) {
      PriorFields& o = (*j.priors)[ParamName(p)];
      o.distribution = ToString(prior.distribution);
      const bool normal = prior.distribution == PriorDistribution::kNormal;
      (normal ? o.mean : o.median) = prior.center;
      (normal ? o.sigma : o.factor_95) = prior.spread;
    }
  }
  if (!d.per_condition.empty()) {
    j.per_condition.emplace();
    for (const Param p : d.per_condition) j.per_condition->push_back(ParamName(p));
  }
  for (size_t i = 0; i < d.conditions.size(); ++i) {
    const Condition& c = d.conditions[i];
    ConditionFields o;
    o.name = c.name;
    o.speed_m_s = c.speed_m_s;
    o.known = GivenValues(c.known);
    o.initial = GivenValues(c.initial);
    for (const MeasuredMode& m : d.modes) {
      if (m.condition != static_cast<int>(i)) continue;
      if (!o.modes) o.modes.emplace();
      o.modes->push_back(FieldsOf(m));
    }
    if (c.frf) o.frf = FieldsOf(*c.frf);
    if (c.obstacle) o.obstacle = FieldsOf(*c.obstacle);
    for (const MeasuredStatic& m : d.statics) {
      if (m.condition != static_cast<int>(i)) continue;
      if (!o.statics) o.statics.emplace();
      o.statics->push_back({m.direction, m.value, m.sigma});
    }
    if (j.format == kDatasetFormat2 && !o.modes) o.modes.emplace();  // a condition's modes are required
    j.conditions.push_back(o);
  }
  return j;
}

std::string DatasetToJson(const Dataset& d) {
  // Names may come from file names, which need not be UTF-8.
  return JsonWriter::ToJson(FieldsOf(d)).dump(2, ' ', false, Json::error_handler_t::replace) +
         "\n";
}

}  // namespace ringid
