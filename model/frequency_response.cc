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

// A dynamic stiffness this close to singular is an undamped resonance: its
// reciprocal condition number (Respond: Eigen's estimate), or a pivot of its
// LU against its 1-norm (Lines), below this.
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

// H alone (no derivatives: a fit's residuals, its numeric Jacobians). D is
// block diagonal over the coordinates its entries couple (standing without
// effects {x_b, theta_a, theta_b}, {z_b}, {y_b, gamma_b, psi_b}); each line
// factors the blocks apart on the stack and solves for the inputs that act
// on each. The entries off the blocks are exact zeros, so H is Respond's to
// roundoff.
class Lines {
 public:
  Lines(const MechanicalSystem& s, const Parameters& p, const ResponseRequest& request)
      : on_(s), speed_(s.speed()) {
    const int k = on_.size();
    bool coupled[kNumDofs][kNumDofs];
    for (int a = 0; a < k; ++a) {
      for (int b = 0; b < k; ++b) {
        const int i = on_.dofs[a], j = on_.dofs[b];
        coupled[a][b] = s.M()(i, j) != 0 || s.C()(i, j) != 0 || s.K()(i, j) != 0;
      }
    }
    std::vector<LagRows> lags = speed_ > 0 ? LagsOf(s) : std::vector<LagRows>{};
    for (const LagRows& L : lags) {
      for (int a = 0; a < k; ++a) {
        for (int b = 0; b < k; ++b) coupled[a][b] |= L.fd[a][b] != 0 || L.fe[a][b] != 0;
      }
    }
    const Mat<double> B = Inputs<double>(request.inputs, p, on_);
    for (const std::vector<int>& members : Connected(coupled, k)) {
      blocks_.push_back(BlockOf(s, lags, B, members));
    }
    X_.assign(static_cast<size_t>(k) * B.cols(), Complex(0));
    // Each function's terms: the output's nonzero coefficients against the
    // input's column of X.
    const auto G_d = s.axle_displacement();
    const auto G_v = s.axle_velocity();
    for (const auto& [o, i] : request.pairs) {
      const ResponseOutput& out = request.outputs[o];
      Function f{static_cast<int>(terms_.size()), 0, out.channel.has_value(), out.order};
      for (int a = 0; a < k; ++a) {
        const int d = on_.dofs[a];
        double c = 0, v = 0;
        if (out.channel) {
          c = G_d(static_cast<int>(*out.channel), d);
          v = G_v(static_cast<int>(*out.channel), d);
        } else {
          for (const auto& [dof, coef] : out.coordinates) c += static_cast<int>(dof) == d ? coef : 0;
        }
        if (c != 0 || v != 0) terms_.push_back({a + k * i, c, v});
      }
      f.end = static_cast<int>(terms_.size());
      functions_.push_back(f);
    }
  }

  // Row l of r->H at w; false where D is singular there.
  bool At(double w, int l, ResponseResult* r) {
    for (const Block& block : blocks_) {
      if (!Solve(block, w)) return false;
    }
    const Complex* X = X_.data();
    for (int f = 0; f < static_cast<int>(functions_.size()); ++f) {
      const Function& fn = functions_[f];
      Complex h = 0;
      if (fn.channel) {
        for (int t = fn.begin; t < fn.end; ++t) {
          h += Mul(Complex(terms_[t].displacement, w * terms_[t].velocity), X[terms_[t].x]);
        }
      } else {
        for (int t = fn.begin; t < fn.end; ++t) h += terms_[t].displacement * X[terms_[t].x];
        for (int n = 0; n < fn.order; ++n) h = Complex(-w * h.imag(), w * h.real());  // (i w)^order
      }
      r->H(l, f) = h;
    }
    return true;
  }

 private:
  struct Term {
    int x;  // into X_: the active row + k * the input
    double displacement, velocity;
  };
  struct Function {
    int begin, end;  // its terms
    bool channel;
    int order;
  };
  // Each lag's f d^T and f e^T over the active rows, whose coefficients at a
  // line Stiffness gives.
  struct LagRows {
    double K, sigma;
    double fd[kNumDofs][kNumDofs], fe[kNumDofs][kNumDofs];
  };
  // One block of D: its rows, M, C, K on them (row-major m x m), the lags'
  // terms, and the inputs that act on it with their generalised forces.
  struct Block {
    std::vector<int> rows;
    std::vector<double> M, C, K;
    std::vector<LagRows> lags;  // fd, fe over the block's m x m
    std::vector<std::pair<int, std::vector<double>>> inputs;
  };

