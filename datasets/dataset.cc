#include "datasets/dataset.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "model/spelling.h"

namespace ringid {
namespace {

using nlohmann::json;

// Thrown inside the loader only, caught in ParseDataset.
struct Failure {
  std::string field;
  std::string message;
};

// "1e+12 in magnitude", for messages.
std::string Magnitude() {
  std::ostringstream o;
  o << kMaxParameterMagnitude << " in magnitude";
  return o.str();
}

[[noreturn]] void Fail(const std::string& field, const std::string& message) {
  throw Failure{field, message};
}

void OnlyKeys(const json& j, const std::string& where,
              const std::set<std::string>& allowed) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (!allowed.count(it.key())) {
      Fail(where.empty() ? it.key() : where + "." + it.key(), "unknown key");
    }
  }
}

double Number(const json& j, const std::string& field) {
  if (!j.is_number()) Fail(field, "must be a number");
  const double v = j.get<double>();
  if (!std::isfinite(v)) Fail(field, "must be finite");
  return v;
}

double Positive(const json& j, const std::string& field) {
  const double v = Number(j, field);
  if (!(v > 0)) Fail(field, "must be positive");
  return v;
}

std::string String(const json& j, const std::string& field) {
  if (!j.is_string()) Fail(field, "must be a string");
  return j.get<std::string>();
}

Param ParamCalled(const std::string& name, const std::string& field) {
  const auto p = ParseParam(name);
  if (!p) Fail(field, UnknownName("parameter", name, NamesOf<Param>()));
  return *p;
}

std::map<Param, double> Values(const json& j, const std::string& field) {
  if (!j.is_object()) Fail(field, "must be an object of parameter values");
  std::map<Param, double> out;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string f = field + "." + it.key();
    const Param p = ParamCalled(it.key(), f);
    const double v = Number(it.value(), f);
    const std::string problem = ParameterValueProblem(p, v);
    if (!problem.empty()) Fail(f, problem);
    out[p] = v;
  }
  return out;
}

// The labels a dataset may name: every one but the hub's (docs/conventions.md
// §1), in catalogue order.
std::vector<std::string> MeasurableLabels() {
  std::vector<std::string> names;
  for (const std::string& name : NamesOf<ModeLabel>()) {
    if (LabelPlane(*ParseLabel(name)) != Plane::kHub) names.push_back(name);
  }
  return names;
}

MeasuredMode Mode(const json& j, const std::string& field) {
  if (!j.is_object()) Fail(field, "must be an object");
  OnlyKeys(j, field,
           {"label", "plane", "frequency_hz", "frequency_sigma_hz",
            "damping_ratio", "damping_sigma", "shape", "shape_sigma"});
  MeasuredMode m;
  if (!j.contains("label")) Fail(field + ".label", "missing");
  const std::string label = String(j["label"], field + ".label");
  const auto parsed = ParseLabel(label);
  if (!parsed) Fail(field + ".label", UnknownName("label", label, MeasurableLabels()));
  if (LabelPlane(*parsed) == Plane::kHub) {  // not a typo: nothing to suggest
    Fail(field + ".label", "'" + label + "' is a mode of the hub, which a dataset does not "
                          "list (expected " + OneOf(MeasurableLabels()) + ")");
  }
  m.label = *parsed;
  if (j.contains("plane")) {
    const std::string plane = String(j["plane"], field + ".plane");
    if (plane != "in_plane" && plane != "out_of_plane") {
      Fail(field + ".plane", "must be in_plane or out_of_plane");
    }
    if (plane != PlaneName(LabelPlane(m.label))) {
      Fail(field + ".plane", "'" + plane + "' contradicts label '" + label + "'");
    }
  }
  if (!j.contains("frequency_hz")) Fail(field + ".frequency_hz", "missing");
  m.frequency_hz = Positive(j["frequency_hz"], field + ".frequency_hz");
  const std::string problem = ModeFrequencyProblem(m.frequency_hz);
  if (!problem.empty()) Fail(field + ".frequency_hz", problem);
  if (j.contains("frequency_sigma_hz")) {
    m.frequency_sigma_hz =
        Positive(j["frequency_sigma_hz"], field + ".frequency_sigma_hz");
  }
  if (j.contains("damping_ratio")) {
    const double z = Number(j["damping_ratio"], field + ".damping_ratio");
    if (!(z > 0 && z < 1)) Fail(field + ".damping_ratio", "must lie in (0, 1)");
    m.damping_ratio = z;
  }
  if (j.contains("damping_sigma")) {
    if (!m.damping_ratio) {
      Fail(field + ".damping_sigma", "given without damping_ratio");
    }
    m.damping_sigma = Positive(j["damping_sigma"], field + ".damping_sigma");
  }
  if (j.contains("shape")) {
    const json& s = j["shape"];
    if (!s.is_object() || s.empty()) {
      Fail(field + ".shape", "must be a non-empty object of components");
    }
    double largest = 0;
    for (auto it = s.begin(); it != s.end(); ++it) {
      const std::string f = field + ".shape." + it.key();
      const auto dof = ParseDof(it.key());
      if (!dof) Fail(f, UnknownName("degree of freedom", it.key(), NamesOf<Dof>()));
      const double v = Number(it.value(), f);
      largest = std::max(largest, std::abs(v));
      m.shape.emplace_back(*dof, v);
    }
    if (!(largest > 0)) Fail(field + ".shape", "all components are zero");
  }
  if (j.contains("shape_sigma")) {
    if (m.shape.empty()) Fail(field + ".shape_sigma", "given without shape");
    m.shape_sigma = Positive(j["shape_sigma"], field + ".shape_sigma");
  }
  return m;
}

