#include "model/frequency_response.h"

#include <array>
#include <cmath>

#include <Eigen/LU>

#include "model/forced_response.h"

namespace ringid {
namespace {

template <class T>
using Mat = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;
using CMat = Eigen::MatrixXcd;

double Value(double v) { return v; }
double Value(const ParameterJet& v) { return v.a; }
double Slope(double, int) { return 0; }
double Slope(const ParameterJet& v, int p) { return v.v[p]; }

// A complex matrix as its real and imaginary parts, each of scalar T.
template <class T>
struct Parts {
  Mat<T> re, im;
  Parts(int rows, int cols) : re(rows, cols), im(rows, cols) {
    re.setConstant(T(0.0));
    im.setConstant(T(0.0));
  }
  CMat Values() const {
    CMat out(re.rows(), re.cols());
    for (int a = 0; a < re.rows(); ++a) {
      for (int b = 0; b < re.cols(); ++b) out(a, b) = Complex(Value(re(a, b)), Value(im(a, b)));
    }
    return out;
  }
  CMat Slopes(int p) const {
    CMat out(re.rows(), re.cols());
    for (int a = 0; a < re.rows(); ++a) {
      for (int b = 0; b < re.cols(); ++b) {
        out(a, b) = Complex(Slope(re(a, b), p), Slope(im(a, b), p));
      }
    }
    return out;
  }
};

// The active coordinates and the row of each (-1: held).
struct Active {
  std::vector<int> dofs;
  std::array<int, kNumDofs> row;
  template <class T>
  explicit Active(const BasicSystem<T>& s) {
    row.fill(-1);
    for (int d = 0; d < kNumDofs; ++d) {
      if (!s.active(static_cast<Dof>(d))) continue;
      row[d] = static_cast<int>(dofs.size());
      dofs.push_back(d);
    }
  }
  int operator[](Dof d) const { return row[static_cast<int>(d)]; }
  int size() const { return static_cast<int>(dofs.size()); }
};

// Eq. (F1) at lambda = i w: K - w^2 M + i w C, and at speed each lag's
// standstill spring (K/sigma) f d^T taken out and K f (V e - i w d)^T /
// (i w sigma + V) put in, written out in real and imaginary parts.
template <class T>
Parts<T> Stiffness(const BasicSystem<T>& s, const Active& on, double w) {
  const int k = on.size();
  Parts<T> D(k, k);
  for (int a = 0; a < k; ++a) {
    for (int b = 0; b < k; ++b) {
      const int i = on.dofs[a], j = on.dofs[b];
      D.re(a, b) = s.K()(i, j) - w * w * s.M()(i, j);
      D.im(a, b) = w * s.C()(i, j);
    }
  }
  if (!(s.speed() > 0)) return D;  // the lags' standstill springs are K's
  const double V = s.speed();
  for (const auto& lag : s.lags()) {
    const T sigma = lag.relaxation_length;
    const T den = V * V + sigma * sigma * w * w;
    const T g_re = lag.stiffness * V / den, g_im = -lag.stiffness * sigma * w / den;
    const T standstill = lag.stiffness / sigma;
    for (const auto& [row_dof, f] : lag.force) {
      const int a = on[row_dof];
      if (a < 0) continue;
      for (const auto& [col_dof, d] : lag.velocity) {
        const int b = on[col_dof];
        if (b < 0) continue;
        D.re(a, b) -= standstill * f * d + g_im * w * f * d;
        D.im(a, b) += g_re * w * f * d;
      }
      for (const auto& [col_dof, e] : lag.heading) {
        const int b = on[col_dof];
        if (b < 0) continue;
        D.re(a, b) -= g_re * V * f * e;
        D.im(a, b) -= g_im * V * f * e;
      }
    }
  }
  return D;
}

// The inputs' generalised forces over the active coordinates (eq. F2 for a
// contact force).
template <class T, class P>
Mat<T> Inputs(const std::vector<ResponseInput>& inputs, const P& p, const Active& on) {
  const auto lug = LugForceColumns<T>(p);
  Mat<T> B(on.size(), static_cast<int>(inputs.size()));
  B.setConstant(T(0.0));
  for (int i = 0; i < B.cols(); ++i) {
    const ResponseInput& in = inputs[i];
    if (in.contact) {
      for (int a = 0; a < on.size(); ++a) B(a, i) = lug(on.dofs[a], static_cast<int>(*in.contact));
    }
    for (const auto& [dof, c] : in.coordinates) {
      if (on[dof] >= 0) B(on[dof], i) += T(c);  // a rim point's held hub aside
    }
  }
  return B;
}

// The outputs' rows at w: an axle channel G_d + i w G_v (eq. F3), or a
// combination times (i w)^order.
template <class T>
Parts<T> Outputs(const std::vector<ResponseOutput>& outputs, const BasicSystem<T>& s,
                 const Active& on, double w) {
  Parts<T> G(static_cast<int>(outputs.size()), on.size());
  const auto G_d = s.axle_displacement();
  const auto G_v = s.axle_velocity();
  for (int o = 0; o < G.re.rows(); ++o) {
    const ResponseOutput& out = outputs[o];
    if (out.channel) {
      const int c = static_cast<int>(*out.channel);
      for (int a = 0; a < on.size(); ++a) {
        G.re(o, a) = G_d(c, on.dofs[a]);
        G.im(o, a) = w * G_v(c, on.dofs[a]);
      }
      continue;
    }
    const Complex factor = std::pow(Complex(0, w), out.order);
    for (const auto& [dof, c] : out.coordinates) {
      if (on[dof] < 0) continue;  // a rim point's held hub
      G.re(o, on[dof]) += T(factor.real() * c);
      G.im(o, on[dof]) += T(factor.imag() * c);
    }
  }
  return G;
}

// A dynamic stiffness this close to singular is an undamped resonance.
constexpr double kSingularRcond = 1e-14;

template <class T, class P>
ResponseResult Respond(const BasicSystem<T>& s, const P& p, const ResponseRequest& request,
                       const std::vector<int>* params) {
  ResponseResult r;
  const Active on(s);
  const int lines = static_cast<int>(request.frequencies_hz.size());
  const int functions = static_cast<int>(request.pairs.size());
  const int n = params ? static_cast<int>(params->size()) : 0;
  r.H.resize(lines, functions);
  r.dH.assign(n, CMat(lines, functions));
  const Mat<T> B = Inputs<T>(request.inputs, p, on);
  Mat<double> Bv(B.rows(), B.cols());
  for (int a = 0; a < B.rows(); ++a) {
    for (int b = 0; b < B.cols(); ++b) Bv(a, b) = Value(B(a, b));
  }
  const CMat Bc = Bv.cast<Complex>();
  for (int l = 0; l < lines; ++l) {
    const double w = 2 * M_PI * request.frequencies_hz[l];
    const Parts<T> D = Stiffness(s, on, w);
    const Parts<T> G = Outputs(request.outputs, s, on, w);
    const Eigen::PartialPivLU<CMat> lu(D.Values());
    if (!(lu.rcond() > kSingularRcond)) {
      r.error = "the dynamic stiffness is singular at " +
                std::to_string(request.frequencies_hz[l]) + " Hz (an undamped resonance)";
      return r;
    }
    const CMat Gv = G.Values();
    const CMat X = lu.solve(Bc);  // D^-1 B
    const CMat GX = Gv * X;
    for (int f = 0; f < functions; ++f) r.H(l, f) = GX(request.pairs[f].first, request.pairs[f].second);
    if (n == 0) continue;
    const CMat Y = Gv * lu.inverse();  // G D^-1; D is at most 10 x 10
    for (int k = 0; k < n; ++k) {
      const int q = (*params)[k];
      const CMat dX = D.Slopes(q) * X;
      const CMat dG = G.Slopes(q);
      CMat dB(B.rows(), B.cols());
      for (int a = 0; a < B.rows(); ++a) {
        for (int b = 0; b < B.cols(); ++b) dB(a, b) = Slope(B(a, b), q);
      }
      for (int f = 0; f < functions; ++f) {
        const auto [o, i] = request.pairs[f];
        const Complex a = dG.row(o) * X.col(i), b = Y.row(o) * dB.col(i),
                      c = Y.row(o) * dX.col(i);
        r.dH[k](l, f) = a + b - c;
      }
    }
  }
  if (!r.H.allFinite()) {
    r.error = "the response is not finite";
    return r;
  }
  for (const CMat& d : r.dH) {
    if (!d.allFinite()) {
      r.error = "the response's derivatives are not finite";
      return r;
    }
  }
  r.ok = true;
  return r;
}

bool Hub(Dof d) { return d == Dof::kXa || d == Dof::kZa || d == Dof::kYa; }

template <class T>
std::optional<Dof> Missing(const BasicSystem<T>& s, const Coordinates& c, bool on_rim) {
  for (const auto& [dof, coef] : c) {
    if (!s.active(dof) && !(on_rim && Hub(dof))) return dof;
  }
  return std::nullopt;
}

}  // namespace

std::optional<Dof> MissingCoordinate(const ModalModel& model, const Coordinates& c,
                                     bool on_rim) {
  Parameters p;  // each effect at a positive size, where it frees what it frees
  for (int i = 0; i < kNumParams; ++i) p[ParamAt(i)] = 1;
  return Missing(model.Assemble(p, 0), c, on_rim);
}

ResponseResult FrequencyResponse(const ModalModel& model, const Parameters& p, double speed_m_s,
                                 const ResponseRequest& request,
                                 const std::vector<int>* params) {
  ResponseResult r;
  if (!(speed_m_s >= 0) || !std::isfinite(speed_m_s)) {
    r.error = "the speed must be finite and not negative";
    return r;
  }
  for (double hz : request.frequencies_hz) {
    if (!(hz > 0) || !std::isfinite(hz)) {
      r.error = "every frequency must be positive";
      return r;
    }
  }
  for (Param q : model.parameters()) {
    if (!std::isfinite(p[q])) {
      r.error = std::string("parameter ") + ParamName(q) + " is not finite";
      return r;
    }
  }
  const MechanicalSystem s = model.Assemble(p, speed_m_s);
  for (const ResponseInput& in : request.inputs) {
    if (auto d = Missing(s, in.coordinates, in.on_rim)) {
      r.error = std::string("an input acts on ") + DofName(*d) + ", which the model lacks";
      return r;
    }
  }
  for (const ResponseOutput& out : request.outputs) {
    if (auto d = Missing(s, out.coordinates, out.on_rim)) {
      r.error = std::string("an output reads ") + DofName(*d) + ", which the model lacks";
      return r;
    }
  }
  if (!params) return Respond(s, p, request, nullptr);
  const ParameterArray<ParameterJet> jets = Seeded(p);
  return Respond(model.Assemble(jets, speed_m_s), jets, request, params);
}

}  // namespace ringid