  static Complex Mul(const Complex& a, const Complex& b) {
    return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
  }
  // An entry's size for pivots and norms: |re| + |im| (LAPACK's cabs1).
  static double Size(const Complex& z) { return std::abs(z.real()) + std::abs(z.imag()); }

  std::vector<LagRows> LagsOf(const MechanicalSystem& s) const {
    std::vector<LagRows> out;
    for (const auto& lag : s.lags()) {
      LagRows L{lag.stiffness, lag.relaxation_length, {}, {}};
      for (const auto& [row_dof, f] : lag.force) {
        const int a = on_[row_dof];
        if (a < 0) continue;
        for (const auto& [col_dof, d] : lag.velocity) {
          if (on_[col_dof] >= 0) L.fd[a][on_[col_dof]] += f * d;
        }
        for (const auto& [col_dof, e] : lag.heading) {
          if (on_[col_dof] >= 0) L.fe[a][on_[col_dof]] += f * e;
        }
      }
      out.push_back(L);
    }
    return out;
  }

  // The connected sets of rows that D's entries couple.
  static std::vector<std::vector<int>> Connected(const bool (*coupled)[kNumDofs], int k) {
    std::vector<std::vector<int>> sets;
    std::array<bool, kNumDofs> placed{};
    for (int start = 0; start < k; ++start) {
      if (placed[start]) continue;
      std::vector<int> members = {start};
      placed[start] = true;
      for (size_t n = 0; n < members.size(); ++n) {
        for (int b = 0; b < k; ++b) {
          if (!placed[b] && (coupled[members[n]][b] || coupled[b][members[n]])) {
            placed[b] = true;
            members.push_back(b);
          }
        }
      }
      sets.push_back(std::move(members));
    }
    return sets;
  }

  Block BlockOf(const MechanicalSystem& s, const std::vector<LagRows>& lags, const Mat<double>& B,
                const std::vector<int>& rows) const {
    const int m = static_cast<int>(rows.size());
    Block b{rows, {}, {}, {}, {}, {}};
    for (int x = 0; x < m; ++x) {
      for (int y = 0; y < m; ++y) {
        const int i = on_.dofs[rows[x]], j = on_.dofs[rows[y]];
        b.M.push_back(s.M()(i, j));
        b.C.push_back(s.C()(i, j));
        b.K.push_back(s.K()(i, j));
      }
    }
    for (const LagRows& L : lags) {
      LagRows on{L.K, L.sigma, {}, {}};
      for (int x = 0; x < m; ++x) {
        for (int y = 0; y < m; ++y) {
          on.fd[x][y] = L.fd[rows[x]][rows[y]];
          on.fe[x][y] = L.fe[rows[x]][rows[y]];
        }
      }
      b.lags.push_back(on);
    }
    for (int i = 0; i < B.cols(); ++i) {
      std::vector<double> column(m);
      bool acts = false;
      for (int x = 0; x < m; ++x) acts |= (column[x] = B(rows[x], i)) != 0;
      if (acts) b.inputs.emplace_back(i, std::move(column));
    }
    return b;
  }

