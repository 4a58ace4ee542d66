// A measured modal damping ratio (docs/conventions.md §2).
#include "datasets/measurement.h"

#include <algorithm>

namespace ringid {
namespace {

class Damping : public ModeQuantity {
 public:
  Quantity quantity() const override { return Quantity::kDamping; }
  const char* description() const override { return "damping ratio"; }
  const char* unit() const override { return "-"; }
  std::string Count(int n) const override { return std::to_string(n) + " damping ratios"; }
  bool SetByDampers() const override { return true; }
  bool In(const MeasuredMode& m) const override { return m.damping_ratio.has_value(); }
  int Rows(const MeasuredMode& m, const MeasurementOptions& o) const override {
    return o.use_damping && In(m) ? 1 : 0;
  }
  void Evaluate(const MeasuredMode& m, const Mode& mode, const MeasurementOptions& o, double* r,
                const std::vector<int>* params, Eigen::Ref<RowMatrix> dr) const override {
    const double sigma = Sigma(m, o);
    r[0] = (mode.damping_ratio - *m.damping_ratio) / sigma;
    if (!params) return;
    for (size_t k = 0; k < params->size(); ++k) {
      dr(0, k) = mode.derivatives->DampingRatio(mode.eigenvalue, (*params)[k]) / sigma;
    }
  }
  void AddMisfit(const MeasuredMode&, int, double r, ModeMisfit* w) const override {
    w->damping_sigma = r;
  }
  bool Scalar(const MeasuredMode& m, const MeasurementOptions& o, double* value,
              double* sigma) const override {
    *value = *m.damping_ratio;
    *sigma = Sigma(m, o);
    return true;
  }
  void Measure(const Mode& mode, const MeasurementOptions&, MeasuredMode* m) const override {
    if (In(*m)) m->damping_ratio = Clamped(mode.damping_ratio);
  }
  void Add(const Mode& mode, const MeasurementOptions&, const AdviceSigmas& sigmas,
           MeasuredMode* m) const override {
    const double sigma = sigmas.damping;
    m->damping_ratio = Clamped(mode.damping_ratio);
    m->damping_sigma = sigma;
  }
  void AddNoise(double noise, const std::function<double()>& draw,
                MeasuredMode* m) const override {
    if (!In(*m)) return;
    m->damping_sigma = noise * *m->damping_ratio;
    m->damping_ratio = Clamped(*m->damping_ratio * (1 + noise * draw()));
  }

 private:
  static double Sigma(const MeasuredMode& m, const MeasurementOptions& o) {
    return m.damping_sigma.value_or(o.default_damping_sigma);
  }
  // A model's ratio held this far inside the loader's open interval
  // (DampingRatioProblem), so that the dataset written reads back.
  static constexpr double kInside = 1e-6;
  static double Clamped(double z) {
    return std::clamp(z, kMinDampingRatio + kInside, kMaxDampingRatio - kInside);
  }
};

}  // namespace

const ModeQuantity& DampingMeasurement() {
  static const Damping unit;
  return unit;
}

}  // namespace ringid
