#include "datasets/parameter_files.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "datasets/file_kind.h"
#include "datasets/synthetic.h"
#include "model/effects.h"
#include "model/spelling.h"

namespace ringid {
namespace {

// The parameter set of a file as docs/conventions.md §3 reads it: each value
// through ParameterValue's field list (an identify report's other fields of a
// value, its unit or reason, left unread), or a bare number; the set's name
// and description are not needed. False with `error`'s field and message.
bool ReadParameterSet(const Json& j, ParameterSet* set, LoadError* error) {
  const auto fail = [&](const std::string& field, const std::string& message) {
    error->field = field;
    error->message = message;
    return false;
  };
  if (!j.is_object()) return fail("", "top level must be a JSON object");
  const SniffedFile kind = SniffJson(j);
  if (kind.kind != FileKind::kUnknown && kind.kind != FileKind::kParameterSet &&
      kind.kind != FileKind::kReport) {  // an identify report's parameters are read
    return fail(kind.field, NotTheKind(kind, "a parameter set"));
  }
  if (const auto format = j.find("format"); format != j.end() && *format != kParameterSetFormat) {
    return fail("format", std::string("must be \"") + kParameterSetFormat + "\"");
  }
  const auto values = j.find("parameters");
  if (values == j.end() || !values->is_object()) {
    return fail("parameters", "missing or not an object");
  }
  for (const auto& [name, item] : values->items()) {
    const std::string field = "parameters." + name;
    const std::optional<Param> param = ParseParam(name);
    if (!param) return fail(field, UnknownName("parameter", name, NamesOf<Param>()));
    ParameterValue v;
    std::string why;
    if (item.is_object()) {
      Json fields = item;  // a report's null (not available) is an absent field
      for (auto it = fields.begin(); it != fields.end();) {
        it = it->is_null() ? fields.erase(it) : std::next(it);
      }
      JsonReader reader(fields, field, &why);
      v.Serialize(&reader);  // no Finish(): a report's other fields are no error
    } else {
      JsonReader::FromJson(item, field, &v.value, &why);
    }
    if (!why.empty()) {
      SetArchiveError(why, error);
      return false;
    }
    const std::string at = field + (item.is_object() ? ".value" : "");
    if (!std::isfinite(v.value)) return fail(at, "must be a number");  // null reads as NaN
    if (const std::string problem = ParameterValueProblem(*param, v.value); !problem.empty()) {
      return fail(at, problem);
    }
    const std::optional<std::string>& c = v.identifiable;
    if (c && *c != "yes" && *c != "practically_no" && *c != "no") {
      return fail(field + ".identifiable", "must be yes, practically_no or no");
    }
    set->parameters[*param] = v;
  }
  return true;
}

// The text of a typed file: its fields in Serialize's order.
template <class T>
std::string Text(const T& value) {
  return JsonWriter::ToJson(value).dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace

std::string ParameterSetText(const ParameterSet& set) { return Text(set); }

std::string TruthText(const Truth& truth) { return Text(truth); }

Truth MakeTruth(const RigidRingModel& model, const Parameters& truth, const Dataset& d,
                const std::string& dataset_file) {
  Truth t;
  t.dataset = dataset_file;
  t.effect = EffectList(model.effects());
  std::vector<Param> used = model.parameters();
  if (std::any_of(d.conditions.begin(), d.conditions.end(),
                  [](const Condition& c) { return c.obstacle.has_value(); })) {
    used.insert(used.end(), CamParameters().begin(), CamParameters().end());
  }
  for (Param q : used) {
    if (!d.IsPerCondition(q)) t.parameters[ParamName(q)].value = truth[q];
  }
  for (const Condition& c : d.conditions) {
    for (const auto& [q, v] : c.known) t.parameters[std::string(ParamName(q)) + "@" + c.name].value = v;
  }
  return t;
}

bool Truth::Validate(LoadError* error) const {
  auto fail = [&](const std::string& field, const std::string& message) {
    error->field = field;
    error->message = message;
    return false;
  };
  if (effect != "none") {
    size_t begin = 0;
    while (begin <= effect.size()) {
      const size_t end = std::min(effect.find(',', begin), effect.size());
      const std::string name = effect.substr(begin, end - begin);
      if (!FindEffect(name)) return fail("effect", "unknown effect '" + name + "'");
      begin = end + 1;
    }
  }
  for (const auto& [key, v] : parameters) {
    const std::string field = "parameters." + key;
    const auto param = ParseParam(key.substr(0, key.find('@')));
    if (!param) return fail(field, "not a parameter (NAME or NAME@CONDITION)");
    if (const std::string problem = ParameterValueProblem(*param, v.value); !problem.empty()) {
      return fail(field + ".value", problem);
    }
  }
  return true;
}

bool LoadParameterSet(const std::string& path, Parameters* p, LoadError* error,
                      Undetermined* undetermined) {
  std::string text;
  Json parsed;
  ParameterSet set;
  *p = Parameters{};
  if (undetermined) undetermined->clear();
  if (!ReadInputFile(path, &text, error) || !ParseJsonInput(text, &parsed, error) ||
      !ReadParameterSet(parsed, &set, error)) {
    return false;
  }
  for (const auto& [param, v] : set.parameters) {
    (*p)[param] = v.value;
    // What identify said of it (its report, or --save_parameters).
    std::string why;
    if (v.identifiable && *v.identifiable != "yes") {
      why = "classed " + *v.identifiable + " by ringid identify";
    }
    if (v.condition) why += (why.empty() ? "" : "; ") + *v.condition;
    if (undetermined && !why.empty()) (*undetermined)[param] = why;
  }
  return true;
}

bool LoadTruth(const std::string& path, Truth* truth, LoadError* error) {
  std::string text;
  Json parsed;
  if (!ReadInputFile(path, &text, error) || !ParseJsonInput(text, &parsed, error)) return false;
  std::string why;
  *truth = Truth{};
  if (!JsonReader::FromJson(parsed, "", truth, &why)) {
    SetArchiveError(why, error);
    return false;
  }
  return truth->Validate(error);
}

}  // namespace ringid