// "name" and "description", required and optional, as in both formats.
void NameAndDescription(const json& j, Dataset* d) {
  if (!j.contains("name")) Fail("name", "missing");
  d->name = String(j["name"], "name");
  if (d->name.empty()) Fail("name", "must not be empty");
  if (j.contains("description")) {
    d->description = String(j["description"], "description");
  }
}

// The shared "known", "initial" and "ties" of both formats.
void SharedValues(const json& j, Dataset* d) {
  if (j.contains("known")) d->known = Values(j["known"], "known");
  if (j.contains("initial")) d->initial = Values(j["initial"], "initial");
  for (const auto& [p, v] : d->initial) {
    if (d->known.count(p)) {
      Fail(std::string("initial.") + ParamName(p),
           "also given in known");
    }
  }
  if (j.contains("ties")) {
    const json& t = j["ties"];
    if (!t.is_object()) Fail("ties", "must be an object");
    for (auto it = t.begin(); it != t.end(); ++it) {
      const std::string f = "ties." + it.key();
      const Param from = ParamCalled(it.key(), f);
      const Param to = ParamCalled(String(it.value(), f), f);
      if (from == to) Fail(f, "tied to itself");
      if (Info(from).domain != Info(to).domain) {
        Fail(f, "ties parameters of different kinds");
      }
      if (d->known.count(from) || d->initial.count(from)) {
        Fail(f, "a tied parameter takes its value from its target; remove it "
                "from known/initial");
      }
      d->ties[from] = to;
    }
    for (const auto& [from, to] : d->ties) {
      if (d->ties.count(to)) {
        Fail(std::string("ties.") + ParamName(from),
             std::string("target '") + ParamName(to) +
                 "' is itself tied");
      }
    }
  }
}

// The "modes" array at `field` (of condition `condition`), appended to
// d->modes; a label at most once within it.
void Modes(const json& j, const std::string& field, int condition,
           Dataset* d) {
  if (!j.contains("modes")) Fail(field, "missing");
  const json& modes = j["modes"];
  if (!modes.is_array() || modes.empty()) {
    Fail(field, "must be a non-empty array");
  }
  if (modes.size() > static_cast<size_t>(kMaxModes)) {
    Fail(field, "more than " + std::to_string(kMaxModes) +
                    " modes (one per contract label)");
  }
  std::set<ModeLabel> seen;
  for (size_t i = 0; i < modes.size(); ++i) {
    const std::string f = field + "[" + std::to_string(i) + "]";
    d->modes.push_back(Mode(modes[i], f));
    d->modes.back().condition = condition;
    if (!seen.insert(d->modes.back().label).second) {
      Fail(f + ".label", std::string("label '") +
                             LabelName(d->modes.back().label) +
                             "' appears twice");
    }
  }
}

