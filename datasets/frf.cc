// The frf block's rules (contract §9) and its writing back.
#include "datasets/frf.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <utility>

#include "datasets/dataset.h"
#include "datasets/load_failure.h"
#include "model/spelling.h"

namespace ringid {
namespace {

using internal::Fail;  // caught in ReadFrf
using internal::Captured;
using internal::Failure;

std::string Text(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

std::string At(const std::string& field, size_t i) {
  return field + "[" + std::to_string(i) + "]";
}

// The archive reads null as a number that is not finite.
double Finite(double v, const std::string& field) {
  if (!std::isfinite(v)) Fail(field, "must be a number");
  return v;
}

std::array<double, 3> Vector3(const std::vector<double>& v, const std::string& field) {
  if (v.size() != 3) {
    Fail(field, "must be three numbers [x, y, z] (found " + std::to_string(v.size()) + ")");
  }
  return {Finite(v[0], At(field, 0)), Finite(v[1], At(field, 1)), Finite(v[2], At(field, 2))};
}

// A point's three fields, all or none ("a point input").
std::optional<FrfPoint> Point(const FrfPointFields& j, const std::string& field,
                              const std::string& what) {
  if (!j.on && !j.point_m && !j.direction) return std::nullopt;
  const std::pair<const char*, bool> given[] = {
      {"on", j.on.has_value()}, {"point_m", j.point_m.has_value()},
      {"direction", j.direction.has_value()}};
  for (const auto& [key, has] : given) {
    if (!has) {
      Fail(field + "." + key, "missing: a point " + what + " needs on, point_m and direction");
    }
  }
  FrfPoint p;
  p.on = *j.on;
  p.point_m = Vector3(*j.point_m, field + ".point_m");
  p.direction = Vector3(*j.direction, field + ".direction");
  if (p.direction[0] == 0 && p.direction[1] == 0 && p.direction[2] == 0) {
    Fail(field + ".direction", "must not be zero");
  }
  for (const auto& [dof, v] : PointCombination(p)) {
    if (!std::isfinite(v)) Fail(field + ".point_m", "is too far out: its coefficients overflow");
  }
  return p;
}

DofCombination Coordinates(const std::map<std::string, double>& given, const std::string& field) {
  if (given.empty()) Fail(field, "must be a non-empty object of degree-of-freedom names");
  DofCombination out;
  bool any = false;
  for (const auto& [name, v] : given) {
    const std::string f = field + "." + name;
    const auto dof = ParseDof(name);
    if (!dof) Fail(f, UnknownName("degree of freedom", name, NamesOf<Dof>()));
    out[*dof] = Finite(v, f);
    any = any || v != 0;
  }
  if (!any) Fail(field, "all coefficients are zero");
  return out;
}

// The keys given of an input's or output's kinds; more than one is an error
// naming the second.
void OneKind(const std::vector<const char*>& given, const std::string& field,
             const std::string& kinds) {
  if (given.empty()) Fail(field, "gives none of " + kinds);
  if (given.size() > 1) {
    Fail(field + "." + given[1], std::string("not with ") + given[0] + ": it is one of " + kinds);
  }
}

// Why a condition at speed refuses a point (contract §9): "at speed_m_s 8 ...".
std::string TurningPoint(double speed_m_s, const std::string& on_them, const std::string& takes) {
  return "at speed_m_s " + Text(speed_m_s) + " the tread and the rim turn, so " + on_them +
         " them is not a fixed linear channel: a condition at speed takes " + takes + " only";
}

FrfInput Input(const FrfInputFields& j, double speed_m_s, const std::string& field) {
  FrfInput in;
  in.name = j.name;
  in.point = Point(j.point, field, "input");
  std::vector<const char*> kinds;
  if (in.point) kinds.push_back("on");
  if (j.contact) kinds.push_back("contact");
  if (j.coordinates) kinds.push_back("coordinates");
  OneKind(kinds, field, "a point force (on, point_m, direction), contact or coordinates");
  in.contact = j.contact;
  if (in.point) in.coordinates = PointCombination(*in.point);
  if (j.coordinates) in.coordinates = Coordinates(*j.coordinates, field + ".coordinates");
  if (speed_m_s > 0 && in.point) {
    Fail(field + ".on", "input '" + in.name + "' is a point force: " +
                            TurningPoint(speed_m_s, "a force on", "contact inputs"));
  }
  if (speed_m_s > 0 && !in.contact) {
    Fail(field + ".coordinates", "input '" + in.name + "' is given as coordinates: a condition "
                                 "at speed takes contact inputs only (contract §9)");
  }
  return in;
}

FrfOutput Output(const FrfOutputFields& j, double speed_m_s, const std::string& field) {
  FrfOutput out;
  out.name = j.name;
  out.point = Point(j.point, field, "output");
  std::vector<const char*> kinds;
  if (out.point) kinds.push_back("on");
  if (j.coordinates) kinds.push_back("coordinates");
  if (j.channel) kinds.push_back("channel");
  OneKind(kinds, field, "a point motion (on, point_m, direction), coordinates or channel");
  out.channel = j.channel;
  if (out.point) out.coordinates = PointCombination(*out.point);
  if (j.coordinates) out.coordinates = Coordinates(*j.coordinates, field + ".coordinates");
  if (out.channel && j.quantity) {
    Fail(field + ".quantity", "not with channel: an axle channel is a force (N or N m per N)");
  }
  if (!out.channel) {
    if (!j.quantity) {
      Fail(field + ".quantity", "missing: a point or coordinates output says what it measures (" +
                                    EnumChoices<FrfQuantity>() + ")");
    }
    out.quantity = *j.quantity;
  }
  if (speed_m_s > 0 && out.point) {
    Fail(field + ".on", "output '" + out.name + "' is a point motion: " +
                            TurningPoint(speed_m_s, "a sensor on",
                                         "channel or coordinates outputs"));
  }
  return out;
}

// Names each at most once, for a function to refer to.
template <class T>
std::vector<std::string> UniqueNames(const std::vector<T>& items, const std::string& field,
                                     const std::string& what) {
  std::vector<std::string> names;
  for (size_t i = 0; i < items.size(); ++i) {
    const std::string& name = items[i].name;
    if (name.empty()) Fail(At(field, i) + ".name", "must not be empty");
    for (size_t k = 0; k < i; ++k) {
      if (names[k] == name) {
        Fail(At(field, i) + ".name", what + " '" + name + "' appears twice (" + At(field, k) + ")");
      }
    }
    names.push_back(name);
  }
  return names;
}

void Lines(const std::vector<double>& lines, const std::string& field) {
  if (lines.empty()) Fail(field, "must be a non-empty array");
  for (size_t i = 0; i < lines.size(); ++i) {
    if (!(Finite(lines[i], At(field, i)) > 0)) Fail(At(field, i), "must be positive");
    if (i > 0 && !(lines[i] > lines[i - 1])) {
      Fail(At(field, i), "must exceed the line before (" + Text(lines[i - 1]) +
                             " Hz): the lines are strictly increasing");
    }
  }
}

// One value per frequency line, each finite.
const std::vector<double>& PerLine(const std::vector<double>& v, size_t lines,
                                   const std::string& field) {
  if (v.size() != lines) {
    Fail(field, "has " + std::to_string(v.size()) + " values for " + std::to_string(lines) +
                    " frequency lines (one per line)");
  }
  for (size_t i = 0; i < v.size(); ++i) Finite(v[i], At(field, i));
  return v;
}

int IndexOf(const std::string& name, const std::vector<std::string>& names,
            const std::string& field, const std::string& what) {
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return static_cast<int>(i);
  }
  Fail(field, UnknownName(what, name, names));
}

// The noise of `fn`: sigma, or coherence with averages.
void Noise(const FrfFunctionFields& j, const std::string& f, FrfFunction* fn) {
  const size_t lines = fn->h.size();
  if (j.sigma && j.coherence) {
    Fail(f + ".coherence", "not with sigma: a function gives sigma, or coherence and averages");
  }
  if (j.sigma && j.averages) Fail(f + ".averages", "not with sigma: averages go with coherence");
  if (j.sigma) {
    fn->sigma = PerLine(*j.sigma, lines, f + ".sigma");
    for (size_t i = 0; i < lines; ++i) {
      if (!(fn->sigma[i] > 0)) Fail(At(f + ".sigma", i), "must be positive");
    }
    return;
  }
  if (!j.coherence) {
    Fail(f + ".sigma", "missing: a function gives sigma, or coherence and averages");
  }
  if (!j.averages) Fail(f + ".averages", "missing: coherence needs the number of averages");
  FrfCoherence c{PerLine(*j.coherence, lines, f + ".coherence"), *j.averages};
  if (c.averages < 1) Fail(f + ".averages", "must be at least 1");
  for (size_t i = 0; i < lines; ++i) {
    const std::string at = At(f + ".coherence", i);
    if (!(c.gamma2[i] > 0 && c.gamma2[i] < 1)) Fail(at, "must lie in (0, 1)");
    const double sigma = CoherenceSigma(fn->h[i], c.gamma2[i], c.averages);
    if (!(sigma > 0 && std::isfinite(sigma))) {
      Fail(at, "gives sigma " + Text(sigma) + " (|H| sqrt((1 - coherence) / (2 averages "
               "coherence))): give sigma for this function");
    }
    fn->sigma.push_back(sigma);
  }
  fn->coherence = std::move(c);
}

void Functions(const FrfFields& j, const std::vector<std::string>& outputs,
               const std::vector<std::string>& inputs, const std::string& field, Frf* frf) {
  if (j.functions.empty()) Fail(field, "must be a non-empty array");
  std::map<std::pair<int, int>, size_t> seen;
  const size_t lines = j.frequencies_hz.size();
  for (size_t k = 0; k < j.functions.size(); ++k) {
    const FrfFunctionFields& jf = j.functions[k];
    const std::string f = At(field, k);
    FrfFunction fn;
    fn.output = IndexOf(jf.output, outputs, f + ".output", "output");
    fn.input = IndexOf(jf.input, inputs, f + ".input", "input");
    const auto [before, fresh] = seen.emplace(std::make_pair(fn.output, fn.input), k);
    if (!fresh) {
      Fail(f, "pairs output '" + jf.output + "' with input '" + jf.input + "' as " +
                  At(field, before->second) + " does: a pair is given at most once");
    }
    const std::vector<double>& re = PerLine(jf.re, lines, f + ".re");
    const std::vector<double>& im = PerLine(jf.im, lines, f + ".im");
    for (size_t i = 0; i < lines; ++i) fn.h.emplace_back(re[i], im[i]);
    Noise(jf, f, &fn);
    frf->functions.push_back(std::move(fn));
  }
}

void Check(const FrfFields& j, double speed_m_s, const std::string& field, Frf* frf) {
  const std::string inputs = field + ".inputs", outputs = field + ".outputs";
  if (j.inputs.empty()) Fail(inputs, "must be a non-empty array");
  if (j.outputs.empty()) Fail(outputs, "must be a non-empty array");
  const std::vector<std::string> input_names = UniqueNames(j.inputs, inputs, "input");
  const std::vector<std::string> output_names = UniqueNames(j.outputs, outputs, "output");
  for (size_t i = 0; i < j.inputs.size(); ++i) {
    frf->inputs.push_back(Input(j.inputs[i], speed_m_s, At(inputs, i)));
  }
  for (size_t i = 0; i < j.outputs.size(); ++i) {
    frf->outputs.push_back(Output(j.outputs[i], speed_m_s, At(outputs, i)));
  }
  Lines(j.frequencies_hz, field + ".frequencies_hz");
  frf->frequencies_hz = j.frequencies_hz;
  Functions(j, output_names, input_names, field + ".functions", frf);
}

FrfPointFields PointFields(const FrfPoint& p) {
  FrfPointFields o;
  o.on = p.on;
  o.point_m.emplace(p.point_m.begin(), p.point_m.end());
  o.direction.emplace(p.direction.begin(), p.direction.end());
  return o;
}

std::map<std::string, double> CoordinateFields(const DofCombination& c) {
  std::map<std::string, double> o;
  for (const auto& [dof, v] : c) o[DofName(dof)] = v;
  return o;
}

}  // namespace

double CoherenceSigma(std::complex<double> h, double gamma2, int averages) {
  return std::abs(h) * std::sqrt((1 - gamma2) / (2.0 * averages * gamma2));
}

DofCombination PointCombination(const FrfPoint& point) {
  // Scaled by its largest component first, so that no square under- or overflows.
  double d[3], largest = 0;
  for (const double v : point.direction) largest = std::max(largest, std::abs(v));
  for (int i = 0; i < 3; ++i) d[i] = point.direction[i] / largest;
  const double norm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  for (double& v : d) v /= norm;
  const auto& p = point.point_m;
  const double theta = d[2] * p[0] - d[0] * p[2];
  std::vector<std::pair<Dof, double>> terms;
  if (point.on == FrfBody::kBelt) {
    terms = {{Dof::kXb, d[0]}, {Dof::kYb, d[1]}, {Dof::kZb, d[2]},
             {Dof::kGammaB, d[2] * p[1] - d[1] * p[2]}, {Dof::kThetaB, theta},
             {Dof::kPsiB, d[1] * p[0] - d[0] * p[1]}};
  } else {
    terms = {{Dof::kXa, d[0]}, {Dof::kYa, d[1]}, {Dof::kZa, d[2]}, {Dof::kThetaA, theta}};
  }
  DofCombination out;
  for (const auto& [dof, v] : terms) {
    if (v != 0) out[dof] = v;
  }
  return out;
}

bool ReadFrf(const FrfFields& fields, double speed_m_s, const std::string& path,
             const std::string& field, Frf* out, LoadError* error) {
  *out = Frf{};
  if (Captured(error, [&] { Check(fields, speed_m_s, field, out); })) return true;
  error->file = path;
  return false;
}

FrfFields FieldsOf(const Frf& frf) {
  FrfFields j;
  for (const FrfInput& in : frf.inputs) {
    FrfInputFields o;
    o.name = in.name;
    if (in.point) {
      o.point = PointFields(*in.point);
    } else if (in.contact) {
      o.contact = in.contact;
    } else {
      o.coordinates = CoordinateFields(in.coordinates);
    }
    j.inputs.push_back(std::move(o));
  }
  for (const FrfOutput& out : frf.outputs) {
    FrfOutputFields o;
    o.name = out.name;
    if (out.point) {
      o.point = PointFields(*out.point);
    } else if (!out.channel) {
      o.coordinates = CoordinateFields(out.coordinates);
    }
    if (out.channel) {
      o.channel = out.channel;
    } else {
      o.quantity = out.quantity;
    }
    j.outputs.push_back(std::move(o));
  }
  j.frequencies_hz = frf.frequencies_hz;
  for (const FrfFunction& fn : frf.functions) {
    FrfFunctionFields o;
    o.output = frf.outputs[fn.output].name;
    o.input = frf.inputs[fn.input].name;
    for (const std::complex<double>& h : fn.h) {
      o.re.push_back(h.real());
      o.im.push_back(h.imag());
    }
    if (fn.coherence) {
      o.coherence = fn.coherence->gamma2;
      o.averages = fn.coherence->averages;
    } else {
      o.sigma = fn.sigma;
    }
    j.functions.push_back(std::move(o));
  }
  return j;
}

}  // namespace ringid
