// A measured static stiffness (contract §10): the model's static solve at the
// condition's load (model/static_stiffness.h), standing conditions only.
#include <set>

#include "datasets/measurement.h"
#include "model/static_stiffness.h"

namespace ringid {
namespace {

class StaticItems final : public MeasurementRecords {
 public:
  int Items(const Dataset& d) const override { return static_cast<int>(d.statics.size()); }
  int ConditionOf(const Dataset& d, int i) const override { return d.statics[i].condition; }
  std::string ItemName(const Dataset& d, int i) const override {
    return std::string("static ") + ToString(d.statics[i].direction) + " stiffness";
  }
  // Measured again in a standing condition only.
  void Repeat(const ModelAt&, int from, int to, double speed, Dataset* d) const override {
    if (speed > 0) return;
    const size_t n = d->statics.size();
    for (size_t i = 0; i < n; ++i) {
      if (d->statics[i].condition != from) continue;
      MeasuredStatic m = d->statics[i];
      m.condition = to;
      d->statics.push_back(m);
    }
  }
};

const StaticItems& TheStaticItems() {
  static const StaticItems records;
  return records;
}

double Sigma(const MeasuredStatic& m) {
  return m.sigma.value_or(kDefaultStaticRelativeSigma * m.value);
}

class Static final : public Measurement {
 public:
  Quantity quantity() const override { return Quantity::kStatic; }
  const char* description() const override { return "static stiffness"; }
  const char* unit() const override { return "N/m"; }
  const MeasurementRecords& records() const override { return TheStaticItems(); }
  std::string Addition(const Dataset& d, int i) const override {
    std::string words = "a static " + std::string(ToString(d.statics[i].direction)) + " stiffness";
    if (d.conditions.size() > 1) words += " in condition " + d.conditions[d.statics[i].condition].name;
    return words;
  }
  int Rows(const Dataset&, int, const MeasurementOptions&) const override { return 1; }
  bool SeesScale() const override { return true; }  // a stiffness, not a ratio of them
  std::string Count(int n) const override { return std::to_string(n) + " static stiffnesses"; }
  bool Evaluate(const Dataset& d, int i, const ModelAt& at, const MeasurementOptions&, double* r,
                const std::vector<int>* params, Eigen::Ref<RowMatrix> dr) const override {
    const MeasuredStatic& m = d.statics[i];
    const StaticStiffnessResult k =
        StaticStiffness(*at.model, *at.parameters, m.direction, params != nullptr);
    if (!k.ok) return false;
    const double sigma = Sigma(m);
    r[0] = (k.value - m.value) / sigma;
    if (params) {
      for (size_t j = 0; j < params->size(); ++j) dr(0, j) = k.derivative[(*params)[j]] / sigma;
    }
    return true;
  }
  void AddMisfit(const Dataset& d, int i, int, double r, const MeasurementOptions&,
                 MisfitTable* t) const override {
    ItemMisfit w;
    if (d.NamesConditions()) w.condition = d.conditions[d.statics[i].condition].name;
    w.name = TheStaticItems().ItemName(d, i);
    w.sigma = r;
    t->others.push_back(w);
  }
  bool Compared(const Dataset& d, int i, const ModelAt& at, double* measured, double* sigma,
                double* model) const override {
    const MeasuredStatic& m = d.statics[i];
    const StaticStiffnessResult k = StaticStiffness(*at.model, *at.parameters, m.direction);
    *measured = m.value;
    *sigma = Sigma(m);
    *model = k.value;
    return k.ok;
  }
  bool Measure(const ModelAt& at, int i, const MeasurementOptions&, Dataset* d) const override {
    MeasuredStatic& m = d->statics[i];
    const StaticStiffnessResult k = StaticStiffness(*at.model, *at.parameters, m.direction);
    if (!k.ok) return false;
    m.value = k.value;
    return true;
  }
  void AddUnmeasured(const ModelAt& at, int c, const MeasurementOptions&,
                     const AdviceSigmas& sigmas, Dataset* d) const override {
    if (d->conditions[c].speed_m_s > 0) return;
    std::set<StaticDirection> measured;
    for (const MeasuredStatic& m : d->statics) {
      if (m.condition == c) measured.insert(m.direction);
    }
    for (int k = 0; k < kNumStaticDirections; ++k) {
      const auto direction = static_cast<StaticDirection>(k);
      if (measured.count(direction)) continue;
      const StaticStiffnessResult value = StaticStiffness(*at.model, *at.parameters, direction);
      if (!value.ok) continue;
      d->statics.push_back({direction, value.value, sigmas.static_relative * value.value, c});
    }
  }
  void AddNoise(double noise, const std::function<double()>& draw, int i,
                Dataset* d) const override {
    MeasuredStatic& m = d->statics[i];
    if (!(noise > 0)) return;
    m.sigma = noise * m.value;
    m.value *= 1 + noise * draw();
  }
};

}  // namespace

const Measurement& StaticMeasurement() {
  static const Static unit;
  return unit;
}

const MeasurementRecords& StaticRecords() { return TheStaticItems(); }

}  // namespace ringid
