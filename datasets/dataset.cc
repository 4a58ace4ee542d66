#include "datasets/dataset.h"

#include <cmath>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

namespace ringid {
namespace {

using nlohmann::json;

// Thrown inside the loader only, caught in ParseDataset.
struct Failure {
  std::string field;
  std::string message;
};

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
  if (!p) Fail(field, "unknown parameter '" + name + "'");
  return *p;
}

std::map<Param, double> Values(const json& j, const std::string& field) {
  if (!j.is_object()) Fail(field, "must be an object of parameter values");
  std::map<Param, double> out;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string f = field + "." + it.key();
    const Param p = ParamCalled(it.key(), f);
    const double v = Number(it.value(), f);
    const Domain d = Info(p).domain;
    if (d == Domain::kPositive && !(v > 0)) Fail(f, "must be positive");
    if (d == Domain::kNonNegative && v < 0) Fail(f, "must not be negative");
    out[p] = v;
  }
  return out;
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
  if (!parsed || LabelPlane(*parsed) == Plane::kHub) {
    Fail(field + ".label", "unknown label '" + label + "'");
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
      if (!dof) Fail(f, "unknown degree of freedom '" + it.key() + "'");
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

void Check(const json& j, Dataset* d) {
  if (!j.is_object()) Fail("", "top level must be a JSON object");
  OnlyKeys(j, "", {"format", "name", "description", "known", "initial", "ties",
                   "modes"});
  if (!j.contains("format")) Fail("format", "missing");
  if (String(j["format"], "format") != "ringid-modal-dataset/1") {
    Fail("format", "must be \"ringid-modal-dataset/1\"");
  }
  if (!j.contains("name")) Fail("name", "missing");
  d->name = String(j["name"], "name");
  if (d->name.empty()) Fail("name", "must not be empty");
  if (j.contains("description")) {
    d->description = String(j["description"], "description");
  }
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
  if (!j.contains("modes")) Fail("modes", "missing");
  const json& modes = j["modes"];
  if (!modes.is_array() || modes.empty()) {
    Fail("modes", "must be a non-empty array");
  }
  if (modes.size() > static_cast<size_t>(kMaxModes)) {
    Fail("modes", "more than " + std::to_string(kMaxModes) +
                      " modes (one per contract label)");
  }
  std::set<ModeLabel> seen;
  for (size_t i = 0; i < modes.size(); ++i) {
    const std::string f = "modes[" + std::to_string(i) + "]";
    d->modes.push_back(Mode(modes[i], f));
    if (!seen.insert(d->modes.back().label).second) {
      Fail(f + ".label", std::string("label '") +
                             LabelName(d->modes.back().label) +
                             "' appears twice");
    }
  }
}

}  // namespace

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
void CheckParameterSet(const json& j, Parameters* p) {
  if (!j.is_object()) Fail("", "top level must be a JSON object");
  if (j.contains("format") && j["format"] != "ringid-parameters/1") {
    Fail("format", "must be \"ringid-parameters/1\"");
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
    (*p)[param] = Number(v, field + (it.value().is_object() ? ".value" : ""));
  }
}

}  // namespace

bool ParseDataset(const std::string& text, const std::string& path,
                  Dataset* dataset, LoadError* error) {
  *dataset = Dataset{};
  dataset->path = path;
  error->file = path;
  return ParseChecked(text, error, [&](const json& j) { Check(j, dataset); });
}

bool LoadParameterSet(const std::string& path, Parameters* p,
                      LoadError* error) {
  std::string text;
  if (!ReadInputFile(path, &text, error)) return false;
  *p = Parameters{};
  return ParseChecked(text, error,
                      [&](const json& j) { CheckParameterSet(j, p); });
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

std::string DatasetToJson(const Dataset& d) {
  json j;
  j["format"] = "ringid-modal-dataset/1";
  j["name"] = d.name;
  if (!d.description.empty()) j["description"] = d.description;
  auto values = [](const std::map<Param, double>& m) {
    json o = json::object();
    for (const auto& [p, v] : m) o[ParamName(p)] = v;
    return o;
  };
  if (!d.known.empty()) j["known"] = values(d.known);
  if (!d.initial.empty()) j["initial"] = values(d.initial);
  if (!d.ties.empty()) {
    json t = json::object();
    for (const auto& [a, b] : d.ties) t[ParamName(a)] = ParamName(b);
    j["ties"] = t;
  }
  j["modes"] = json::array();
  for (const MeasuredMode& m : d.modes) {
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
    j["modes"].push_back(o);
  }
  // Names may come from file names, which need not be UTF-8.
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

Parameters InitialParameters(const Dataset& d) {
  Parameters p;
  for (const auto& [k, v] : d.known) p[k] = v;
  for (const auto& [k, v] : d.initial) p[k] = v;
  for (const auto& [from, to] : d.ties) p[from] = p[to];
  return p;
}

}  // namespace ringid
