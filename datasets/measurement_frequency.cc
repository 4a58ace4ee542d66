// A measured natural frequency (the damped one, docs/conventions.md §2).
#include "datasets/measurement.h"

namespace ringid {
namespace {

class Frequency : public ModeQuantity {
 public:
  Quantity quantity() const override { return Quantity::kFrequency; }
  const char* description() const override { return "natural frequency"; }
  const char* unit() const override { return "Hz"; }
  std::string Count(int n) const override { return std::to_string(n) + " frequencies"; }
  bool In(const MeasuredMode&) const override { return true; }
  int Rows(const MeasuredMode&, const MeasurementOptions&) const override { return 1; }
  void Evaluate(const MeasuredMode& m, const Mode& mode, const MeasurementOptions& o, double* r,
                const std::vector<int>* params, Eigen::Ref<RowMatrix> dr) const override {
    const double sigma = FrequencySigma(m, o);
    r[0] = (mode.frequency_hz - m.frequency_hz) / sigma;
    if (!params) return;
    for (size_t k = 0; k < params->size(); ++k) {
      dr(0, k) = mode.derivatives->Frequency((*params)[k]) / sigma;
    }
  }
  void AddMisfit(const MeasuredMode&, int, double r, ModeMisfit* w) const override {
    w->frequency_sigma = r;
  }
  bool Scalar(const MeasuredMode& m, const MeasurementOptions& o, double* value,
              double* sigma) const override {
    *value = m.frequency_hz;
    *sigma = FrequencySigma(m, o);
    return true;
  }
  void Measure(const Mode& mode, const MeasurementOptions&, MeasuredMode* m) const override {
    m->frequency_hz = mode.frequency_hz;
  }
  void Add(const Mode& mode, const MeasurementOptions& o, const AdviceSigmas& sigmas,
           MeasuredMode* m) const override {
    const double sigma = sigmas.frequency_relative * mode.frequency_hz;
    m->frequency_hz = mode.frequency_hz;
    m->frequency_sigma_hz = sigma;
  }
  void AddNoise(double noise, const std::function<double()>& draw,
                MeasuredMode* m) const override {
    m->frequency_sigma_hz = noise * m->frequency_hz;
    m->frequency_hz *= 1 + noise * draw();
  }
};

}  // namespace

double FrequencySigma(const MeasuredMode& m, const MeasurementOptions& o) {
  if (o.frequency_weighting == FrequencyWeighting::kSigma && m.frequency_sigma_hz) {
    return *m.frequency_sigma_hz;
  }
  return o.relative_sigma * m.frequency_hz;
}

const ModeQuantity& FrequencyMeasurement() {
  static const Frequency unit;
  return unit;
}

}  // namespace ringid
