// A measured real mode shape on some degrees of freedom (docs/conventions.md
// §2), compared component by component after alignment.
#include "datasets/measurement.h"

#include <cmath>
#include <complex>

namespace ringid {
namespace {

class Shape : public ModeQuantity {
 public:
  Quantity quantity() const override { return Quantity::kShape; }
  const char* description() const override { return "mode shape"; }
  const char* unit() const override { return "-"; }
  std::string Count(int n) const override { return std::to_string(n) + " shape components beyond their scales"; }
  bool In(const MeasuredMode& m) const override { return !m.shape.empty(); }
  int Rows(const MeasuredMode& m, const MeasurementOptions& o) const override {
    return o.use_shapes ? static_cast<int>(m.shape.size()) : 0;
  }
  // The scale is fitted: a shape of n components observes n - 1 numbers.
  int Scales(const MeasuredMode& m, const MeasurementOptions& o) const override {
    return Rows(m, o) > 0 ? 1 : 0;
  }
  // The measured shape scaled to a largest component of 1, the model shape by
  // least squares onto it.
  void Evaluate(const MeasuredMode& m, const Mode& mode, const MeasurementOptions& o, double* r,
                const std::vector<int>* params, Eigen::Ref<RowMatrix> dr) const override {
    const RealShapeVector u = ComparableShape(mode, o.shape_convention, m.shape);
    double largest = 0, uu = 0, um = 0;
    for (const auto& [dof, v] : m.shape) largest = std::max(largest, std::abs(v));
    for (const auto& [dof, v] : m.shape) {
      const double ui = u[static_cast<int>(dof)];
      uu += ui * ui;
      um += ui * v / largest;
    }
    // The paper's vectors have a fixed norm (unit state vector), which
    // carries zeta / |lambda|: only their sign is free.
    const bool paper = o.shape_convention == ShapeConvention::kPaper;
    const double alpha = paper ? (um >= 0 ? 1.0 : -1.0) / largest : (uu > 0 ? um / uu : 0);
    const double sigma = m.shape_sigma.value_or(o.default_shape_sigma);
    int j = 0;
    for (const auto& [dof, v] : m.shape) {
      r[j++] = (alpha * u[static_cast<int>(dof)] - v / largest) / sigma;
    }
    if (!params) return;
    for (size_t k = 0; k < params->size(); ++k) {
      const RealShapeVector du =
          ComparableShapeDerivative(mode, o.shape_convention, m.shape, (*params)[k]);
      double duu = 0, dum = 0;
      for (const auto& [dof, v] : m.shape) {
        const int i = static_cast<int>(dof);
        duu += 2 * u[i] * du[i];
        dum += du[i] * v / largest;
      }
      const double dalpha = paper || !(uu > 0) ? 0.0 : dum / uu - um * duu / (uu * uu);
      j = 0;
      for (const auto& [dof, v] : m.shape) {
        const int i = static_cast<int>(dof);
        dr(j++, k) = (dalpha * u[i] + alpha * du[i]) / sigma;
      }
    }
  }
  void AddMisfit(const MeasuredMode& m, int component, double r, ModeMisfit* w) const override {
    w->shape_chi2 += r * r;
    if (std::abs(r) > std::abs(w->worst_component_sigma)) {
      w->worst_component_sigma = r;
      w->worst_component = DofName(m.shape[component].first);
    }
  }
  void Measure(const Mode& mode, const MeasurementOptions& o, MeasuredMode* m) const override {
    const RealShapeVector u = ComparableShape(mode, o.shape_convention);
    for (auto& [dof, v] : m->shape) v = u[static_cast<int>(dof)];
  }
  void Add(const Mode& mode, const MeasurementOptions& o, const AdviceSigmas& sigmas,
           MeasuredMode* m) const override {
    const double sigma = sigmas.shape;
    m->shape.clear();
    for (int d = 0; d < kNumDofs; ++d) {
      if (DofPlane(static_cast<Dof>(d)) == mode.plane()) m->shape.emplace_back(static_cast<Dof>(d), 0);
    }
    Measure(mode, o, m);
    m->shape_sigma = sigma;
  }
  void AddNoise(double noise, const std::function<double()>& draw,
                MeasuredMode* m) const override {
    if (!In(*m)) return;
    for (auto& [dof, v] : m->shape) v += noise * draw();
    m->shape_sigma = noise;
  }
};

}  // namespace

const ModeQuantity& ShapeMeasurement() {
  static const Shape unit;
  return unit;
}

RealShapeVector ComparableShape(const Mode& mode, ShapeConvention c) {
  return c == ShapeConvention::kPaper ? mode.PaperShape() : mode.RealShape();
}

int ShapeReference(const Mode& mode, const std::vector<std::pair<Dof, double>>& measured) {
  int model_largest = 0;
  for (int i = 1; i < kNumDofs; ++i) {
    if (std::abs(mode.shape[i]) > std::abs(mode.shape[model_largest])) model_largest = i;
  }
  // Where the model's largest component is not measured, the convention
  // took an unmeasured phase: the model's rule is the only one to follow.
  int data_largest = -1;
  bool largest_measured = false;
  double v_largest = 0;
  for (const auto& [dof, v] : measured) {
    if (std::abs(v) > v_largest) v_largest = std::abs(v), data_largest = static_cast<int>(dof);
    largest_measured |= static_cast<int>(dof) == model_largest;
  }
  if (largest_measured && data_largest >= 0 && std::abs(mode.shape[data_largest]) > 0 &&
      std::abs(mode.shape[data_largest]) >=
          kShapeReferenceShare * std::abs(mode.shape[model_largest])) {
    return data_largest;
  }
  return model_largest;
}

RealShapeVector ComparableShape(const Mode& mode, ShapeConvention c,
                                const std::vector<std::pair<Dof, double>>& measured) {
  if (c == ShapeConvention::kPaper) return mode.PaperShape();
  const std::complex<double> z = mode.shape[ShapeReference(mode, measured)];
  return (mode.shape * (std::conj(z) / std::abs(z))).real();
}

RealShapeVector ComparableShapeDerivative(const Mode& mode, ShapeConvention c,
                                          const std::vector<std::pair<Dof, double>>& measured,
                                          int p) {
  const ModeDerivatives& d = *mode.derivatives;
  const ShapeVector ds = d.shape.col(p);
  if (c == ShapeConvention::kContract) {
    // u = Re(s g), g = conj(z) / |z| with z = s_r (Mode::shape has its
    // largest component fixed at 1, so g = 1 and dg = 0 when r is that one).
    const int r = ShapeReference(mode, measured);
    const std::complex<double> z = mode.shape[r], dz = ds[r];
    const double abs_z = std::abs(z), dabs_z = (std::conj(z) * dz).real() / abs_z;
    const std::complex<double> g = std::conj(z) / abs_z;
    const std::complex<double> dg = std::conj(dz) / abs_z - std::conj(z) * dabs_z / (abs_z * abs_z);
    return (ds * g + mode.shape * dg).real();
  }
  // Mode::PaperShape: u = Re(s g) / N, g = conj(L) / |L| with L = lambda s_big
  // (s_big = 1, fixed), N^2 = |s|^2 (1 + |lambda|^2).
  const std::complex<double> lambda = mode.eigenvalue, dlambda = d.eigenvalue[p];
  const bool by_lambda = std::abs(lambda) >= 1;
  const std::complex<double> L = by_lambda ? lambda : 1.0, dL = by_lambda ? dlambda : 0.0;
  const double abs_L = std::abs(L), dabs_L = (std::conj(L) * dL).real() / abs_L;
  const std::complex<double> g = std::conj(L) / abs_L;
  const std::complex<double> dg = std::conj(dL) / abs_L - std::conj(L) * dabs_L / (abs_L * abs_L);
  const double S = mode.shape.squaredNorm();
  const double dS = 2 * (mode.shape.conjugate().cwiseProduct(ds)).sum().real();
  const double l2 = std::norm(lambda), dl2 = 2 * (std::conj(lambda) * dlambda).real();
  const double N = std::sqrt(S * (1 + l2));
  const double dN = (dS * (1 + l2) + S * dl2) / (2 * N);
  const RealShapeVector u = (mode.shape * g).real() / N;
  return (ds * g + mode.shape * dg).real() / N - u * (dN / N);
}

double Mac(const RealShapeVector& model,
           const std::vector<std::pair<Dof, double>>& measured) {
  double mm = 0, uu = 0, mu = 0;
  for (const auto& [dof, v] : measured) {
    const double u = model[static_cast<int>(dof)];
    mm += v * v;
    uu += u * u;
    mu += u * v;
  }
  if (!(mm > 0) || !(uu > 0)) return 0;
  const double mac = mu * mu / (mm * uu);
  return std::isfinite(mac) ? mac : 0;  // components beyond the range of their squares
}

}  // namespace ringid
