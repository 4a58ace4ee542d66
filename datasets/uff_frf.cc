// UFF 58 FRFs as format-3 frf blocks (datasets/uff_frf.h, docs/uff.md).
#include "datasets/uff_frf.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <tuple>
#include <utility>

#include "datasets/load_failure.h"
#include "datasets/uff_internal.h"
#include "model/spelling.h"

namespace ringid {
namespace {

using internal::Fail;  // caught in AddUffFrfs
using internal::Captured;
using internal::Failure;
using Vec3 = std::array<double, 3>;

constexpr double kStandardGravity = 9.80665;  // m/s² per g
constexpr double kPoundForce = 4.4482216152605;  // N per lbf
constexpr int kMaxExponent = 3;  // a motion per force has exponents 0 and ±1

std::string Text(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

std::string Where(const UffFile& file, size_t k) { return UffFunctionName(file, k); }
std::string NodeName(int node, int direction) { return UffNodeName(node, direction); }

std::string Trimmed(const std::string& s) { return std::string(uff_internal::Trim(s)); }
// The file's text as a message may quote it: 'printable ASCII', at most 40 characters.
using internal::Quoted;

const UffUnitName* FindUnit(const std::string& name) {
  for (const UffUnitName& u : UffUnitNames()) {
    if (name == u.name) return &u;
  }
  return nullptr;
}

// One axis (record 9 or 10) in SI: the factor to SI, its dimension
// (length, force exponents) and what said it.
struct AxisUnit {
  double si = 1;
  int length = 0, force = 0;
  std::optional<FrfQuantity> quantity;
  std::string said;
};

AxisUnit FromName(const UffUnitName& u, const std::string& said) {
  AxisUnit a;
  a.si = u.si;
  a.length = u.quantity ? 1 : 0;
  a.force = u.quantity ? 0 : 1;
  a.quantity = u.quantity;
  a.said = said;
  return a;
}

// The units of one axis: the map's, else the exponents with dataset 164's
// factors (a units label, if it names one, must agree), else the label.
AxisUnit Axis(const UffAxis& x, const UffUnits* units, const std::string& map_unit, bool force,
              const std::string& field) {
  const std::string key = force ? "reference" : "response";
  if (!map_unit.empty()) return FromName(*FindUnit(map_unit), "the map's units." + key + " '" + map_unit + "'");
  const std::string label = Trimmed(x.units_label);
  const bool named = !label.empty() && label != "NONE";
  const UffUnitName* unit = named ? FindUnit(label) : nullptr;
  const std::string ask = ", or give the map's units." + key + " (docs/uff.md)";
  if (named && !unit) {
    const std::string shown = Quoted(label);
    Fail(field, "units label " + shown + " names no unit ringid knows (" +
                    UffUnitProblem(shown.substr(1, shown.size() - 2), force) + ")" + ask);
  }
  if (x.temperature_exponent != 0) Fail(field, "field 4 (temperature units exponent) must be 0" + ask);
  if (std::abs(x.length_exponent) > kMaxExponent || std::abs(x.force_exponent) > kMaxExponent) {
    Fail(field, "fields 2 and 3 (length and force units exponents) must lie in -3..3" + ask);
  }
  if (x.length_exponent == 0 && x.force_exponent == 0) {
    if (unit) return FromName(*unit, "label " + Quoted(label));
    AxisUnit a;  // the other axis may carry the dimension
    a.said = "no exponents, no units label";
    return a;
  }
  AxisUnit a;
  a.length = x.length_exponent;
  a.force = x.force_exponent;
  const double lf = units ? units->length_factor : 1, ff = units ? units->force_factor : 1;
  a.si = 1 / (std::pow(lf, a.length) * std::pow(ff, a.force));
  a.said = "exponents (length " + std::to_string(a.length) + ", force " + std::to_string(a.force) +
           ") and " + (units ? "dataset 164 " + Quoted(Trimmed(units->description)) : "SI (no dataset 164)");
  if (unit) {
    const AxisUnit by_label = FromName(*unit, "");
    if (by_label.length != a.length || by_label.force != a.force ||
        std::abs(by_label.si - a.si) > 1e-9 * by_label.si) {
      char size[64];
      std::snprintf(size, sizeof size, "%.6g", a.si);
      Fail(field, "units label " + Quoted(label) + " disagrees with the exponents: those give length^" +
                      std::to_string(a.length) + " force^" + std::to_string(a.force) +
                      " of " + size + " SI units (dataset 164)" + ask);
    }
    a.quantity = unit->quantity;
  }
  return a;
}

const char* DataTypeQuantity(int specific_data_type, std::optional<FrfQuantity>* q) {
  switch (specific_data_type) {
    case 8: *q = FrfQuantity::kDisplacement; return "displacement";
    case 11: *q = FrfQuantity::kVelocity; return "velocity";
    case 12: *q = FrfQuantity::kAcceleration; return "acceleration";
    default: *q = std::nullopt; return nullptr;
  }
}

// An FRF's factor to SI and what its response measures.
struct FunctionUnits {
  double si = 1;
  FrfQuantity quantity = FrfQuantity::kAcceleration;
  std::string said;
};

FunctionUnits Units(const UffFunction& f, const UffUnits* units, const UffMap& map,
                    const std::string& where) {
  const std::string r9 = where + " record 9", r10 = where + " record 10";
  const AxisUnit num = Axis(f.ordinate, units, map.response_unit, false, r9);
  const AxisUnit den = Axis(f.denominator, units, map.reference_unit, true, r10);
  if (num.length - den.length != 1 || num.force - den.force != -1) {
    Fail(r9, "the FRF's units (" + num.said + " over " + den.said + ") are length^" +
                 std::to_string(num.length - den.length) + " force^" +
                 std::to_string(num.force - den.force) + ", not a motion per force: give the "
                 "map's units.response and units.reference (docs/uff.md)");
  }
  std::optional<FrfQuantity> by_type;
  const char* type = DataTypeQuantity(f.ordinate.specific_data_type, &by_type);
  if (by_type && num.quantity && *by_type != *num.quantity && map.response_unit.empty()) {
    Fail(r9, std::string("field 1 (specific data type) says ") + type + ", the units (" + num.said +
                 ") " + ToString(*num.quantity) + ": give the map's units.response (docs/uff.md)");
  }
  FunctionUnits u;
  if (num.quantity && (!map.response_unit.empty() || !by_type)) {
    u.quantity = *num.quantity;
  } else if (by_type) {
    u.quantity = *by_type;
  } else {
    Fail(r9, "field 1 (specific data type) is " + std::to_string(f.ordinate.specific_data_type) +
                 ", not displacement (8), velocity (11) or acceleration (12): give the map's "
                 "units.response (docs/uff.md)");
  }
  u.si = num.si / den.si;
  u.said = std::string(ToString(u.quantity)) + " per force; response by " + num.said +
           ", reference by " + den.said;
  return u;
}

// The lines of `f` above 0 Hz (contract §9), strictly increasing, and the
// index of the first.
std::vector<double> Lines(const UffFunction& f, const std::string& where, size_t* first) {
  if (f.abscissa.specific_data_type != 18 && f.abscissa.specific_data_type != 0) {
    Fail(where + " record 8", "field 1 (specific data type) is " +
                                  std::to_string(f.abscissa.specific_data_type) +
                                  ": an FRF's abscissa is frequency (18) in Hz");
  }
  const std::string label = Trimmed(f.abscissa.units_label);
  if (!label.empty() && label != "NONE" && label != "Hz" && label != "HZ" && label != "hz") {
    Fail(where + " record 8", "units label " + Quoted(label) + ": an FRF's abscissa is in Hz");
  }
  *first = 0;
  while (*first < f.x.size() && !(f.x[*first] > 0)) ++*first;
  std::vector<double> lines(f.x.begin() + static_cast<long>(*first), f.x.end());
  for (size_t i = 1; i < lines.size(); ++i) {
    if (!(lines[i] > lines[i - 1])) {
      Fail(where + " record 12", "abscissa value " + std::to_string(*first + i + 1) + " (" +
                                     Text(lines[i]) + " Hz) does not exceed the one before: an "
                                     "FRF's lines increase");
    }
  }
  return lines;
}

// A dataset-18 system in the global frame: global = origin + axes * local.
struct Frame {
  Vec3 origin{};
  std::array<Vec3, 3> axes{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};  // columns: the system's x, y, z
  Vec3 Apply(const Vec3& v) const {
    Vec3 g = origin;
    for (int k = 0; k < 3; ++k) {
      for (int i = 0; i < 3; ++i) g[i] += axes[k][i] * v[k];
    }
    return g;
  }
};

Vec3 Minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double Dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 Cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
bool Normalise(Vec3* v) {
  const double n = std::sqrt(Dot(*v, *v));
  if (!(n > 0) || !std::isfinite(n)) return false;
  for (double& x : *v) x /= n;
  return true;
}

// System `label` (0: the global frame), its points in metres; a system is
// defined in its reference system (at most 16 deep).
Frame SystemFrame(const UffFile& file, int label, const UffUnits* units, const std::string& field,
                  int depth = 0) {
  if (label == 0) return Frame{};
  if (depth > 16) Fail(field, "coordinate systems refer to each other in a loop (dataset 18)");
  for (const UffCoordinateSystems& d : file.coordinate_systems) {
    for (const UffCoordinateSystem& s : d.systems) {
      if (s.label != label) continue;
      const std::string at = "dataset 18 (line " + std::to_string(d.line) + ") system " +
                             std::to_string(label);
      if (s.type != 0) Fail(at, "is not cartesian (type " + std::to_string(s.type) + "): give the node's point_m, and directions in a cartesian system");
      const Frame ref = SystemFrame(file, s.reference, units, at, depth + 1);
      const auto metres = [&](const std::array<double, 3>& p) {
        Vec3 m;
        for (int k = 0; k < 3; ++k) m[k] = units ? units->LengthToSi(p[k]) : p[k];
        return ref.Apply(m);
      };
      Frame f;
      f.origin = metres(s.origin);
      Vec3 x = Minus(metres(s.x_point), f.origin), xz = Minus(metres(s.xz_point), f.origin);
      const double along = Dot(xz, x) / Dot(x, x);
      Vec3 z = {xz[0] - along * x[0], xz[1] - along * x[1], xz[2] - along * x[2]};
      if (!Normalise(&x) || !Normalise(&z)) {
        Fail(at, "has no axes: its point on +x, or its point in the xz plane, lies on the line "
                 "before it");
      }
      f.axes = {x, Cross(z, x), z};
      return f;
    }
  }
  Fail(field, "names coordinate system " + std::to_string(label) + ", which the file's dataset 18 does not hold");
}

const UffNode* FindNode(const UffFile& file, int label, int* line) {
  for (const UffNodes& d : file.nodes) {
    for (const UffNode& n : d.nodes) {
      if (n.label == label) {
        *line = d.line;
        return &n;
      }
    }
  }
  return nullptr;
}

Vec3 ToRingid(const UffMap& map, const Vec3& lab) {
  Vec3 r{};
  for (int i = 0; i < 3; ++i) r[i] = Dot(map.axes[i], lab);
  return r;
}

// A placed node's point and a direction of it in ringid's axes.
FrfPointFields PointOf(const UffFile& file, const UffMap& map, size_t p, int direction,
                       const UffUnits* units) {
  const UffMap::Point& point = map.points[p];
  int line = 0;
  const UffNode* node = FindNode(file, point.node, &line);
  const std::string at = node ? "dataset 15 (line " + std::to_string(line) + ") node " +
                                    std::to_string(point.node)
                              : "";
  Vec3 d{};
  d[std::abs(direction) - 1] = direction < 0 ? -1 : 1;
  if (node) {  // the node's displacement system turns its directions
    const Frame system = SystemFrame(file, node->displacement_system, units, at);
    d = Minus(system.Apply(d), system.origin);
  }
  FrfPointFields out;
  out.on = point.on;
  if (point.point_m) {
    out.point_m.emplace(point.point_m->begin(), point.point_m->end());
  } else if (node) {
    Vec3 xyz;
    for (int k = 0; k < 3; ++k) xyz[k] = units ? units->LengthToSi(node->xyz[k]) : node->xyz[k];
    const Vec3 p_m = ToRingid(map, SystemFrame(file, node->definition_system, units, at).Apply(xyz));
    out.point_m.emplace(p_m.begin(), p_m.end());
  } else {
    Fail("points[" + std::to_string(p) + "].point_m",
         "missing: node " + std::to_string(point.node) + " is not in the file's dataset 15: give its point_m");
  }
  const Vec3 dir = ToRingid(map, d);
  out.direction.emplace(dir.begin(), dir.end());
  return out;
}

// A function placed: which points, its lines.
struct Placed {
  size_t k = 0;  // into file.functions
  size_t response = 0, reference = 0;  // into map.points
  std::vector<double> lines;
  size_t first = 0;  // the first line kept
};

std::optional<size_t> PointIndex(const UffMap& map, int node) {
  for (size_t i = 0; i < map.points.size(); ++i) {
    if (map.points[i].node == node) return i;
  }
  return std::nullopt;
}

// Why the map cannot place `f`, or empty.
std::string CannotPlace(const UffFunction& f, const UffMap& map) {
  const std::pair<int, int> ends[] = {{f.response_node, f.response_direction},
                                      {f.reference_node, f.reference_direction}};
  for (const auto& [node, direction] : ends) {
    if (!PointIndex(map, node)) return "node " + std::to_string(node) + " is not in the map's points";
    if (std::abs(direction) < 1 || std::abs(direction) > 3) {
      return "direction " + NodeName(node, direction) + " is not a translation (1, 2, 3)";
    }
  }
  return "";
}

using PairKey = std::tuple<int, int, int, int>;
PairKey Pair(const UffFunction& f) {
  return {f.response_node, f.response_direction, f.reference_node, f.reference_direction};
}

// The condition's FRF block: inputs, outputs and functions of `placed`.
struct Built {
  FrfFields fields;
  std::map<std::string, int> units;  // what said each function's units -> how many
  int default_sigma = 0, clamped = 0;
};

void AddFunction(const UffFile& file, const UffMap& map, const Placed& p,
                 const std::map<PairKey, std::pair<size_t, std::vector<double>>>& coherences,
                 const UffUnits* units, Built* b) {
  const UffFunction& f = file.functions[p.k];
  const std::string where = Where(file, p.k);
  const FunctionUnits u = Units(f, units, map, where);
  ++b->units[u.said];
  FrfFields& j = b->fields;
  const std::string in = NodeName(f.reference_node, f.reference_direction);
  std::string out = NodeName(f.response_node, f.response_direction);
  if (std::none_of(j.inputs.begin(), j.inputs.end(), [&](const auto& x) { return x.name == in; })) {
    j.inputs.push_back({in, PointOf(file, map, p.reference, f.reference_direction, units), {}, {}});
  }
  const auto same = std::find_if(j.outputs.begin(), j.outputs.end(),
                                 [&](const auto& x) { return x.name == out; });
  if (same != j.outputs.end() && same->quantity != u.quantity) {
    out += std::string(" ") + ToString(u.quantity);
  }
  if (std::none_of(j.outputs.begin(), j.outputs.end(), [&](const auto& x) { return x.name == out; })) {
    j.outputs.push_back({out, PointOf(file, map, p.response, f.response_direction, units), {},
                         u.quantity, {}});
  }
  for (const FrfFunctionFields& other : j.functions) {
    if (other.output == out && other.input == in) {
      Fail(where, "pairs response " + out + " with reference " + in + " on the lines of an FRF "
                  "before it: a pair is given once");
    }
  }
  FrfFunctionFields fn;
  fn.output = out;
  fn.input = in;
  double peak = 0;
  std::vector<std::complex<double>> h;
  for (size_t i = p.first; i < f.y.size(); ++i) {
    h.push_back(u.si * f.y[i]);
    fn.re.push_back(h.back().real());
    fn.im.push_back(h.back().imag());
    peak = std::max(peak, std::abs(h.back()));
  }
  if (!(peak > 0) || !std::isfinite(peak)) Fail(where + " record 12", "the FRF is zero, or not finite in SI, at every line");
  const auto c = coherences.find(Pair(f));
  if (c == coherences.end() || c->second.second != p.lines) {
    ++b->default_sigma;
    fn.sigma.emplace();
    for (const auto& v : h) {
      fn.sigma->push_back(FrfSigma(kDefaultFrfRelativeSigma, v, peak));
    }
    j.functions.push_back(std::move(fn));
    return;
  }
  const UffFunction& g = file.functions[c->second.first];
  const size_t first = g.x.size() - p.lines.size();
  std::vector<double> gamma2;
  bool clamped = false;
  for (size_t i = 0; i < p.lines.size(); ++i) {
    const double v = g.y[first + i].real();
    gamma2.push_back(std::min(std::max(v, kUffMinCoherence), kUffMaxCoherence));
    clamped |= !(v > 0 && v < 1) || !(CoherenceSigma(h[i], v, *map.averages) > 0);
  }
  if (!clamped) {
    fn.coherence = gamma2;
    fn.averages = map.averages;
  } else {
    ++b->clamped;
    fn.sigma.emplace();
    for (size_t i = 0; i < h.size(); ++i) {
      const double floor = FrfSigma(kDefaultFrfRelativeSigma, 0.0, peak);
      fn.sigma->push_back(std::max(CoherenceSigma(h[i], gamma2[i], *map.averages), floor));
    }
  }
  j.functions.push_back(std::move(fn));
}

// The coherence functions (type 6) of placed pairs: pair -> (function, lines).
std::map<PairKey, std::pair<size_t, std::vector<double>>> Coherences(const UffFile& file,
                                                                     const UffMap& map) {
  std::map<PairKey, std::pair<size_t, std::vector<double>>> out;
  for (size_t k = 0; k < file.functions.size(); ++k) {
    const UffFunction& f = file.functions[k];
    if (f.function_type != 6 || !CannotPlace(f, map).empty()) continue;
    const std::string where = Where(file, k);
    for (const auto& y : f.y) {
      if (y.imag() != 0) Fail(where + " record 12", "a coherence is real; this one has an imaginary part");
    }
    if (!map.averages) {
      Fail("averages", "the file has coherence functions (" + where + "): give the map's averages, "
                       "the number of averages behind them, which the file does not carry");
    }
    size_t first = 0;
    std::vector<double> lines = Lines(f, where, &first);
    if (!out.emplace(Pair(f), std::make_pair(k, std::move(lines))).second) {
      Fail(where, "a second coherence of response " + NodeName(f.response_node, f.response_direction) +
                      " and reference " + NodeName(f.reference_node, f.reference_direction));
    }
  }
  return out;
}

std::string Count(size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

void Add(const UffFile& file, const UffMap& map, UffImport* out) {
  std::vector<std::string>& notes = out->notes;
  const UffUnits* units = file.units.empty() ? nullptr : &file.units.front();
  const auto coherences = Coherences(file, map);
  std::vector<std::vector<Placed>> groups;
  size_t dc = 0, used_coherences = 0;
  for (size_t k = 0; k < file.functions.size(); ++k) {
    const UffFunction& f = file.functions[k];
    const std::string where = Where(file, k);
    const std::string pair = NodeName(f.response_node, f.response_direction) + " / " +
                             NodeName(f.reference_node, f.reference_direction);
    if (f.function_type == 6) continue;
    if (f.function_type != 4) {
      notes.push_back(where + " " + pair + ": function type " + std::to_string(f.function_type) +
                      " is not an FRF (4); left out");
      continue;
    }
    const std::string why = CannotPlace(f, map);
    if (!why.empty()) {
      notes.push_back(where + " " + pair + ": " + why + "; left out");
      continue;
    }
    if (!f.IsComplex()) Fail(where + " record 7", "field 1 (ordinate data type): an FRF is complex (5 or 6)");
    Placed p{k, *PointIndex(map, f.response_node), *PointIndex(map, f.reference_node), {}, 0};
    p.lines = Lines(f, where, &p.first);
    if (p.lines.empty()) {
      notes.push_back(where + " " + pair + ": no line above 0 Hz; left out");
      continue;
    }
    dc += p.first > 0;
    const auto c = coherences.find(Pair(f));
    used_coherences += c != coherences.end() && c->second.second == p.lines;
    auto group = std::find_if(groups.begin(), groups.end(),
                              [&](const std::vector<Placed>& g) { return g[0].lines == p.lines; });
    if (group == groups.end()) group = groups.insert(groups.end(), std::vector<Placed>{});
    group->push_back(std::move(p));
  }
  if (groups.empty()) Fail("points", "the map places no FRF (function type 4) of the file");
  if (used_coherences < coherences.size()) {
    notes.push_back(Count(coherences.size() - used_coherences, "coherence function matches",
                          "coherence functions match") + " no FRF of its pair on its lines; left out");
  }
  if (map.averages && coherences.empty()) notes.push_back("averages: the file has no coherence; unused");
  if (dc) notes.push_back("lines at or below 0 Hz left out of " + Count(dc, "FRF", "FRFs") + " (contract §9: lines > 0)");
  Dataset& d = out->dataset;
  if (d.modes.empty() && d.statics.empty()) d.conditions.clear();
  d.format = 3;
  for (size_t g = 0; g < groups.size(); ++g) {
    Built b;
    b.fields.frequencies_hz = groups[g][0].lines;
    for (const Placed& p : groups[g]) AddFunction(file, map, p, coherences, units, &b);
    const size_t c = g == 0 && !d.conditions.empty() ? 0 : d.conditions.size();
    if (c == d.conditions.size()) {
      d.conditions.emplace_back();
      if (c > 0) d.conditions[c].name = "standing_" + std::to_string(c + 1);
    }
    Condition& condition = d.conditions[c];
    const std::string field = "conditions[" + std::to_string(c) + "].frf";
    condition.frf.emplace();
    LoadError e;
    if (!ReadFrf(b.fields, 0, file.path, field, &*condition.frf, &e)) Fail(e.field, e.message);
    const std::vector<double>& lines = b.fields.frequencies_hz;
    char head[200];
    std::snprintf(head, sizeof head, "condition %s: %s of %s and %s, %s %.6g-%.6g Hz",
                  condition.name.c_str(), Count(b.fields.functions.size(), "FRF", "FRFs").c_str(),
                  Count(b.fields.outputs.size(), "output", "outputs").c_str(),
                  Count(b.fields.inputs.size(), "input", "inputs").c_str(),
                  Count(lines.size(), "line", "lines").c_str(), lines.front(), lines.back());
    notes.push_back(head);
    for (const auto& [said, n] : b.units) notes.push_back("  units: " + Count(n, "FRF", "FRFs") + ": " + said);
    if (b.default_sigma) {
      char line[200];
      std::snprintf(line, sizeof line, "  sigma: %s without coherence: %g %% of |H| per line, at least "
                    "%g %% of the function's largest |H| (docs/uff.md)",
                    Count(b.default_sigma, "FRF", "FRFs").c_str(), 100 * kDefaultFrfRelativeSigma,
                    100 * kDefaultFrfRelativeSigma * kFrfSigmaFloor);
      notes.push_back(line);
    }
    const size_t coherent = b.fields.functions.size() - b.default_sigma;
    if (coherent) {
      notes.push_back("  sigma: " + Count(coherent, "FRF", "FRFs") + " from coherence with " +
                      std::to_string(*map.averages) + " averages (contract §9)" +
                      (b.clamped ? ", " + std::to_string(b.clamped) + " with coherence outside (0, 1) "
                                   "taken inside it" : std::string()));
    }
  }
}

}  // namespace

const std::vector<UffUnitName>& UffUnitNames() {
  static const std::vector<UffUnitName> kUnits = {
      {"m/s^2", FrfQuantity::kAcceleration, 1}, {"m/s2", FrfQuantity::kAcceleration, 1},
      {"mm/s^2", FrfQuantity::kAcceleration, 1e-3}, {"mm/s2", FrfQuantity::kAcceleration, 1e-3},
      {"g", FrfQuantity::kAcceleration, kStandardGravity},
      {"in/s^2", FrfQuantity::kAcceleration, 0.0254}, {"ft/s^2", FrfQuantity::kAcceleration, 0.3048},
      {"m/s", FrfQuantity::kVelocity, 1}, {"mm/s", FrfQuantity::kVelocity, 1e-3},
      {"in/s", FrfQuantity::kVelocity, 0.0254},
      {"m", FrfQuantity::kDisplacement, 1}, {"mm", FrfQuantity::kDisplacement, 1e-3},
      {"um", FrfQuantity::kDisplacement, 1e-6}, {"in", FrfQuantity::kDisplacement, 0.0254},
      {"N", std::nullopt, 1}, {"kN", std::nullopt, 1e3}, {"mN", std::nullopt, 1e-3},
      {"lbf", std::nullopt, kPoundForce}, {"kgf", std::nullopt, kStandardGravity}};
  return kUnits;
}

std::string UffUnitProblem(const std::string& name, bool force) {
  std::vector<std::string> names;
  for (const UffUnitName& u : UffUnitNames()) {
    if (u.quantity.has_value() != force) names.push_back(u.name);
  }
  if (std::find(names.begin(), names.end(), name) != names.end()) return "";
  return UnknownName(force ? "force unit" : "motion unit", name, names);
}

std::string UffFunctionName(const UffFile& file, size_t k) {
  const UffFunction& f = file.functions[k];
  return std::string("dataset 58") + (f.binary ? "b" : "") + " #" + std::to_string(k + 1) +
         " (line " + std::to_string(f.line) + ")";
}

std::string UffNodeName(int node, int direction) {
  return std::to_string(node) + ":" + (direction < 0 ? "-" : "+") + std::to_string(std::abs(direction));
}

std::optional<FrfQuantity> UffResponseQuantity(int specific_data_type) {
  std::optional<FrfQuantity> q;
  DataTypeQuantity(specific_data_type, &q);
  return q;
}

bool UffFrfUnits(const UffFile& file, size_t k, const UffMap& map, double* si,
                 FrfQuantity* quantity, std::string* said, LoadError* why) {
  why->file = file.path;
  const UffUnits* units = file.units.empty() ? nullptr : &file.units.front();
  return Captured(why, [&] {
    const FunctionUnits u = Units(file.functions[k], units, map, Where(file, k));
    *si = u.si;
    *quantity = u.quantity;
    *said = u.said;
  });
}

bool AddUffFrfs(const UffFile& file, const UffMap& map, UffImport* out, LoadError* error) {
  error->file = file.path;
  error->field.clear();
  Dataset& d = out->dataset;
  if (d.name.empty()) {
    d.path = file.path;
    d.name = map.name;
    d.description = map.description.empty() ? "imported by ringid from the UFF file " + file.path
                                             : map.description;
  }
  return Captured(error, [&] { Add(file, map, out); });
}

}  // namespace ringid
