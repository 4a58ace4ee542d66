#include "datasets/dataset.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "datasets/dataset_file.h"
#include "datasets/file_kind.h"
#include "datasets/load_failure.h"
#include "model/spelling.h"

namespace ringid {
namespace {

using internal::Fail;  // caught in ParseDataset
using internal::Failure;

using nlohmann::json;


// "1e+12 in magnitude", for messages.
std::string Magnitude() {
  std::ostringstream o;
  o << kMaxParameterMagnitude << " in magnitude";
  return o.str();
}


// The archive reads null as a number that is not finite.
double Finite(double v, const std::string& field) {
  if (!std::isfinite(v)) Fail(field, "must be a number");
  return v;
}

double Positive(double v, const std::string& field) {
  if (!(Finite(v, field) > 0)) Fail(field, "must be positive");
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

std::map<Param, double> Values(const NamedValues& values, const std::string& field) {
  std::map<Param, double> out;
  for (const auto& [name, v] : values) {
    const std::string f = field + "." + name;
    const Param p = ParamCalled(name, f);
    const std::string problem = ParameterValueProblem(p, Finite(v, f));
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

MeasuredMode ReadMode(const ModeFields& j, const std::string& field) {
  MeasuredMode m;
  const auto parsed = ParseLabel(j.label);
  if (!parsed) Fail(field + ".label", UnknownName("label", j.label, MeasurableLabels()));
  if (LabelPlane(*parsed) == Plane::kHub) {  // not a typo: nothing to suggest
    Fail(field + ".label", "'" + j.label + "' is a mode of the hub, which a dataset does not "
                          "list (expected " + OneOf(MeasurableLabels()) + ")");
  }
  m.label = *parsed;
  if (j.plane) {
    if (*j.plane != "in_plane" && *j.plane != "out_of_plane") {
      Fail(field + ".plane", "must be in_plane or out_of_plane");
    }
    if (*j.plane != PlaneName(LabelPlane(m.label))) {
      Fail(field + ".plane", "'" + *j.plane + "' contradicts label '" + j.label + "'");
    }
  }
  m.frequency_hz = Positive(j.frequency_hz, field + ".frequency_hz");
  const std::string problem = ModeFrequencyProblem(m.frequency_hz);
  if (!problem.empty()) Fail(field + ".frequency_hz", problem);
  if (j.frequency_sigma_hz) {
    m.frequency_sigma_hz = Positive(*j.frequency_sigma_hz, field + ".frequency_sigma_hz");
  }
  if (j.damping_ratio) {
    const double z = Finite(*j.damping_ratio, field + ".damping_ratio");
    const std::string problem = DampingRatioProblem(z);
    if (!problem.empty()) Fail(field + ".damping_ratio", problem);
    m.damping_ratio = z;
  }
  if (j.damping_sigma) {
    if (!m.damping_ratio) Fail(field + ".damping_sigma", "given without damping_ratio");
    m.damping_sigma = Positive(*j.damping_sigma, field + ".damping_sigma");
  }
  if (j.shape) {
    if (j.shape->empty()) {
      Fail(field + ".shape", "must be a non-empty object of components");
    }
    double largest = 0;
    for (const auto& [name, v] : *j.shape) {
      const std::string f = field + ".shape." + name;
      const auto dof = ParseDof(name);
      if (!dof) Fail(f, UnknownName("degree of freedom", name, NamesOf<Dof>()));
      largest = std::max(largest, std::abs(Finite(v, f)));
      m.shape.emplace_back(*dof, v);
    }
    if (!(largest > 0)) Fail(field + ".shape", "all components are zero");
  }
  if (j.shape_sigma) {
    if (m.shape.empty()) Fail(field + ".shape_sigma", "given without shape");
    m.shape_sigma = Positive(*j.shape_sigma, field + ".shape_sigma");
  }
  return m;
}

// The shared "known", "initial" and "ties" of both formats.
void SharedValues(const DatasetFields& j, Dataset* d) {
  if (j.known) d->known = Values(*j.known, "known");
  if (j.initial) d->initial = Values(*j.initial, "initial");
  for (const auto& [p, v] : d->initial) {
    if (d->known.count(p)) Fail(std::string("initial.") + ParamName(p), "also given in known");
  }
  if (!j.ties) return;
  for (const auto& [name, target] : *j.ties) {
    const std::string f = "ties." + name;
    const Param from = ParamCalled(name, f);
    const Param to = ParamCalled(target, f);
    if (from == to) Fail(f, "tied to itself");
    if (Info(from).domain != Info(to).domain) Fail(f, "ties parameters of different kinds");
    if (d->known.count(from) || d->initial.count(from)) {
      Fail(f, "a tied parameter takes its value from its target; remove it from known/initial");
    }
    d->ties[from] = to;
  }
  for (const auto& [from, to] : d->ties) {
    if (d->ties.count(to)) {
      Fail(std::string("ties.") + ParamName(from),
           std::string("target '") + ParamName(to) + "' is itself tied");
    }
  }
}

// The modes at `field` (of condition `condition`), appended to d->modes; a
// label at most once among them.
void Modes(const std::vector<ModeFields>& modes, const std::string& field, int condition,
           Dataset* d) {
  if (modes.empty()) Fail(field, "must be a non-empty array");
  if (modes.size() > static_cast<size_t>(kMaxModes)) {
    Fail(field, "more than " + std::to_string(kMaxModes) + " modes (one per contract label)");
  }
  std::set<ModeLabel> seen;
  for (size_t i = 0; i < modes.size(); ++i) {
    const std::string f = field + "[" + std::to_string(i) + "]";
    d->modes.push_back(ReadMode(modes[i], f));
    d->modes.back().condition = condition;
    if (!seen.insert(d->modes.back().label).second) {
      Fail(f + ".label",
           std::string("label '") + LabelName(d->modes.back().label) + "' appears twice");
    }
  }
}

// "per_condition": parameter names, each at most once, none shared (top-level
// known/initial) or tied; kept in catalogue order.
void PerCondition(const std::vector<std::string>& names, Dataset* d) {
  for (size_t i = 0; i < names.size(); ++i) {
    const std::string f = "per_condition[" + std::to_string(i) + "]";
    const std::string& name = names[i];
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
void Priors(const std::map<std::string, PriorFields>& priors, Dataset* d) {
  for (const auto& [name, o] : priors) {
    const std::string f = "priors." + name;
    const Param p = ParamCalled(name, f);
    const auto distribution = FromString<PriorDistribution>(o.distribution);
    if (!distribution) {
      Fail(f + ".distribution", "must be " + EnumChoices<PriorDistribution>());
    }
    const bool normal = *distribution == PriorDistribution::kNormal;
    const char* center = normal ? "mean" : "median";
    const char* spread = normal ? "sigma" : "factor_95";
    const std::pair<const char*, const std::optional<double>*> given[] = {
        {"mean", &o.mean}, {"sigma", &o.sigma}, {"median", &o.median}, {"factor_95", &o.factor_95}};
    for (const auto& [key, value] : given) {
      if (value->has_value() && key != std::string(center) && key != std::string(spread)) {
        Fail(f + "." + key, std::string("not a key of a ") + o.distribution +
                                " prior (it takes " + center + " and " + spread + ")");
      }
    }
    for (const auto& [key, value] : given) {
      if ((key == std::string(center) || key == std::string(spread)) && !value->has_value()) {
        Fail(f + "." + key, "missing");
      }
    }
    Prior prior;
    prior.distribution = *distribution;
    if (normal) {
      prior.center = Finite(*o.mean, f + ".mean");
      const std::string problem = ParameterValueProblem(p, prior.center);
      if (!problem.empty()) Fail(f + ".mean", problem);
      prior.spread = Positive(*o.sigma, f + ".sigma");
      if (prior.spread > kMaxParameterMagnitude) Fail(f + ".sigma", ParameterValueProblem(p, prior.spread));
    } else {
      if (Info(p).domain != Domain::kPositive) {
        Fail(f + ".distribution", "a lognormal prior needs a positive parameter fitted in log; '" +
                                      name + "' is not");
      }
      prior.center = Positive(*o.median, f + ".median");
      const std::string problem = ParameterValueProblem(p, prior.center);
      if (!problem.empty()) Fail(f + ".median", problem);
      prior.spread = Finite(*o.factor_95, f + ".factor_95");
      if (!(prior.spread > 1)) Fail(f + ".factor_95", "must be greater than 1");
      if (prior.spread > kMaxParameterMagnitude) {
        Fail(f + ".factor_95", "is absurd: beyond " + Magnitude());
      }
    }
    if (d->known.count(p)) Fail(f, "'" + name + "' is known: a known value needs no prior");
    if (d->ties.count(p)) {
      Fail(f, "'" + name + "' is tied: it takes its value from '" + ParamName(d->ties.at(p)) +
                  "'; put the prior there");
    }
    if (d->IsPerCondition(p)) Fail(f, "priors on per-condition parameters are not supported");
    d->priors[p] = prior;
  }
}

// The static stiffnesses at `field` of a condition at `speed`, appended to
// d->statics (contract §10): standing only, one per direction.
void Statics(const std::vector<StaticFields>& statics, const std::string& field, int condition,
             double speed, Dataset* d) {
  if (statics.empty()) Fail(field, "must be a non-empty array");
  if (speed > 0) {
    Fail(field, "a static stiffness is measured standing: this condition's speed_m_s is not 0 "
                "(contract §10)");
  }
  std::set<StaticDirection> seen;
  for (size_t i = 0; i < statics.size(); ++i) {
    const std::string f = field + "[" + std::to_string(i) + "]";
    MeasuredStatic m;
    m.direction = statics[i].kind;
    m.value = Positive(statics[i].value, f + ".value");
    if (std::abs(m.value) > kMaxParameterMagnitude) Fail(f + ".value", "is absurd: beyond " + Magnitude());
    if (statics[i].sigma) m.sigma = Positive(*statics[i].sigma, f + ".sigma");
    m.condition = condition;
    if (!seen.insert(m.direction).second) {
      Fail(f + ".kind", std::string("'") + ToString(m.direction) + "' appears twice");
    }
    d->statics.push_back(m);
  }
}

// One element of "conditions", appended to d->conditions and its modes to
// d->modes.
void ReadCondition(const ConditionFields& j, const std::string& field, Dataset* d) {
  Condition c;
  c.name = j.name;
  if (c.name.empty()) Fail(field + ".name", "must not be empty");
  if (!ValidConditionName(c.name)) {
    Fail(field + ".name", "'" + c.name + "' may hold only letters, digits, '_', '-' and '.'");
  }
  for (const Condition& before : d->conditions) {
    if (before.name == c.name) Fail(field + ".name", "condition '" + c.name + "' appears twice");
  }
  if (j.speed_m_s) {
    c.speed_m_s = Finite(*j.speed_m_s, field + ".speed_m_s");
    if (c.speed_m_s < 0) Fail(field + ".speed_m_s", "must not be negative");
  }
  for (const bool known : {true, false}) {
    const auto& given = known ? j.known : j.initial;
    if (!given) continue;
    const std::string f = field + (known ? ".known" : ".initial");
    auto& values = known ? c.known : c.initial;
    values = Values(*given, f);
    for (const auto& [p, v] : values) {
      const std::string name = ParamName(p);
      if (!d->IsPerCondition(p)) {
        Fail(f + "." + name, "'" + name + "' is shared: give it at top level, or list it in "
                                          "per_condition");
      }
      if (!known && c.known.count(p)) Fail(f + "." + name, "also given in known");
    }
  }
  const int index = static_cast<int>(d->conditions.size());
  d->conditions.push_back(c);
  if (d->format == 2 && !j.modes) Fail(field + ".modes", "missing");
  for (const auto& [given, name] : {std::pair{j.statics.has_value(), "static"},
                                     std::pair{j.frf.has_value(), "frf"},
                                     std::pair{j.obstacle.has_value(), "obstacle"}}) {
    if (d->format == 2 && given) {
      Fail(field + "." + name, std::string("needs format \"") + kDatasetFormat3 + "\" (contract §10)");
    }
  }
  if (j.modes) Modes(*j.modes, field + ".modes", index, d);
  if (j.frf) {
    LoadError error;
    d->conditions.back().frf.emplace();
    if (!ReadFrf(*j.frf, c.speed_m_s, d->path, field + ".frf", &*d->conditions.back().frf, &error)) {
      Fail(error.field, error.message);
    }
  }
  if (j.statics) Statics(*j.statics, field + ".static", index, c.speed_m_s, d);
  if (j.obstacle) {
    LoadError error;
    d->conditions.back().obstacle.emplace();
    if (!ReadObstacle(*j.obstacle, c.speed_m_s, d->path, field + ".obstacle",
                      &*d->conditions.back().obstacle, &error)) {
      Fail(error.field, error.message);
    }
  }
  if (!j.modes && !j.statics && !j.frf && !j.obstacle) {
    Fail(field, "holds no measurement: give it modes, frf, static or obstacle (contract §10)");
  }
}

// What the field list cannot say of a file the archive has read.
void Check(const DatasetFields& j, Dataset* d) {
  d->name = j.name;
  if (d->name.empty()) Fail("name", "must not be empty");
  d->description = j.description.value_or("");
  SharedValues(j, d);
  if (j.format == kDatasetFormat1) {
    Modes(j.modes, "modes", 0, d);
    return;
  }
  d->format = j.format == kDatasetFormat3 ? 3 : 2;
  if (j.per_condition) PerCondition(*j.per_condition, d);
  if (j.priors) Priors(*j.priors, d);
  if (j.conditions.empty()) Fail("conditions", "must be a non-empty array");
  d->conditions.clear();
  for (size_t i = 0; i < j.conditions.size(); ++i) {
    ReadCondition(j.conditions[i], "conditions[" + std::to_string(i) + "]", d);
  }
}

// Before the field list: a file of another kind, named as what it is rather
// than by the first key a dataset does not have ("parameters: unknown key"),
// and the format that decides which fields follow. A parameter set may leave
// out its format (LoadParameterSet).
void CheckKind(const json& j) {
  if (!j.is_object()) Fail("", "top level must be a JSON object");
  const SniffedFile kind = SniffJson(j);
  if (kind.kind != FileKind::kUnknown && kind.kind != FileKind::kModalDataset) {
    Fail(kind.field, NotTheKind(kind, "a dataset"));
  }
  if (!j.contains("format")) Fail("format", "missing");
  const std::string format = String(j["format"], "format");
  if (format != kDatasetFormat1 && format != kDatasetFormat2 && format != kDatasetFormat3) {
    Fail("format", std::string("must be \"") + kDatasetFormat1 + "\", \"" + kDatasetFormat2 +
                       "\" or \"" + kDatasetFormat3 + "\"");
  }
  if (format != kDatasetFormat1 && j.contains("modes")) {
    Fail("modes", "not used in format " + format.substr(format.size() - 1) +
                      ": each condition gives its own modes (conditions[i].modes)");
  }
}

// The archive's "FIELD: MESSAGE" as a Failure.
[[noreturn]] void FailWith(const std::string& archive_error) {
  LoadError e;
  SetArchiveError(archive_error, &e);
  Fail(e.field, e.message);
}

void Read(const json& j, Dataset* d) {
  CheckKind(j);
  DatasetFields fields;
  std::string error;
  if (!JsonReader::FromJson(Json(j), "", &fields, &error)) FailWith(error);
  Check(fields, d);
}

}  // namespace

std::string ParameterValueProblem(Param p, double v) {
  if (!std::isfinite(v)) return "must be finite";
  const Domain d = Info(p).domain;
  if (d == Domain::kPositive && !(v > 0)) return "must be positive";
  if (d == Domain::kNonNegative && v < 0) return "must not be negative";
  if (d == Domain::kAboveOne && !(v > 1)) return "must be greater than 1";
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

std::string DampingRatioProblem(double zeta) {
  if (zeta > kMinDampingRatio && zeta < kMaxDampingRatio) return "";
  std::ostringstream o;
  o << "must lie in (" << kMinDampingRatio << ", " << kMaxDampingRatio << ")";
  return o.str();
}

bool ValidConditionName(const std::string& name) {
  if (name.empty()) return false;
  for (const char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                    (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
    if (!ok) return false;
  }
  return true;
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

}  // namespace

bool ParseJsonInput(const std::string& text, Json* out, LoadError* error) {
  return ParseChecked(text, error, [&](const json& j) { *out = Json(j); });
}

void SetArchiveError(const std::string& archive_error, LoadError* error) {
  const size_t colon = archive_error.find(": ");
  error->field = colon == std::string::npos ? "" : archive_error.substr(0, colon);
  error->message = colon == std::string::npos ? archive_error : archive_error.substr(colon + 2);
}

bool ParseDataset(const std::string& text, const std::string& path,
                  Dataset* dataset, LoadError* error) {
  *dataset = Dataset{};
  dataset->path = path;
  error->file = path;
  return ParseChecked(text, error, [&](const json& j) { Read(j, dataset); });
}

bool ReadInputFile(const std::string& path, std::string* text, LoadError* error,
                   long max_bytes) {
  error->file = path;
  error->field = "";
  if (SniffPath(path).kind == FileKind::kDirectory) {
    error->message = "a directory, not a file";
    return false;
  }
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
  if (static_cast<long>(text->size()) > max_bytes) {
    error->message = "larger than " + std::to_string(max_bytes) + " bytes";
    return false;
  }
  return true;
}

bool LoadDataset(const std::string& path, Dataset* dataset, LoadError* error) {
  std::string text;
  if (!ReadInputFile(path, &text, error)) return false;
  // Not JSON at all: a .tir or a UFF file, named as such (the JSON kinds: CheckKind).
  if (const SniffedFile kind = SniffFile(path, text); kind.kind != FileKind::kUnknown) {
    error->message = NotTheKind(kind, "a dataset");
    return false;
  }
  return ParseDataset(text, path, dataset, error);
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
