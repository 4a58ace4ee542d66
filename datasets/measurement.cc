// The registry of measurements (datasets/measurement.h): the measured modes'
// quantities as one family, then the other kinds.
#include "datasets/measurement.h"

namespace ringid {

// Each defined in its own file.
const ModeQuantity& FrequencyMeasurement();
const ModeQuantity& DampingMeasurement();
const ModeQuantity& ShapeMeasurement();
const Measurement& StaticMeasurement();
const MeasurementRecords& StaticRecords();
const Measurement& FrfMeasurement();
const MeasurementRecords& FrfRecords();

const Mode* ModelAt::ModeOf(const Dataset& d, int i) const {
  if (!solution) return nullptr;
  if (!pairs) return solution->Find(d.modes[i].label);
  const int k = (*pairs)[i];
  return k >= 0 && k < static_cast<int>(solution->modes.size()) ? &solution->modes[k] : nullptr;
}

namespace {

// The measured modes as records: a repeated condition measures each mode again.
class ModeRecords final : public MeasurementRecords {
 public:
  int Items(const Dataset& d) const override { return static_cast<int>(d.modes.size()); }
  int ConditionOf(const Dataset& d, int i) const override { return d.modes[i].condition; }
  std::string ItemName(const Dataset& d, int i) const override {
    return std::string(LabelName(d.modes[i].label)) + " mode";
  }
  // The modes the model has there (by label); a frequency's sigma keeps its
  // share of the frequency.
  void Repeat(const ModelAt& at, int from, int to, double, Dataset* d) const override {
    const size_t n = d->modes.size();
    for (size_t i = 0; i < n; ++i) {
      if (d->modes[i].condition != from) continue;
      const Mode* mode = at.solution ? at.solution->Find(d->modes[i].label) : nullptr;
      if (!mode) continue;
      MeasuredMode m = d->modes[i];
      m.condition = to;
      if (m.frequency_sigma_hz) {
        m.frequency_sigma_hz = *m.frequency_sigma_hz / m.frequency_hz * mode->frequency_hz;
      }
      d->modes.push_back(m);
    }
  }
};

const ModeRecords& TheModeRecords() {
  static const ModeRecords records;
  return records;
}

// A quantity of the mode family as a kind of measurement: each measured mode
// an item, compared with its paired model mode.
class OfModes final : public Measurement {
 public:
  explicit OfModes(const ModeQuantity& unit) : unit_(unit) {}
  Quantity quantity() const override { return unit_.quantity(); }
  const char* description() const override { return unit_.description(); }
  const char* unit() const override { return unit_.unit(); }
  const MeasurementRecords& records() const override { return TheModeRecords(); }
  std::string Addition(const Dataset& d, int i) const override {
    return std::string(unit_.description()) + " of the " + LabelName(d.modes[i].label) + " mode";
  }
  int Rows(const Dataset& d, int i, const MeasurementOptions& o) const override {
    return unit_.Rows(d.modes[i], o);
  }
  int Scales(const Dataset& d, int i, const MeasurementOptions& o) const override {
    return unit_.Scales(d.modes[i], o);
  }
  std::string Count(int n) const override { return unit_.Count(n); }
  bool Evaluate(const Dataset& d, int i, const ModelAt& at, const MeasurementOptions& o,
                double* r, const std::vector<int>* params,
                Eigen::Ref<RowMatrix> dr) const override {
    const Mode* mode = at.ModeOf(d, i);
    if (!mode || (params && !mode->derivatives)) return false;
    unit_.Evaluate(d.modes[i], *mode, o, r, params, dr);
    return true;
  }
  void AddMisfit(const Dataset& d, int i, int component, double r, const MeasurementOptions&,
                 MisfitTable* t) const override {
    if (t->modes.size() != d.modes.size()) {  // the table's mode entries, once
      t->modes.assign(d.modes.size(), ModeMisfit{});
      for (size_t k = 0; k < d.modes.size(); ++k) {
        t->modes[k].label = d.modes[k].label;
        if (d.NamesConditions()) t->modes[k].condition = d.conditions[d.modes[k].condition].name;
      }
    }
    ModeMisfit& w = t->modes[i];
    w.chi2 += r * r;
    unit_.AddMisfit(d.modes[i], component, r, &w);
  }
  bool Scalar(const Dataset& d, int i, const MeasurementOptions& o, double* value, double* sigma,
              ModeLabel* label, bool* damping) const override {
    *label = d.modes[i].label;
    *damping = unit_.SetByDampers();
    return unit_.Scalar(d.modes[i], o, value, sigma);
  }
  bool Measure(const ModelAt& at, int i, const MeasurementOptions& o, Dataset* d) const override {
    const Mode* mode = at.ModeOf(*d, i);
    if (!mode) return false;
    unit_.Measure(*mode, o, &d->modes[i]);
    return true;
  }
  void AddUnmeasured(const ModelAt& at, int c, const MeasurementOptions& o,
                     const AdviceSigmas& sigmas, Dataset* d) const override {
    for (size_t i = 0; i < d->modes.size(); ++i) {
      MeasuredMode& m = d->modes[i];
      const Mode* mode = m.condition == c ? at.ModeOf(*d, static_cast<int>(i)) : nullptr;
      if (mode && unit_.Rows(m, o) == 0) unit_.Add(*mode, o, sigmas, &m);
    }
  }
  void AddNoise(double noise, const std::function<double()>& draw, int i,
                Dataset* d) const override {
    unit_.AddNoise(noise, draw, &d->modes[i]);
  }

 private:
  const ModeQuantity& unit_;
};

}  // namespace

const std::vector<const ModeQuantity*>& ModeQuantities() {
  static const std::vector<const ModeQuantity*> all = {
      &FrequencyMeasurement(), &DampingMeasurement(), &ShapeMeasurement()};
  return all;
}

const MeasurementRecords& ModeRecords() { return TheModeRecords(); }

const std::vector<const MeasurementRecords*>& Records() {
  static const std::vector<const MeasurementRecords*> all = {&TheModeRecords(), &StaticRecords(),
                                                              &FrfRecords()};
  return all;
}

const std::vector<const Measurement*>& Measurements() {
  static const std::vector<OfModes> of_modes = [] {
    std::vector<OfModes> units;
    for (const ModeQuantity* unit : ModeQuantities()) units.emplace_back(*unit);
    return units;
  }();
  static const std::vector<const Measurement*> all = [] {
    std::vector<const Measurement*> kinds;
    for (const OfModes& unit : of_modes) kinds.push_back(&unit);
    kinds.push_back(&StaticMeasurement());
    kinds.push_back(&FrfMeasurement());
    return kinds;
  }();
  return all;
}

const Measurement& MeasurementOf(Quantity q) {
  for (const Measurement* unit : Measurements()) {
    if (unit->quantity() == q) return *unit;
  }
  return *Measurements().front();  // every Quantity is registered
}

}  // namespace ringid
