// A UFF file's FRFs as they are (datasets/uff_raw_frf.h).
#include "datasets/uff_raw_frf.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <tuple>

#include "datasets/load_failure.h"
#include "datasets/uff_frf.h"

namespace ringid {
namespace {

using internal::Fail;

std::string Where(const UffFile& file, size_t k) { return UffFunctionName(file, k); }

const char* FunctionTypeName(int type) {
  switch (type) {
    case 1: return "time response";
    case 2: return "auto spectrum";
    case 3: return "cross spectrum";
    case 5: return "transmissibility";
    case 6: return "coherence";
    default: return "not an FRF";
  }
}

template <class End>
int IndexOf(std::vector<End>* ends, std::vector<UffEnd>* keys, const UffEnd& key) {
  for (size_t i = 0; i < keys->size(); ++i) {
    if ((*keys)[i].node == key.node && (*keys)[i].direction == key.direction) return static_cast<int>(i);
  }
  keys->push_back(key);
  ends->emplace_back();
  ends->back().name = UffNodeName(key.node, key.direction);
  return static_cast<int>(keys->size()) - 1;
}

constexpr char kMixed[] = "mixed: SI where the units say, else the file's";

using PairKey = std::tuple<int, int, int, int>;
PairKey Pair(const UffFunction& f) {
  return {f.response_node, f.response_direction, f.reference_node, f.reference_direction};
}

void Read(const UffFile& file, const UffMap* map, int min_lines, UffRawFrfs* out) {
  std::multimap<PairKey, size_t> coherences;  // a pair's coherences, on any lines
  size_t frfs = 0, dc = 0;
  std::map<int, size_t> others;  // function type -> how many
  for (size_t k = 0; k < file.functions.size(); ++k) {
    const UffFunction& f = file.functions[k];
    if (f.function_type == 4) ++frfs;
    else if (f.function_type == 6) coherences.emplace(Pair(f), k);
    else ++others[f.function_type];
  }
  if (frfs == 0) {
    if (file.functions.empty()) Fail("", "holds no dataset 58: poles need FRFs (function type 4)");
    const UffFunction& f = file.functions.front();
    Fail(Where(file, 0) + " record 6", "function type " + std::to_string(f.function_type) + " (" +
                                           FunctionTypeName(f.function_type) + "): poles need FRFs "
                                           "(function type 4), and the file holds none");
  }
  for (const auto& [type, n] : others) {
    out->notes.push_back(std::to_string(n) + " function(s) of type " + std::to_string(type) + " (" +
                         FunctionTypeName(type) + ") left out: not FRFs");
  }
  const UffMap none;
  const UffMap& units_map = map ? *map : none;
  size_t in_file_units = 0, with_coherence = 0;
  for (size_t k = 0; k < file.functions.size(); ++k) {
    const UffFunction& f = file.functions[k];
    if (f.function_type != 4) continue;
    const std::string where = Where(file, k);
    if (!f.IsComplex()) Fail(where + " record 7", "field 1 (ordinate data type): an FRF is complex (5 or 6)");
    size_t first = 0;
    while (first < f.x.size() && !(f.x[first] > 0)) ++first;
    dc += first > 0;
    std::vector<double> lines(f.x.begin() + static_cast<long>(first), f.x.end());
    for (size_t i = 1; i < lines.size(); ++i) {
      if (!(lines[i] > lines[i - 1])) {
        Fail(where + " record 12", "abscissa value " + std::to_string(first + i + 1) +
                                       " does not exceed the one before: an FRF's lines increase");
      }
    }
    if (static_cast<int>(lines.size()) < min_lines) {
      Fail(where + " record 7", std::to_string(lines.size()) + " line(s) above 0 Hz: poles need at least " +
                                    std::to_string(min_lines));
    }
    double si = 1;
    FrfQuantity quantity = FrfQuantity::kAcceleration;
    std::string said;
    LoadError why;
    const bool known = UffFrfUnits(file, k, units_map, &si, &quantity, &said, &why);
    if (!known) {
      si = 1;
      ++in_file_units;
      quantity = UffResponseQuantity(f.ordinate.specific_data_type).value_or(FrfQuantity::kAcceleration);
    }
    if (std::all_of(f.y.begin() + static_cast<long>(first), f.y.end(), [](const auto& y) { return y == 0.0; })) {
      out->notes.push_back(where + " " + UffNodeName(f.response_node, f.response_direction) + " / " +
                           UffNodeName(f.reference_node, f.reference_direction) +
                           ": zero at every line above 0 Hz; left out");
      --frfs;
      continue;
    }
    auto c = std::find_if(out->conditions.begin(), out->conditions.end(),
                          [&](const UffRawCondition& r) { return r.frf.frequencies_hz == lines; });
    if (c == out->conditions.end()) {
      c = out->conditions.insert(out->conditions.end(), UffRawCondition{});
      c->frf.frequencies_hz = lines;
      c->units = known ? "SI (" + said + ")" : "the file's units";
    } else if (c->units != (known ? "SI (" + said + ")" : "the file's units") && c->units != kMixed) {
      c->units = known && c->units != "the file's units" ? "SI" : kMixed;
    }
    FrfFunction fn;
    fn.output = IndexOf(&c->frf.outputs, &c->outputs, {f.response_node, f.response_direction});
    fn.input = IndexOf(&c->frf.inputs, &c->inputs, {f.reference_node, f.reference_direction});
    c->frf.outputs[fn.output].quantity = quantity;
    for (const FrfFunction& g : c->frf.functions) {
      if (g.output == fn.output && g.input == fn.input) {
        Fail(where, "pairs response " + c->frf.outputs[fn.output].name + " with reference " +
                        c->frf.inputs[fn.input].name + " on the lines of an FRF before it: a pair is given once");
      }
    }
    for (size_t i = first; i < f.y.size(); ++i) fn.h.push_back(si * f.y[i]);
    const UffFunction* g = nullptr;  // its pair's coherence on its lines
    for (auto [at, end] = coherences.equal_range(Pair(f)); at != end; ++at) {
      if (file.functions[at->second].x == f.x) g = &file.functions[at->second];
    }
    if (map && map->averages && g) {
      double peak = 0;
      for (const auto& h : fn.h) peak = std::max(peak, std::abs(h));
      for (size_t i = 0; i < fn.h.size(); ++i) {
        const double gamma2 = std::min(std::max(g->y[first + i].real(), kUffMinCoherence), kUffMaxCoherence);
        fn.sigma.push_back(std::max(CoherenceSigma(fn.h[i], gamma2, *map->averages),
                                    FrfSigma(kDefaultFrfRelativeSigma, 0.0, peak)));
      }
      ++with_coherence;
    }
    c->frf.functions.push_back(std::move(fn));
  }
  if (out->conditions.empty()) Fail("", "every FRF is zero: no poles");
  if (dc) out->notes.push_back("lines at or below 0 Hz dropped from " + std::to_string(dc) + " FRF(s)");
  if (in_file_units) {
    out->notes.push_back(std::to_string(in_file_units) + " FRF(s) in the file's units: their units "
                         "records do not say (give a map's units, docs/uff.md); the poles do not depend on them");
  }
  if (!coherences.empty() && !(map && map->averages)) {
    out->notes.push_back("coherence functions left out: the number of averages behind them is not "
                         "in the file (give a map's averages)");
  }
  if (with_coherence < frfs) {
    out->notes.push_back(std::to_string(frfs - with_coherence) + " FRF(s) without coherence: the "
                         "noise of every FRF on their lines is estimated from the residuals of the fit");
  }
}

}  // namespace

bool ReadUffRawFrfs(const UffFile& file, const UffMap* map, int min_lines, UffRawFrfs* out,
                    LoadError* error) {
  *out = UffRawFrfs{};
  error->file = file.path;
  error->field.clear();
  return internal::Captured(error, [&] { Read(file, map, min_lines, out); });
}

}  // namespace ringid