// Format 1 (docs/conventions.md §3): one standing condition.
void CheckFormat1(const json& j, Dataset* d) {
  OnlyKeys(j, "", {"format", "name", "description", "known", "initial", "ties",
                   "modes"});
  if (!j.contains("format")) Fail("format", "missing");
  if (String(j["format"], "format") != kDatasetFormat1) {
    Fail("format", std::string("must be \"") + kDatasetFormat1 + "\" or \"" +
                       kDatasetFormat2 + "\"");
  }
  NameAndDescription(j, d);
  SharedValues(j, d);
  Modes(j, "modes", 0, d);
}

// "per_condition": parameter names, each at most once, none shared (top-level
// known/initial) or tied; kept in catalogue order.
void PerCondition(const json& j, Dataset* d) {
  if (!j.is_array()) Fail("per_condition", "must be an array of parameter names");
  for (size_t i = 0; i < j.size(); ++i) {
    const std::string f = "per_condition[" + std::to_string(i) + "]";
    const std::string name = String(j[i], f);
    const Param p = ParamCalled(name, f);
    if (d->IsPerCondition(p)) Fail(f, "'" + name + "' is listed twice");
    for (const char* where : {"known", "initial"}) {
      const auto& values = std::string(where) == "known" ? d->known : d->initial;
      if (values.count(p)) {
        Fail(f, "'" + name + "' is also given in top-level " + where +
                    ": a per-condition parameter takes its values in each "
                    "condition's known or initial");
      }
    }
    for (const auto& [from, to] : d->ties) {
      if (from == p || to == p) {
        Fail(f, "'" + name + "' is tied (ties." + ParamName(from) +
                    "): a tied parameter cannot be per-condition");
      }
    }
    d->per_condition.push_back(p);
  }
  std::sort(d->per_condition.begin(), d->per_condition.end());
}

// "priors": one prior per parameter, on neither a known, a tied nor a
// per-condition parameter.
void Priors(const json& j, Dataset* d) {
  if (!j.is_object()) Fail("priors", "must be an object of priors");
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string f = "priors." + it.key();
    const Param p = ParamCalled(it.key(), f);
    const json& o = it.value();
    if (!o.is_object()) Fail(f, "must be an object");
    OnlyKeys(o, f, {"distribution", "mean", "sigma", "median", "factor_95"});
    if (!o.contains("distribution")) Fail(f + ".distribution", "missing");
    const std::string name = String(o["distribution"], f + ".distribution");
    const auto distribution = FromString<PriorDistribution>(name);
    if (!distribution) {
      Fail(f + ".distribution", "must be " + EnumChoices<PriorDistribution>());
    }
    const bool normal = *distribution == PriorDistribution::kNormal;
    const char* center = normal ? "mean" : "median";
    const char* spread = normal ? "sigma" : "factor_95";
    for (const char* other : {"mean", "sigma", "median", "factor_95"}) {
      const std::string key = other;
      if (o.contains(key) && key != center && key != spread) {
        Fail(f + "." + other, std::string("not a key of a ") + name +
                                  " prior (it takes " + center + " and " +
                                  spread + ")");
      }
    }
    for (const char* key : {center, spread}) {
      if (!o.contains(key)) Fail(f + "." + key, "missing");
    }
    Prior prior;
    prior.distribution = *distribution;
    if (normal) {
      prior.center = Number(o["mean"], f + ".mean");
      const std::string problem = ParameterValueProblem(p, prior.center);
      if (!problem.empty()) Fail(f + ".mean", problem);
      prior.spread = Positive(o["sigma"], f + ".sigma");
      if (prior.spread > kMaxParameterMagnitude) Fail(f + ".sigma", ParameterValueProblem(p, prior.spread));
    } else {
      if (Info(p).domain != Domain::kPositive) {
        Fail(f + ".distribution",
             "a lognormal prior needs a positive parameter; '" + it.key() +
                 "' may be zero or negative");
      }
      prior.center = Positive(o["median"], f + ".median");
      const std::string problem = ParameterValueProblem(p, prior.center);
      if (!problem.empty()) Fail(f + ".median", problem);
      prior.spread = Number(o["factor_95"], f + ".factor_95");
      if (!(prior.spread > 1)) Fail(f + ".factor_95", "must be greater than 1");
      if (prior.spread > kMaxParameterMagnitude) {
        Fail(f + ".factor_95", "is absurd: beyond " + Magnitude());
      }
    }
    if (d->known.count(p)) {
      Fail(f, "'" + it.key() + "' is known: a known value needs no prior");
    }
    if (d->ties.count(p)) {
      Fail(f, "'" + it.key() + "' is tied: it takes its value from '" +
                  ParamName(d->ties.at(p)) + "'; put the prior there");
    }
    if (d->IsPerCondition(p)) {
      Fail(f, "priors on per-condition parameters are not supported");
    }
    d->priors[p] = prior;
  }
}

