// Measured frequency response functions (contract §9): one item per
// condition with an `frf` block, its rows the real and imaginary parts of
// (model - measured) / sigma, function by function, line by line within the
// band, against the model's H(iω) (model/frequency_response.h).
#include <algorithm>
#include <cmath>
#include <string>

#include "datasets/measurement.h"
#include "datasets/measurement_frf.h"
#include "model/frequency_response.h"

namespace ringid {
namespace {

// The conditions that hold FRFs, in order: item i is the i-th.
int ConditionOfItem(const Dataset& d, int item) {
  for (int c = 0; c < static_cast<int>(d.conditions.size()); ++c) {
    if (d.conditions[c].frf && item-- == 0) return c;
  }
  return -1;
}

const Frf& FrfOf(const Dataset& d, int item) { return *d.conditions[ConditionOfItem(d, item)].frf; }

bool InBand(double hz, const MeasurementOptions& o) {
  return hz >= o.band_low_hz && hz <= o.band_high_hz;
}

// Whether the functions can be measured at `speed` (contract §9: at speed,
// contact inputs and channel or coordinate outputs only).
bool MeasurableAt(const Frf& frf, double speed) {
  if (!(speed > 0)) return true;
  for (const FrfInput& in : frf.inputs) {
    if (in.point) return false;
  }
  for (const FrfOutput& out : frf.outputs) {
    if (out.point) return false;
  }
  return true;
}

class FrfItems final : public MeasurementRecords {
 public:
  int Items(const Dataset& d) const override {
    int n = 0;
    for (const Condition& c : d.conditions) n += c.frf.has_value();
    return n;
  }
  int ConditionOf(const Dataset& d, int i) const override { return ConditionOfItem(d, i); }
  std::string ItemName(const Dataset&, int) const override { return "frequency response functions"; }
  void Repeat(const ModelAt&, int from, int to, double speed, Dataset* d) const override {
    const std::optional<Frf>& frf = d->conditions[from].frf;
    if (frf && MeasurableAt(*frf, speed)) d->conditions[to].frf = frf;
  }
};

const FrfItems& TheFrfItems() {
  static const FrfItems records;
  return records;
}

bool OnRim(const std::optional<FrfPoint>& p) { return p && p->on == FrfBody::kRim; }

// The request for the model: every input and output, the functions given,
// the lines within the band (or all of them).
ResponseRequest RequestOf(const Frf& frf, const MeasurementOptions* band) {
  ResponseRequest r;
  for (const FrfInput& in : frf.inputs) {
    r.inputs.push_back({in.contact, Coordinates(in.coordinates.begin(), in.coordinates.end()),
                        OnRim(in.point)});
  }
  for (const FrfOutput& out : frf.outputs) {
    r.outputs.push_back({out.channel, Coordinates(out.coordinates.begin(), out.coordinates.end()),
                         static_cast<int>(out.quantity),  // displacement 0, velocity 1, ...
                         OnRim(out.point)});
  }
  for (const FrfFunction& f : frf.functions) r.pairs.push_back({f.output, f.input});
  for (double hz : frf.frequencies_hz) {
    if (!band || InBand(hz, *band)) r.frequencies_hz.push_back(hz);
  }
  return r;
}

int LinesInBand(const Frf& frf, const MeasurementOptions& o) {
  int n = 0;
  for (double hz : frf.frequencies_hz) n += InBand(hz, o);
  return n;
}

// "response/hammer": a function by its output and input names.
std::string FunctionName(const Frf& frf, const FrfFunction& f) {
  return "FRF " + frf.outputs[f.output].name + "/" + frf.inputs[f.input].name;
}

class FrfKind final : public Measurement {
 public:
  Quantity quantity() const override { return Quantity::kFrf; }
  const char* description() const override { return "frequency response function"; }
  const char* unit() const override { return "per N"; }
  const MeasurementRecords& records() const override { return TheFrfItems(); }
  std::string Addition(const Dataset& d, int i) const override {
    std::string words = "the frequency response functions";
    if (d.conditions.size() > 1) words += " in condition " + d.conditions[ConditionOfItem(d, i)].name;
    return words;
  }
  int Rows(const Dataset& d, int i, const MeasurementOptions& o) const override {
    const Frf& frf = FrfOf(d, i);
    return 2 * static_cast<int>(frf.functions.size()) * LinesInBand(frf, o);
  }
  bool SeesScale() const override { return true; }  // force-calibrated: per newton
  std::string Count(int n) const override {
    return std::to_string(n) + " FRF values (re and im)";
  }
  std::optional<std::string> Unfit(const ModalModel& model, const Dataset& d,
                                   int i) const override {
    const Frf& frf = FrfOf(d, i);
    const std::string where = "condition " + d.conditions[ConditionOfItem(d, i)].name + ": frf ";
    for (const FrfInput& in : frf.inputs) {
      const Coordinates c(in.coordinates.begin(), in.coordinates.end());
      if (auto dof = MissingCoordinate(model, c, OnRim(in.point))) {
        return where + "input " + in.name + " acts on " + DofName(*dof) +
               ", which the model lacks (hub_compliance gives the hub x_a, z_a, y_a)";
      }
    }
    for (const FrfOutput& out : frf.outputs) {
      const Coordinates c(out.coordinates.begin(), out.coordinates.end());
      if (auto dof = MissingCoordinate(model, c, OnRim(out.point))) {
        return where + "output " + out.name + " reads " + DofName(*dof) +
               ", which the model lacks (hub_compliance gives the hub x_a, z_a, y_a)";
      }
    }
    return std::nullopt;
  }
  bool Evaluate(const Dataset& d, int i, const ModelAt& at, const MeasurementOptions& o,
                double* r, const std::vector<int>* params,
                Eigen::Ref<RowMatrix> dr) const override {
    const int c = ConditionOfItem(d, i);
    const Frf& frf = *d.conditions[c].frf;
    const ResponseRequest request = RequestOf(frf, &o);
    thread_local ResponseResult model;  // reused: its dH are megabytes
    FrequencyResponse(*at.model, *at.parameters, d.conditions[c].speed_m_s, request, params,
                      &model);
    if (!model.ok) return false;
    // The lines rise (contract §9): those in the band are a run from `first`.
    const int first = static_cast<int>(
        std::find_if(frf.frequencies_hz.begin(), frf.frequencies_hz.end(),
                     [&](double hz) { return InBand(hz, o); }) -
        frf.frequencies_hz.begin());
    const int lines = static_cast<int>(model.H.rows());
    for (int f = 0; f < static_cast<int>(frf.functions.size()); ++f) {
      const FrfFunction& fn = frf.functions[f];
      const Complex* H = model.H.col(f).data();
      const int row = 2 * lines * f;
      for (int l = 0; l < lines; ++l) {
        const Complex z = (H[l] - fn.h[first + l]) * (1 / fn.sigma[first + l]);
        r[row + 2 * l] = z.real();
        r[row + 2 * l + 1] = z.imag();
      }
      const int n = params ? static_cast<int>(params->size()) : 0;
      for (int l = 0; n > 0 && l < lines; ++l) {
        const Complex* dH = &model.dH(static_cast<Eigen::Index>(f) * lines + l, 0);
        const double inverse = 1 / fn.sigma[first + l];
        double* re = &dr(row + 2 * l, 0);
        double* im = &dr(row + 2 * l + 1, 0);
        for (int k = 0; k < n; ++k) {
          const Complex dz = dH[k] * inverse;
          re[k] = dz.real();
          im[k] = dz.imag();
        }
      }
    }
    return true;
  }
  // One entry per function: its chi-square over its values and their rms.
  void AddMisfit(const Dataset& d, int i, int component, double r, const MeasurementOptions& o,
                 MisfitTable* t) const override {
    const int c = ConditionOfItem(d, i);
    const Frf& frf = *d.conditions[c].frf;
    // Rows are function-major, 2 per line in the band.
    const FrfFunction& f = frf.functions[component / (2 * LinesInBand(frf, o))];
    const std::string name = FunctionName(frf, f);
    const std::optional<std::string> condition =
        d.NamesConditions() ? std::optional<std::string>(d.conditions[c].name) : std::nullopt;
    ItemMisfit* entry = nullptr;
    for (ItemMisfit& w : t->others) {
      if (w.name == name && w.condition == condition) entry = &w;
    }
    if (!entry) {
      t->others.push_back({condition, name, 0, 0.0, 0});  // NOLINT: chi2 and values set
      entry = &t->others.back();
    }
    entry->chi2 = entry->chi2.value_or(0) + r * r;
    entry->values = entry->values.value_or(0) + 1;
    entry->sigma = std::sqrt(*entry->chi2 / *entry->values);
  }
  bool Measure(const ModelAt& at, int i, const MeasurementOptions&, Dataset* d) const override {
    const int c = ConditionOfItem(*d, i);
    Frf& frf = *d->conditions[c].frf;
    const ResponseResult model =
        FrequencyResponse(*at.model, *at.parameters, d->conditions[c].speed_m_s,
                          RequestOf(frf, nullptr));
    if (!model.ok) return false;
    for (int f = 0; f < static_cast<int>(frf.functions.size()); ++f) {
      for (int l = 0; l < static_cast<int>(frf.frequencies_hz.size()); ++l) {
        frf.functions[f].h[l] = model.H(l, f);
      }
    }
    return true;
  }
  // A test that did no FRFs is not advised to (its inputs and outputs would
  // be the analyst's choice).
  void AddUnmeasured(const ModelAt&, int, const MeasurementOptions&, const AdviceSigmas&,
                     Dataset*) const override {}
  // Circular noise of sigma FrfSigma(noise) at each line (contract §9), its
  // floor from the largest |H| its sensor shows (a function across the planes
  // is zero, but not its sensor's noise); noise-free values carry the sigma
  // of the default level.
  void AddNoise(double noise, const std::function<double()>& draw, int i,
                Dataset* d) const override {
    Frf& frf = *d->conditions[ConditionOfItem(*d, i)].frf;
    std::vector<double> peak(frf.outputs.size(), 0.0);
    for (const FrfFunction& f : frf.functions) {
      for (const Complex& h : f.h) peak[f.output] = std::max(peak[f.output], std::abs(h));
    }
    for (FrfFunction& f : frf.functions) {
      f.coherence.reset();
      f.sigma.resize(f.h.size());
      for (size_t l = 0; l < f.h.size(); ++l) {
        f.sigma[l] = FrfSigma(noise > 0 ? noise : kDefaultFrfRelativeSigma, f.h[l], peak[f.output]);
        if (!(noise > 0)) continue;
        const double re = draw(), im = draw();
        f.h[l] += Complex(f.sigma[l] * re, f.sigma[l] * im);
      }
    }
  }
};

}  // namespace

bool CompareFrfs(const Dataset& d, int c, const ModelAt& at, const MeasurementOptions& o,
                 std::vector<FrfLines>* functions) {
  const Frf& frf = *d.conditions[c].frf;
  const ResponseResult model = FrequencyResponse(*at.model, *at.parameters,
                                                 d.conditions[c].speed_m_s, RequestOf(frf, &o));
  if (!model.ok) return false;
  functions->clear();
  for (int f = 0; f < static_cast<int>(frf.functions.size()); ++f) {
    const FrfFunction& fn = frf.functions[f];
    FrfLines lines;
    lines.function = f;
    int l = 0;  // the line within the band
    for (size_t line = 0; line < frf.frequencies_hz.size(); ++line) {
      if (!InBand(frf.frequencies_hz[line], o)) continue;
      lines.frequency_hz.push_back(frf.frequencies_hz[line]);
      lines.measured.push_back(fn.h[line]);
      lines.model.push_back(model.H(l++, f));
      lines.sigma.push_back(fn.sigma[line]);
    }
    functions->push_back(std::move(lines));
  }
  return true;
}

const Measurement& FrfMeasurement() {
  static const FrfKind unit;
  return unit;
}

const MeasurementRecords& FrfRecords() { return TheFrfItems(); }

}  // namespace ringid
