#include "datasets/parameter_files.h"

#include "datasets/synthetic.h"
#include "model/effects.h"

namespace ringid {
namespace {

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
  for (Param q : model.parameters()) {
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