// A condition name: letters, digits, '_', '-', '.'.
bool ValidConditionName(const std::string& name) {
  if (name.empty()) return false;
  for (const char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                    (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
    if (!ok) return false;
  }
  return true;
}

// One element of "conditions", appended to d->conditions and its modes to
// d->modes.
void ReadCondition(const json& j, const std::string& field, Dataset* d) {
  if (!j.is_object()) Fail(field, "must be an object");
  OnlyKeys(j, field, {"name", "speed_m_s", "known", "initial", "modes"});
  Condition c;
  if (!j.contains("name")) Fail(field + ".name", "missing");
  c.name = String(j["name"], field + ".name");
  if (c.name.empty()) Fail(field + ".name", "must not be empty");
  if (!ValidConditionName(c.name)) {
    Fail(field + ".name", "'" + c.name +
                              "' may hold only letters, digits, '_', '-' "
                              "and '.'");
  }
  for (const Condition& before : d->conditions) {
    if (before.name == c.name) {
      Fail(field + ".name", "condition '" + c.name + "' appears twice");
    }
  }
  if (j.contains("speed_m_s")) {
    c.speed_m_s = Number(j["speed_m_s"], field + ".speed_m_s");
    if (c.speed_m_s < 0) Fail(field + ".speed_m_s", "must not be negative");
  }
  for (const char* where : {"known", "initial"}) {
    if (!j.contains(where)) continue;
    const std::string f = field + "." + where;
    auto& values = std::string(where) == "known" ? c.known : c.initial;
    values = Values(j[where], f);
    for (const auto& [p, v] : values) {
      const std::string name = ParamName(p);
      if (!d->IsPerCondition(p)) {
        Fail(f + "." + name, "'" + name +
                                 "' is shared: give it at top level, or list "
                                 "it in per_condition");
      }
      if (&values == &c.initial && c.known.count(p)) {
        Fail(f + "." + name, "also given in known");
      }
    }
  }
  const int index = static_cast<int>(d->conditions.size());
  d->conditions.push_back(c);
  Modes(j, field + ".modes", index, d);
}

// Format 2 (docs/conventions.md §7): several conditions, priors.
void CheckFormat2(const json& j, Dataset* d) {
  d->format = 2;
  if (j.contains("modes")) {
    Fail("modes", "not used in format 2: each condition gives its own modes "
                  "(conditions[i].modes)");
  }
  OnlyKeys(j, "", {"format", "name", "description", "known", "initial", "ties",
                   "priors", "per_condition", "conditions"});
  NameAndDescription(j, d);
  SharedValues(j, d);
  if (j.contains("per_condition")) PerCondition(j["per_condition"], d);
  if (j.contains("priors")) Priors(j["priors"], d);
  if (!j.contains("conditions")) Fail("conditions", "missing");
  const json& conditions = j["conditions"];
  if (!conditions.is_array() || conditions.empty()) {
    Fail("conditions", "must be a non-empty array");
  }
  d->conditions.clear();
  for (size_t i = 0; i < conditions.size(); ++i) {
    ReadCondition(conditions[i], "conditions[" + std::to_string(i) + "]", d);
  }
}

// A file of the other kind, named as what it is rather than by the first key
// a dataset does not have ("parameters: unknown key"). A parameter set may
// leave out its format (LoadParameterSet).
void NotADataset(const json& j) {
  const bool unmarked_set = !j.contains("format") && j.contains("parameters") &&
                            !j.contains("modes") && !j.contains("conditions") &&
                            !j.contains("report");
  if ((j.contains("format") && j["format"] == kParameterSetFormat) || unmarked_set) {
    Fail(unmarked_set ? "parameters" : "format",
         std::string("this is a parameter set (") + kParameterSetFormat +
             "), not a dataset; use --parameters");
  }
  if (!j.contains("format") && j.contains("report") && j["report"].is_string()) {
    Fail("report", "this is a ringid " + j["report"].get<std::string>() +
                       " report, not a dataset");
  }
}

void Check(const json& j, Dataset* d) {
  if (!j.is_object()) Fail("", "top level must be a JSON object");
  NotADataset(j);
  if (j.contains("format") && j["format"] == kDatasetFormat2) {
    CheckFormat2(j, d);
  } else {
    CheckFormat1(j, d);
  }
}

}  // namespace