  // D's block at w by a partially pivoted LU, X = D^-1 B on its rows for the
  // inputs that act on it; false where a pivot is below kSingularRcond of the
  // block's largest column (1-norm). Small blocks are solved at a fixed size,
  // in registers.
  bool Solve(const Block& b, double w) {
    switch (b.rows.size()) {
      case 1: { Complex A[1][1], v[1]; return Solve<1>(b, w, A, v); }
      case 2: { Complex A[2][2], v[2]; return Solve<2>(b, w, A, v); }
      case 3: { Complex A[3][3], v[3]; return Solve<3>(b, w, A, v); }
      case 4: { Complex A[4][4], v[4]; return Solve<4>(b, w, A, v); }
      default: return Solve<0>(b, w, A_, v_);
    }
  }
  template <int kSize, class Square, class Column>  // kSize 0: b's
  bool Solve(const Block& b, double w, Square& A, Column& v) {
    const int m = kSize > 0 ? kSize : static_cast<int>(b.rows.size());
    int pivot[kNumDofs];
    double norm = 0, smallest = INFINITY;
    for (int x = 0; x < m; ++x) {
      for (int y = 0; y < m; ++y) {
        const int e = x * m + y;
        A[x][y] = Complex(b.K[e] - w * w * b.M[e], w * b.C[e]);
      }
    }
    if (!b.lags.empty()) AddLagTerms(b, w, m, A);
    for (int y = 0; y < m; ++y) {
      double column = 0;
      for (int x = 0; x < m; ++x) column += Size(A[x][y]);
      norm = std::max(norm, column);
    }
    for (int c = 0; c < m; ++c) {
      int best = c;
      for (int x = c + 1; x < m; ++x) best = Size(A[x][c]) > Size(A[best][c]) ? x : best;
      pivot[c] = best;
      if (best != c) {
        for (int y = 0; y < m; ++y) std::swap(A[c][y], A[best][y]);
      }
      const Complex u = A[c][c];
      smallest = std::min(smallest, Size(u));
      const double size2 = u.real() * u.real() + u.imag() * u.imag();
      if (!(size2 > 0)) return false;
      const Complex reciprocal(u.real() / size2, -u.imag() / size2);
      A[c][c] = reciprocal;  // kept inverted for the solves
      for (int x = c + 1; x < m; ++x) {
        const Complex l = Mul(A[x][c], reciprocal);
        A[x][c] = l;
        for (int y = c + 1; y < m; ++y) A[x][y] -= Mul(l, A[c][y]);
      }
    }
    if (!(smallest > kSingularRcond * norm)) return false;
    for (const auto& [input, column] : b.inputs) {
      for (int x = 0; x < m; ++x) v[x] = column[x];
      for (int c = 0; c < m; ++c) std::swap(v[c], v[pivot[c]]);  // P
      for (int c = 0; c < m; ++c) {  // L (unit diagonal)
        for (int x = c + 1; x < m; ++x) v[x] -= Mul(A[x][c], v[c]);
      }
      for (int x = m - 1; x >= 0; --x) {  // U
        for (int y = x + 1; y < m; ++y) v[x] -= Mul(A[x][y], v[y]);
        v[x] = Mul(v[x], A[x][x]);
      }
      for (int x = 0; x < m; ++x) X_[b.rows[x] + on_.size() * input] = v[x];
    }
    return true;
  }

  // The lags' terms of eq. (F1) on the block, as Stiffness writes them.
  template <class Square>
  void AddLagTerms(const Block& b, double w, int m, Square& A) const {
    for (const LagRows& L : b.lags) {
      const double den = speed_ * speed_ + L.sigma * L.sigma * w * w;
      const double g_re = L.K * speed_ / den, g_im = -L.K * L.sigma * w / den;
      const Complex on_d(-L.K / L.sigma - g_im * w, g_re * w), on_e(-g_re * speed_, -g_im * speed_);
      for (int x = 0; x < m; ++x) {
        for (int y = 0; y < m; ++y) A[x][y] += on_d * L.fd[x][y] + on_e * L.fe[x][y];
      }
    }
  }

  const Active on_;
  const double speed_;
  std::vector<Block> blocks_;
  std::vector<Function> functions_;
  std::vector<Term> terms_;
  // D^-1 B over the active rows (column-major), zero where an input misses a block.
  std::vector<Complex> X_;
  // A block's LU and a right-hand side: members, as std::complex zeroes the
  // arrays it constructs.
  Complex A_[kNumDofs][kNumDofs], v_[kNumDofs];
};

ResponseResult RespondValues(const MechanicalSystem& s, const Parameters& p,
                             const ResponseRequest& request) {
  ResponseResult r;
  const int lines = static_cast<int>(request.frequencies_hz.size());
  r.H.resize(lines, static_cast<int>(request.pairs.size()));
  Lines solver(s, p, request);
  for (int l = 0; l < lines; ++l) {
    if (!solver.At(2 * M_PI * request.frequencies_hz[l], l, &r)) {
      r.error = "the dynamic stiffness is singular at " +
                std::to_string(request.frequencies_hz[l]) + " Hz (an undamped resonance)";
      return r;
    }
  }
  if (!r.H.allFinite()) {
    r.error = "the response is not finite";
    return r;
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
  if (!params) return RespondValues(s, p, request);
  const ParameterArray<ParameterJet> jets = Seeded(p);
  return Respond(model.Assemble(jets, speed_m_s), jets, request, params);
}

}  // namespace ringid
