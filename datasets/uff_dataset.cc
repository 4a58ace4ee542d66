#include "datasets/uff_dataset.h"

#include <cmath>
#include <complex>
#include <algorithm>
#include <cstdio>
#include <set>

#include "datasets/measurement.h"
#include "datasets/pairing.h"
#include "datasets/uff_frf.h"
#include "model/rigid_ring_model.h"
#include "model/spelling.h"

namespace ringid {
namespace {

bool Fail(LoadError* error, const std::string& field, const std::string& message) {
  error->field = field;
  error->message = message;
  return false;
}

// Format 2's axes: each of ringid's x, y, z as a lab axis with its sign.
bool CheckAxes(const std::vector<std::string>& axes, UffMap* map, LoadError* error) {
  if (axes.size() != 3) {
    return Fail(error, "axes", "must be three lab axes, ringid's x, y and z (e.g. [\"x\", \"-y\", \"-z\"])");
  }
  std::set<int> used;
  for (size_t i = 0; i < 3; ++i) {
    const std::string& a = axes[i];
    const std::string at = "axes[" + std::to_string(i) + "]";
    const bool minus = !a.empty() && a[0] == '-';
    const std::string axis = a.substr(!a.empty() && (a[0] == '-' || a[0] == '+') ? 1 : 0);
    if (axis != "x" && axis != "y" && axis != "z") {
      return Fail(error, at, "must be a lab axis x, y or z, signed: \"-z\" for the lab's -z");
    }
    const int k = axis[0] - 'x';
    if (!used.insert(k).second) return Fail(error, at, "names lab axis " + axis + " twice");
    map->axes[i] = {0, 0, 0};
    map->axes[i][k] = minus ? -1 : 1;
  }
  const auto& m = map->axes;
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  if (det < 0) {
    return Fail(error, "axes", "turn a right-handed frame into a left-handed one (a mirror): "
                               "flip the sign of one axis");
  }
  return true;
}

// Format 2's points, units and averages.
bool CheckFrfFields(const UffMapFields& j, UffMap* map, LoadError* error) {
  if (j.axes && !CheckAxes(*j.axes, map, error)) return false;
  const std::vector<UffPointFields> points = j.points.value_or(std::vector<UffPointFields>{});
  std::set<int> nodes;
  for (size_t i = 0; i < points.size(); ++i) {
    const UffPointFields& p = points[i];
    const std::string at = "points[" + std::to_string(i) + "]";
    if (p.node <= 0) return Fail(error, at + ".node", "must be a positive node label");
    if (!nodes.insert(p.node).second) {
      return Fail(error, at + ".node", "node " + std::to_string(p.node) + " is placed twice");
    }
    UffMap::Point point{p.node, p.on, std::nullopt};
    if (p.point_m) {
      if (p.point_m->size() != 3) return Fail(error, at + ".point_m", "must be three numbers [x, y, z] in metres");
      for (size_t k = 0; k < 3; ++k) {
        if (!std::isfinite((*p.point_m)[k])) return Fail(error, at + ".point_m[" + std::to_string(k) + "]", "must be a number");
      }
      point.point_m = std::array<double, 3>{(*p.point_m)[0], (*p.point_m)[1], (*p.point_m)[2]};
    }
    map->points.push_back(point);
  }
  if (j.units) {
    const std::pair<const char*, const std::optional<std::string>*> given[] = {
        {"response", &j.units->response}, {"reference", &j.units->reference}};
    for (const auto& [key, unit] : given) {
      if (!*unit) continue;
      const bool force = std::string(key) == "reference";
      const std::string problem = UffUnitProblem(**unit, force);
      if (!problem.empty()) return Fail(error, std::string("units.") + key, problem);
      (force ? map->reference_unit : map->response_unit) = **unit;
    }
  }
  if (j.averages && *j.averages < 1) return Fail(error, "averages", "must be at least 1");
  map->averages = j.averages;
  return true;
}

bool CheckMap(const UffMapFields& j, UffMap* map, LoadError* error) {
  const bool format2 = j.format == kUffMapFormat2;
  if (j.format != kUffMapFormat && !format2) {
    return Fail(error, "format", std::string("must be \"") + kUffMapFormat + "\" or \"" +
                                     kUffMapFormat2 + "\"");
  }
  if (j.name.empty()) return Fail(error, "name", "must not be empty");
  map->name = j.name;
  map->description = j.description.value_or("");
  const std::vector<UffChannelFields> channels =
      format2 ? j.channels2.value_or(std::vector<UffChannelFields>{}) : j.channels;
  if (format2 && channels.empty() && (!j.points || j.points->empty())) {
    return Fail(error, "points", "a map places FRF nodes (points) or maps mode channels "
                                 "(channels): give at least one");
  }
  if (!format2 && channels.empty()) return Fail(error, "channels", "must name at least one channel");
  if (format2 && !CheckFrfFields(j, map, error)) return false;
  std::set<std::pair<int, int>> seen;
  for (size_t i = 0; i < channels.size(); ++i) {
    const UffChannelFields& c = channels[i];
    const std::string at = "channels[" + std::to_string(i) + "]";
    if (c.node <= 0) return Fail(error, at + ".node", "must be a positive node label");
    if (std::abs(c.direction) < 1 || std::abs(c.direction) > 6) {
      return Fail(error, at + ".direction", "must be 1..6 (x, y, z; rotations about them)");
    }
    if (!seen.insert({c.node, std::abs(c.direction)}).second) {
      return Fail(error, at, "node " + std::to_string(c.node) + " direction " +
                                 std::to_string(std::abs(c.direction)) + " is mapped twice");
    }
    const std::optional<Dof> dof = ParseDof(c.dof);
    if (!dof) return Fail(error, at + ".dof", UnknownName("degree of freedom", c.dof, NamesOf<Dof>()));
    const double sign = c.sign.value_or(1);
    if (sign != 1 && sign != -1) return Fail(error, at + ".sign", "must be 1 or -1");
    map->channels.push_back({c.node, std::abs(c.direction), *dof, c.direction < 0 ? -sign : sign});
  }
  const std::vector<UffLabelFields> labels = j.labels.value_or(std::vector<UffLabelFields>{});
  for (size_t i = 0; i < labels.size(); ++i) {
    const std::string at = "labels[" + std::to_string(i) + "]";
    const std::optional<ModeLabel> label = ParseLabel(labels[i].label);
    if (!label) {
      return Fail(error, at + ".label", UnknownName("label", labels[i].label, NamesOf<ModeLabel>()));
    }
    if (map->labels.count(labels[i].mode)) return Fail(error, at + ".mode", "mode labelled twice");
    for (const auto& [mode, other] : map->labels) {
      if (other == *label) return Fail(error, at + ".label", "label given to two modes");
    }
    map->labels[labels[i].mode] = *label;
  }
  for (const std::string& name : j.known.value_or(std::vector<std::string>{})) {
    const std::optional<Param> q = ParseParam(name);
    if (!q) return Fail(error, "known", UnknownName("parameter", name, NamesOf<Param>()));
    map->known.push_back(*q);
  }
  return true;
}

bool IsTranslation(Dof d) {
  return d == Dof::kXb || d == Dof::kZb || d == Dof::kYb || d == Dof::kXa || d == Dof::kZa ||
         d == Dof::kYa;
}

std::string Where(const UffModalData& m) {
  return "dataset 55 (line " + std::to_string(m.line) + ") mode " + std::to_string(m.mode_number);
}

// The measured shape of `m` on the map's channels, real as the contract's §2.
bool Shape(const UffModalData& m, const UffMap& map, const UffUnits* units,
           std::vector<std::pair<Dof, double>>* shape, LoadError* error) {
  std::vector<std::pair<Dof, std::complex<double>>> complex;
  for (size_t k = 0; k < map.channels.size(); ++k) {
    const UffMap::Channel& c = map.channels[k];
    bool found = false;
    for (const UffNodeValues& n : m.nodes) found |= n.label == c.node;
    if (!found) {  // else that degree of freedom would drop out of the shape unsaid
      std::string held;
      for (size_t i = 0; i < m.nodes.size() && i < 8; ++i) {
        held += (i ? ", " : "") + std::to_string(m.nodes[i].label);
      }
      if (m.nodes.size() > 8) held += ", ... (" + std::to_string(m.nodes.size()) + " nodes)";
      return Fail(error, Where(m), "the map's channels[" + std::to_string(k) + "] names node " +
                                       std::to_string(c.node) + " direction " +
                                       std::to_string(c.direction) + " (" + DofName(c.dof) +
                                       "), which this record does not hold (its nodes: " +
                                       (held.empty() ? "none" : held) +
                                       "; 'ringid import --uff=FILE' lists them)");
    }
    for (const UffNodeValues& n : m.nodes) {
      if (n.label != c.node) continue;
      if (c.direction > static_cast<int>(n.values.size())) {
        return Fail(error, Where(m), "the map's channels[" + std::to_string(k) + "] names node " +
                                         std::to_string(c.node) + " direction " +
                                         std::to_string(c.direction) + ", and the node holds " +
                                         std::to_string(n.values.size()) + " values (directions 1-" +
                                         std::to_string(n.values.size()) + ")");
      }
      std::complex<double> v = c.sign * n.values[c.direction - 1];
      if (units && IsTranslation(c.dof)) v = units->LengthToSi(1.0) * v;
      for (const auto& [dof, value] : complex) {
        if (dof == c.dof) return Fail(error, Where(m), std::string(DofName(c.dof)) + " is mapped from two channels");
      }
      complex.push_back({c.dof, v});
    }
  }
  if (complex.empty()) return true;
  size_t largest = 0;
  for (size_t i = 1; i < complex.size(); ++i) {
    if (std::abs(complex[i].second) > std::abs(complex[largest].second)) largest = i;
  }
  const double size = std::abs(complex[largest].second);
  if (!(size > 0)) return Fail(error, Where(m), "the mapped channels are all zero");
  const std::complex<double> turn = std::conj(complex[largest].second) / size;
  for (const auto& [dof, v] : complex) shape->push_back({dof, std::real(turn * v) / size});
  return true;
}

// Labels the modes the map does not by the model's modes at `p` that the map
// left, by the one pairing rule (datasets/pairing.h; their labels unknown).
bool LabelByModel(const Parameters& p, ShapeConvention convention,
                  const std::set<ModeLabel>& taken, const std::vector<int>& unlabelled,
                  const std::vector<std::string>& names, std::vector<MeasuredMode>* modes,
                  UffImport* out, LoadError* error) {
  const ModalSolution s = RigidRingModel().Solve(p);
  if (!s.ok) return Fail(error, "parameters", "the model has no modes there: " + s.error);
  std::vector<const Mode*> free;
  for (const Mode& m : s.modes) {
    if (!taken.count(m.label)) free.push_back(&m);
  }
  if (unlabelled.size() > free.size()) {
    return Fail(error, "labels", std::to_string(unlabelled.size()) + " modes to label, and the "
                                 "model has " + std::to_string(free.size()) + " left to pair them with");
  }
  std::vector<internal::ModeToPair> measured;
  for (int i : unlabelled) {
    const MeasuredMode& m = (*modes)[i];
    measured.push_back({m.frequency_hz, &m.shape, std::nullopt});
  }
  std::vector<int> pick;
  std::vector<internal::PairedBy> by;
  std::string why;
  if (!internal::PairModes(measured, free, convention, &pick, &by, &why)) {
    return Fail(error, "labels", why);
  }
  std::vector<std::string>* notes = &out->notes;
  for (size_t r = 0; r < unlabelled.size(); ++r) {
    MeasuredMode& m = (*modes)[unlabelled[r]];
    const Mode& model = *free[pick[r]];
    const bool shaped = by[r] == internal::PairedBy::kShape;
    const auto score = [&](const Mode& mode) {
      return shaped ? internal::ShapeScore(mode, measured[r], convention)
                    : internal::FrequencyScore(mode, measured[r]);
    };
    m.label = model.label;
    const double mine = score(model);
    for (const Mode* other : free) {  // a runner-up as good: say so
      if (other != &model && score(*other) > mine - 0.05) {
        notes->push_back(names[unlabelled[r]] + ": " + LabelName(other->label) +
                         " scores nearly as well; give its label in the map if you know it");
      }
    }
    char line[200];
    if (shaped) {
      std::snprintf(line, sizeof line, "%s, %.4g Hz, labelled %s by the model (%.4g Hz there, MAC %.3f)",
                    names[unlabelled[r]].c_str(), m.frequency_hz, LabelName(model.label),
                    model.frequency_hz, mine);
    } else {
      std::snprintf(line, sizeof line, "%s, %.4g Hz, labelled %s by the model (%.4g Hz there; no "
                    "shape measured: the nearest in frequency)", names[unlabelled[r]].c_str(),
                    m.frequency_hz, LabelName(model.label), model.frequency_hz);
    }
    notes->push_back(line);
    out->by_model.push_back({unlabelled[r], shaped ? std::optional<double>(mine) : std::nullopt});
  }
  return true;
}

}  // namespace

bool ParseUffMap(const std::string& text, const std::string& path, UffMap* map,
                 LoadError* error) {
  *map = UffMap{};
  error->file = path;
  error->field.clear();
  nlohmann::ordered_json j;
  if (!ParseJsonInput(text, &j, error)) return false;
  UffMapFields fields;
  std::string why;
  if (!JsonReader::FromJson(j, "", &fields, &why)) {
    SetArchiveError(why, error);
    return false;
  }
  return CheckMap(fields, map, error);
}

bool LoadUffMap(const std::string& path, UffMap* map, LoadError* error) {
  std::string text;
  return ReadInputFile(path, &text, error) && ParseUffMap(text, path, map, error);
}

bool UffToDataset(const UffFile& file, const UffMap& map, const Parameters* p, UffImport* out,
                  LoadError* error, ShapeConvention convention) {
  *out = UffImport{};
  error->file = file.path;
  error->field.clear();
  Dataset& d = out->dataset;
  d.path = file.path;
  d.name = map.name;
  d.description = map.description.empty() ? "imported by ringid from the UFF file " + file.path
                                           : map.description;
  const UffUnits* units = file.units.empty() ? nullptr : &file.units.front();
  char factor[32];
  std::snprintf(factor, sizeof factor, "%g", units ? units->length_factor : 1.0);
  out->notes.push_back(units ? "units: dataset 164 '" + units->description +
                                   "', lengths divided by " + factor + " to metres"
                             : "units: no dataset 164; the values are taken as SI");
  std::vector<int> unlabelled;
  std::set<int> numbers;
  std::set<ModeLabel> taken;
  std::vector<std::string> names;  // each mode's record, for the notes
  for (const UffModalData& m : file.modal_data) {
    if (!m.IsNormalMode() && !m.IsComplexMode()) {
      out->notes.push_back(Where(m) + ": analysis type " + std::to_string(m.analysis_type) +
                           " is not a mode; skipped");
      continue;
    }
    if (!numbers.insert(m.mode_number).second) {
      return Fail(error, Where(m), "mode number given twice (the map's labels name modes by it)");
    }
    MeasuredMode mode;
    mode.frequency_hz = m.FrequencyHz().value_or(0);
    const std::string problem = ModeFrequencyProblem(mode.frequency_hz);
    if (!problem.empty()) return Fail(error, Where(m) + " frequency", problem);
    const std::optional<double> zeta = m.DampingRatio();
    const std::string damping = zeta ? DampingRatioProblem(*zeta) : "";
    if (zeta && damping.empty()) {
      mode.damping_ratio = zeta;
    } else if (zeta && *zeta != 0) {
      char value[32];
      std::snprintf(value, sizeof value, "%g", *zeta);
      out->notes.push_back(Where(m) + ": damping ratio " + value + " left out: it " + damping);
    }
    if (!Shape(m, map, units, &mode.shape, error)) return false;
    const auto label = map.labels.find(m.mode_number);
    if (label != map.labels.end()) {
      mode.label = label->second;
      taken.insert(label->second);
      out->notes.push_back(Where(m) + " labelled " + LabelName(label->second) + " by the map");
    } else {
      unlabelled.push_back(static_cast<int>(d.modes.size()));
    }
    d.modes.push_back(mode);
    names.push_back(Where(m));
  }
  for (const auto& [number, label] : map.labels) {
    if (!numbers.count(number)) {
      return Fail(error, "labels", "mode " + std::to_string(number) + " is not in the file");
    }
  }
  if (d.modes.empty()) return Fail(error, "dataset 55", "the file holds no mode");
  if (!unlabelled.empty()) {
    if (!p) {
      return Fail(error, "labels", std::to_string(unlabelled.size()) + " modes have no label: give "
                                   "them in the map, or --parameters to label them by the model");
    }
    if (!LabelByModel(*p, convention, taken, unlabelled, names, &d.modes, out, error)) return false;
  }
  if (!p && !map.known.empty()) {
    out->notes.push_back("known: no --parameters, so no value is written known or initial");
  }
  if (p) WriteUffParameters(*p, map, &d);
  return true;
}

void WriteUffParameters(const Parameters& p, const UffMap& map, Dataset* d) {
  for (Param q : RigidRingModel().parameters()) {
    if (!p.IsSet(q)) continue;
    const bool known = std::find(map.known.begin(), map.known.end(), q) != map.known.end();
    (known ? d->known : d->initial)[q] = p[q];
  }
}

}  // namespace ringid