std::string ParameterValueProblem(Param p, double v) {
  if (!std::isfinite(v)) return "must be finite";
  const Domain d = Info(p).domain;
  if (d == Domain::kPositive && !(v > 0)) return "must be positive";
  if (d == Domain::kNonNegative && v < 0) return "must not be negative";
  if (std::abs(v) > kMaxParameterMagnitude) return "is absurd: beyond " + Magnitude();
  return "";
}

std::string ModeFrequencyProblem(double hz) {
  if (hz >= kMinModeFrequencyHz && hz <= kMaxModeFrequencyHz) return "";
  std::ostringstream o;
  o << hz << " Hz is outside " << kMinModeFrequencyHz << "-" << kMaxModeFrequencyHz
    << " Hz, where every rigid-ring mode lies (a typo, or not a rigid-ring mode?)";
  return o.str();
}

std::string LoadError::OneLine() const {
  std::string line = file + ": ";
  if (!field.empty()) line += field + ": ";
  line += message;
  for (char& c : line) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return line;
}

namespace {

// Parses `text` with the depth and duplicate-key guard, then runs `check`;
// any failure becomes `error`.
bool ParseChecked(const std::string& text, LoadError* error,
                  const std::function<void(const json&)>& check) {
  // Where the parser is, so that a syntax error or an out-of-range number
  // names its field too.
  struct Frame {
    bool array;
    std::string key;
    int count = 0;
  };
  std::vector<Frame> path;
  std::vector<std::set<std::string>> keys;
  auto done_element = [&] {
    if (!path.empty() && path.back().array) ++path.back().count;
  };
  auto where = [&] {
    std::string field;
    for (size_t i = 0; i < path.size(); ++i) {
      if (path[i].array) {
        field += "[" + std::to_string(path[i].count) + "]";
      } else if (!path[i].key.empty()) {
        field += (field.empty() ? "" : ".") + path[i].key;
      }
    }
    return field;
  };
  json::parser_callback_t guard = [&](int depth, json::parse_event_t event,
                                      json& parsed) {
    if (depth > kMaxJsonDepth) {
      throw Failure{"", "nested deeper than " + std::to_string(kMaxJsonDepth)};
    }
    switch (event) {
      case json::parse_event_t::object_start:
        path.push_back({false, ""});
        keys.emplace_back();
        break;
      case json::parse_event_t::array_start:
        path.push_back({true, ""});
        break;
      case json::parse_event_t::key:
        path.back().key = parsed.get<std::string>();
        if (!keys.back().insert(path.back().key).second) {
          throw Failure{where(), "duplicate key"};
        }
        break;
      case json::parse_event_t::object_end:
        keys.pop_back();
        [[fallthrough]];
      case json::parse_event_t::array_end:
        path.pop_back();
        done_element();
        break;
      case json::parse_event_t::value:
        done_element();
        break;
    }
    return true;
  };
  try {
    check(json::parse(text, guard));
  } catch (const Failure& f) {
    error->field = f.field;
    error->message = f.message;
    return false;
  } catch (const json::out_of_range& e) {
    error->field = where();
    error->message = "number out of range";
    return false;
  } catch (const json::parse_error& e) {
    error->field = where();
    error->message = "not valid JSON (at byte " + std::to_string(e.byte) + ")";
    return false;
  } catch (const json::exception& e) {
    error->field = where();
    error->message = "invalid JSON";
    return false;
  }
  return true;
}

// A parameter set, or an identify report read back as one: only the
// "parameters" object is read, each entry a number or {"value": number}.
void CheckParameterSet(const json& j, Parameters* p, Undetermined* undetermined) {
  if (!j.is_object()) Fail("", "top level must be a JSON object");
  if (j.contains("format") && (j["format"] == kDatasetFormat1 || j["format"] == kDatasetFormat2)) {
    Fail("format", "this is a modal dataset (" + j["format"].get<std::string>() +
                       "), not a parameter set");
  }
  if (j.contains("format") && j["format"] != kParameterSetFormat) {
    Fail("format", std::string("must be \"") + kParameterSetFormat + "\"");
  }
  if (!j.contains("parameters") || !j["parameters"].is_object()) {
    Fail("parameters", "missing or not an object");
  }
  const json& ps = j["parameters"];
  for (auto it = ps.begin(); it != ps.end(); ++it) {
    const std::string field = "parameters." + it.key();
    const Param param = ParamCalled(it.key(), field);
    const json& v = it.value().is_object() && it.value().contains("value")
                        ? it.value()["value"]
                        : it.value();
    const std::string f = field + (it.value().is_object() ? ".value" : "");
    (*p)[param] = Number(v, f);
    const std::string problem = ParameterValueProblem(param, (*p)[param]);
    if (!problem.empty()) Fail(f, problem);
    if (!it.value().is_object()) continue;
    // What identify said of it (its report, or --save_parameters).
    std::string why;
    if (it.value().contains("identifiable")) {
      const std::string c = String(it.value()["identifiable"], field + ".identifiable");
      if (c != "yes" && c != "practically_no" && c != "no") {
        Fail(field + ".identifiable", "must be yes, practically_no or no");
      }
      if (c != "yes") why = "classed " + c + " by ringid identify";
    }
    if (it.value().contains("condition") && !it.value()["condition"].is_null()) {
      why += (why.empty() ? "" : "; ") + String(it.value()["condition"], field + ".condition");
    }
    if (undetermined && !why.empty()) (*undetermined)[param] = why;
  }
}

}  // namespace

