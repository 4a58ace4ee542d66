#include "operations/option_text.h"


#include <strings.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "datasets/dataset.h"

namespace ringid {
namespace {

// The items of a comma-separated list, empty ones dropped.
std::vector<std::string> Items(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream list(text);
  for (std::string item; std::getline(list, item, ',');) {
    if (!item.empty()) items.push_back(item);
  }
  return items;
}

// A finite number that is the whole of `text`.
bool Number(const std::string& text, double* v) {
  char* end = nullptr;
  *v = std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size() && std::isfinite(*v);
}

template <class T>
std::string Joined(const std::vector<T>& items, std::string (*text)(T)) {
  std::string out;
  for (const T& item : items) out += (out.empty() ? "" : ",") + text(item);
  return out;
}

const OptionInfo* FindIn(const std::vector<OptionInfo>& options, const std::string& name) {
  for (const OptionInfo& o : options) {
    if (o.name == name) return &o;
  }
  return nullptr;
}

std::string EffectText(const Effect* e) { return e->name(); }
std::string ParamText(Param p) { return ParamName(p); }

}  // namespace

std::vector<std::string> OptionItems(const std::string& text) { return Items(text); }

// gflags' own rules (FlagValue::ParseFrom), so that a keyword argument is
// refused exactly where the flag would be.
bool OfKind(OptionKind kind, const std::string& text) {
  const char* value = text.c_str();
  char* end = nullptr;
  switch (kind) {
    case OptionKind::kBool:
      for (const char* word : {"1", "t", "true", "y", "yes", "0", "f", "false", "n", "no"}) {
        if (strcasecmp(value, word) == 0) return true;
      }
      return false;
    case OptionKind::kInteger: {
      if (text.empty()) return false;
      const int base = value[0] == '0' && (value[1] == 'x' || value[1] == 'X') ? 16 : 10;
      errno = 0;
      const long long r = std::strtoll(value, &end, base);
      return errno == 0 && end == value + text.size() && static_cast<int>(r) == r;
    }
    case OptionKind::kNumber:
      if (text.empty()) return false;
      errno = 0;
      std::strtod(value, &end);
      return errno == 0 && end == value + text.size();
    case OptionKind::kText:
      return true;
  }
  return false;
}

std::string BadValue(const std::string& name, const std::string& text, OptionKind kind) {
  const char* expected = kind == OptionKind::kBool     ? "true or false"
                         : kind == OptionKind::kNumber ? "a number"
                         : kind == OptionKind::kText   ? "text"
                                                       : "an integer";
  return "--" + name + ": bad value '" + text + "' (" + expected + " expected)";
}

bool OptionFromText(const std::string& name, const std::string& text, bool* value,
                    std::string* error) {
  if (!OfKind(OptionKind::kBool, text)) {
    *error = BadValue(name, text, OptionKind::kBool);
    return false;
  }
  for (const char* word : {"1", "t", "true", "y", "yes"}) {
    if (strcasecmp(text.c_str(), word) == 0) {
      *value = true;
      return true;
    }
  }
  *value = false;
  return true;
}

bool OptionFromText(const std::string& name, const std::string& text, int* value,
                    std::string* error) {
  if (!OfKind(OptionKind::kInteger, text)) {
    *error = BadValue(name, text, OptionKind::kInteger);
    return false;
  }
  const bool hex = text.size() > 1 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
  *value = static_cast<int>(std::strtoll(text.c_str(), nullptr, hex ? 16 : 10));
  return true;
}

bool OptionFromText(const std::string& name, const std::string& text, double* value,
                    std::string* error) {
  if (!OfKind(OptionKind::kNumber, text)) {
    *error = BadValue(name, text, OptionKind::kNumber);
    return false;
  }
  *value = std::strtod(text.c_str(), nullptr);
  return true;
}

bool OptionFromText(const std::string&, const std::string& text, std::string* value,
                    std::string*) {
  *value = text;
  return true;
}

bool OptionFromText(const std::string& name, const std::string& text, NumberList* value,
                    std::string* error) {
  const std::string flag = "--" + name;
  const std::string rule =
      std::string(value->positive ? "a number > 0" : "a number >= 0") + " in " + value->unit;
  if (text.empty()) {
    *error = flag + ": needs a comma-separated list, each item " + rule;
    return false;
  }
  std::vector<double> values;
  for (size_t start = 0;;) {
    const size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? comma : comma - start);
    char* end = nullptr;
    const double v = item.empty() ? NAN : std::strtod(item.c_str(), &end);
    if (item.empty() || !end || *end != '\0' || !std::isfinite(v) ||
        !(value->positive ? v > 0 : v >= 0)) {
      *error = flag + ": bad item '" + item + "' (each must be " + rule + ")";
      return false;
    }
    if (std::find(values.begin(), values.end(), v) != values.end()) {
      *error = flag + ": '" + item + "' is listed twice";
      return false;
    }
    values.push_back(v);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  value->values = values;
  return true;
}

bool OptionFromText(const std::string& name, const std::string& text, ParameterValues* value,
                    std::string* error) {
  const std::string flag = "--" + name;
  ParameterValues set;
  for (const std::string& item : Items(text)) {
    const size_t eq = item.find('=');
    if (eq == std::string::npos) {
      *error = flag + ": bad item '" + item + "' (NAME=VALUE)";
      return false;
    }
    const std::string param = item.substr(0, eq);
    const std::optional<Param> p = ParseParam(param);
    if (!p) {
      *error = flag + ": " + UnknownName("parameter", param, NamesOf<Param>());
      return false;
    }
    const std::string number = item.substr(eq + 1);
    double v = 0;
    if (!Number(number, &v)) {
      *error = flag + ": " + param + ": bad value '" + number + "' (a finite number)";
      return false;
    }
    const Domain d = Info(*p).domain;
    if ((d == Domain::kPositive && !(v > 0)) || (d == Domain::kNonNegative && v < 0)) {
      *error = flag + ": " + param + ": bad value '" + number + "' (" +
               (d == Domain::kPositive ? "a positive number" : "a number not negative") + ")";
      return false;
    }
    const std::string problem = ParameterValueProblem(*p, v);
    if (!problem.empty()) {
      *error = flag + ": " + param + ": bad value '" + number + "' (" + problem + ")";
      return false;
    }
    set[*p] = v;
  }
  *value = set;
  return true;
}

bool OptionFromText(const std::string& name, const std::string& text,
                    std::vector<const Effect*>* value, std::string* error) {
  std::vector<const Effect*> effects;
  for (const std::string& item : Items(text)) {
    const Effect* e = FindEffect(item);
    if (!e) {
      *error = "--" + name + ": " +
               UnknownName("effect", item, OptionChoices<std::vector<const Effect*>>());
      return false;
    }
    effects.push_back(e);
  }
  *value = effects;
  return true;
}

bool OptionFromText(const std::string& name, const std::string& text, std::vector<Param>* value,
                    std::string* error) {
  std::vector<Param> params;
  for (const std::string& item : Items(text)) {
    const std::optional<Param> p = ParseParam(item);
    if (!p) {
      *error = "--" + name + ": " + UnknownName("parameter", item, NamesOf<Param>());
      return false;
    }
    params.push_back(*p);
  }
  *value = params;
  return true;
}

bool OptionFromText(const std::string& name, const std::string& text, Bounds* value,
                    std::string* error) {
  Bounds bounds;
  for (const std::string& item : Items(text)) {
    std::vector<std::string> part;
    std::stringstream fields(item);
    for (std::string f; std::getline(fields, f, ':');) part.push_back(f);
    Bound b;
    if (part.size() != 3 || !Number(part[1], &b.lower) || !Number(part[2], &b.upper)) {
      *error = "--" + name + ": bad item '" + item + "' (NAME:LO:HI)";
      return false;
    }
    const std::optional<Param> p = ParseParam(part[0]);
    if (!p) {
      *error = "--" + name + ": " + UnknownName("parameter", part[0], NamesOf<Param>());
      return false;
    }
    bounds[*p] = b;
  }
  *value = bounds;
  return true;
}

const std::vector<OptionInfo>& EveryOption() {
  // Never destroyed: the command line's flags keep its names (apps/flags.cc).
  static const std::vector<OptionInfo>* every = new std::vector<OptionInfo>([] {
    std::vector<OptionInfo> all;
    for (const auto& list : {OptionsOf<FitSettings>(), OptionsOf<DiagnoseSettings>(),
                             OptionsOf<IdentifiabilitySettings>(),
                             OptionsOf<PredictSettings>(), OptionsOf<SimulateSettings>(),
                             OptionsOf<ForcesSettings>(), OptionsOf<ExtractSettings>(),
                             OptionsOf<PolesSettings>()}) {
      for (const OptionInfo& o : list) {
        if (!FindIn(all, o.name)) all.push_back(o);
      }
    }
    return all;
  }());
  return *every;
}

const OptionInfo* FindOption(const std::string& name) { return FindIn(EveryOption(), name); }

std::string OptionText(bool value) { return value ? "true" : "false"; }
std::string OptionText(int value) { return std::to_string(value); }
std::string OptionText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}
std::string OptionText(const std::string& value) { return value; }
std::string OptionText(const NumberList& value) {
  std::string out;
  for (double v : value.values) out += (out.empty() ? "" : ",") + OptionText(v);
  return out;
}
std::string OptionText(const ParameterValues& value) {
  std::string out;
  for (const auto& [p, v] : value) {
    out += (out.empty() ? "" : ",") + std::string(ParamName(p)) + "=" + OptionText(v);
  }
  return out;
}
std::string OptionText(const std::vector<const Effect*>& value) {
  return Joined(value, &EffectText);
}
std::string OptionText(const std::vector<Param>& value) { return Joined(value, &ParamText); }
std::string OptionText(const Bounds& value) {
  std::string out;
  for (const auto& [p, b] : value) {
    out += (out.empty() ? "" : ",") + std::string(ParamName(p)) + ":" + OptionText(b.lower) +
           ":" + OptionText(b.upper);
  }
  return out;
}

}  // namespace ringid