bool ParseJsonInput(const std::string& text, json* out, LoadError* error) {
  return ParseChecked(text, error, [&](const json& j) { *out = j; });
}

bool ParseDataset(const std::string& text, const std::string& path,
                  Dataset* dataset, LoadError* error) {
  *dataset = Dataset{};
  dataset->path = path;
  error->file = path;
  return ParseChecked(text, error, [&](const json& j) { Check(j, dataset); });
}

bool LoadParameterSet(const std::string& path, Parameters* p,
                      LoadError* error, Undetermined* undetermined) {
  std::string text;
  if (!ReadInputFile(path, &text, error)) return false;
  *p = Parameters{};
  if (undetermined) undetermined->clear();
  return ParseChecked(text, error,
                      [&](const json& j) { CheckParameterSet(j, p, undetermined); });
}

bool ReadInputFile(const std::string& path, std::string* text,
                   LoadError* error) {
  error->file = path;
  error->field = "";
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error->message = "cannot open file";
    return false;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) {
    error->message = "cannot read file";
    return false;
  }
  *text = buffer.str();
  if (static_cast<long>(text->size()) > kMaxFileBytes) {
    error->message = "larger than " + std::to_string(kMaxFileBytes) + " bytes";
    return false;
  }
  return true;
}

bool LoadDataset(const std::string& path, Dataset* dataset, LoadError* error) {
  std::string text;
  return ReadInputFile(path, &text, error) &&
         ParseDataset(text, path, dataset, error);
}

bool Dataset::IsPerCondition(Param p) const {
  return std::find(per_condition.begin(), per_condition.end(), p) != per_condition.end();
}

Parameters InitialParameters(const Dataset& d, int condition) {
  Parameters p;
  for (const auto& [k, v] : d.known) p[k] = v;
  for (const auto& [k, v] : d.initial) p[k] = v;
  for (const auto& [k, v] : d.conditions[condition].known) p[k] = v;
  for (const auto& [k, v] : d.conditions[condition].initial) p[k] = v;
  for (const auto& [from, to] : d.ties) p[from] = p[to];
  return p;
}

bool FixParameters(const std::vector<Param>& fixed, Dataset* d, std::string* why) {
  for (Param p : fixed) {
    bool moved = false;
    if (const auto it = d->initial.find(p); it != d->initial.end()) {
      d->known[p] = it->second;
      d->initial.erase(it);
      moved = true;
    }
    for (Condition& c : d->conditions) {
      if (const auto it = c.initial.find(p); it != c.initial.end()) {
        c.known[p] = it->second;
        c.initial.erase(it);
        moved = true;
      }
    }
    if (!moved) {
      *why = std::string("fix: ") + ParamName(p) + " is not free in " + d->path +
             (d->ties.count(p) ? " (it is tied)" : "");
      return false;
    }
    d->priors.erase(p);
  }
  return true;
}

}  // namespace ringid
