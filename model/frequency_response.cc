#include "model/frequency_response.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "model/forced_response.h"

namespace ringid {
namespace {

template <class T>
using Mat = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

double Slope(const ParameterJet& v, int p) { return v.v[p]; }

Complex Mul(const Complex& a, const Complex& b) {
  return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}
// An entry's size for pivots and norms: |re| + |im| (LAPACK's cabs1).
double Size(const Complex& z) { return std::abs(z.real()) + std::abs(z.imag()); }

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

// A dynamic stiffness with a pivot of its LU this far below its 1-norm is
// singular: an undamped resonance.
constexpr double kSingularRcond = 1e-14;

// The derivatives' part that no line changes, from the assembly on jets:
// for each parameter asked, the entries of dK, dM and dC, of dB, and of the
// axle rows' dG_d and dG_v; at speed each lag's K_c, sigma_c, f d^T and
// f e^T as jets, whose terms of D (eq. F1) move with the line.
struct Slopes {
  struct Entry {
    int a, b;  // active rows
    double k, m, c;
  };
  struct Force {
    int a, input;
    double value;
  };
  struct Row {
    int output, a;
    double displacement, velocity;
  };
  struct LagEntry {
    int a, b;
    ParameterJet fd, fe;
  };
  struct Lag {
    ParameterJet K, sigma;
    std::vector<LagEntry> entries;
  };

  Slopes(const BasicSystem<ParameterJet>& s, const ParameterArray<ParameterJet>& p,
         const ResponseRequest& request, const Active& on, const std::vector<int>& asked)
      : params(asked), D(asked.size()), B(asked.size()), G(asked.size()), rows(asked.size()) {
    const int k = on.size();
    const Mat<ParameterJet> Bj = Inputs<ParameterJet>(request.inputs, p, on);
    const auto G_d = s.axle_displacement();
    const auto G_v = s.axle_velocity();
    if (s.speed() > 0) AddLags(s, on);
    for (size_t j = 0; j < params.size(); ++j) {
      const int q = params[j];
      for (int a = 0; a < k; ++a) {
        for (int b = 0; b < k; ++b) {
          const int i = on.dofs[a], jj = on.dofs[b];
          const Entry e{a, b, Slope(s.K()(i, jj), q), Slope(s.M()(i, jj), q), Slope(s.C()(i, jj), q)};
          if (e.k != 0 || e.m != 0 || e.c != 0) D[j].push_back(e);
        }
        for (int i = 0; i < Bj.cols(); ++i) {
          if (Slope(Bj(a, i), q) != 0) B[j].push_back({a, i, Slope(Bj(a, i), q)});
        }
        for (int o = 0; o < static_cast<int>(request.outputs.size()); ++o) {
          if (!request.outputs[o].channel) continue;
          const int c = static_cast<int>(*request.outputs[o].channel);
          const Row g{o, a, Slope(G_d(c, on.dofs[a]), q), Slope(G_v(c, on.dofs[a]), q)};
          if (g.displacement != 0 || g.velocity != 0) G[j].push_back(g);
        }
      }
      for (const Entry& e : D[j]) rows[j].push_back(e.a);
      for (const Lag& L : lags) {
        for (const LagEntry& e : L.entries) rows[j].push_back(e.a);
      }
      std::sort(rows[j].begin(), rows[j].end());
      rows[j].erase(std::unique(rows[j].begin(), rows[j].end()), rows[j].end());
    }
  }

  std::vector<int> params;
  std::vector<std::vector<Entry>> D;  // per parameter asked
  std::vector<std::vector<Force>> B;
  std::vector<std::vector<Row>> G;
  std::vector<std::vector<int>> rows;  // the rows dD can reach
  std::vector<Lag> lags;               // at speed

 private:
  void AddLags(const BasicSystem<ParameterJet>& s, const Active& on) {
    for (const auto& lag : s.lags()) {
      Lag L{lag.stiffness, lag.relaxation_length, {}};
      const auto add = [&](int a, int b, const ParameterJet& fd, const ParameterJet& fe) {
        for (LagEntry& e : L.entries) {
          if (e.a == a && e.b == b) {
            e.fd += fd;
            e.fe += fe;
            return;
          }
        }
        L.entries.push_back({a, b, fd, fe});
      };
      const ParameterJet zero(0.0);
      for (const auto& [row_dof, f] : lag.force) {
        const int a = on[row_dof];
        if (a < 0) continue;
        for (const auto& [col_dof, d] : lag.velocity) {
          if (on[col_dof] >= 0) add(a, on[col_dof], f * d, zero);
        }
        for (const auto& [col_dof, e] : lag.heading) {
          if (on[col_dof] >= 0) add(a, on[col_dof], zero, f * e);
        }
      }
      lags.push_back(std::move(L));
    }
  }
};

// H line by line, and its exact derivatives. D is block diagonal over the
// coordinates its entries couple (standing without effects {x_b, theta_a,
// theta_b}, {z_b}, {y_b, gamma_b, psi_b}): each line factors the blocks apart
// on the stack and solves for the inputs that act on each, X = D^-1 B; with
// derivatives, Y = G D^-1 too, and dH = dG X + Y dB - Y dD X through the
// entries of dD.
class Lines {
 public:
  Lines(const MechanicalSystem& s, const Parameters& p, const ResponseRequest& request,
        bool derivatives)
      : on_(s), speed_(s.speed()), keep_(derivatives) {
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
    if (derivatives) OutputRows(s, request);
  }

  // Row l of r->H at w; false where D is singular there.
  bool At(double w, int l, ResponseResult* r) {
    for (Block& block : blocks_) {
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

  // Line l's rows of r->dH at w, after At there: dH = dG X + Y dB - Y dD X,
  // Y = G D^-1 from the blocks' LU (their transposes), dD's entries as the
  // parameter moves them (static, and at speed the lags' terms).
  void Derive(double w, int l, const Slopes& d, const ResponseRequest& request,
              ResponseResult* r) {
    const int k = on_.size(), inputs = static_cast<int>(X_.size()) / std::max(k, 1);
    const Eigen::Index lines = r->H.rows();
    for (size_t o = 0; o < outputs_.size(); ++o) OutputRow(static_cast<int>(o), w);
    std::vector<std::array<ParameterJet, 4>> lag;  // on f d^T (re, im), on f e^T (re, im)
    for (const Slopes::Lag& L : d.lags) {
      const ParameterJet den = speed_ * speed_ + L.sigma * L.sigma * w * w;
      const ParameterJet g_re = L.K * speed_ / den, g_im = -L.K * L.sigma * w / den;
      lag.push_back({-L.K / L.sigma - g_im * w, g_re * w, -g_re * speed_, -g_im * speed_});
    }
    T_.resize(X_.size());
    for (size_t j = 0; j < d.params.size(); ++j) {
      const int q = d.params[j];
      for (int a : d.rows[j]) {
        for (int i = 0; i < inputs; ++i) T_[a + k * i] = 0;
      }
      const auto add = [&](int a, int b, const Complex& v) {  // T = dD X
        for (int i = 0; i < inputs; ++i) T_[a + k * i] += Mul(v, X_[b + k * i]);
      };
      for (const Slopes::Entry& e : d.D[j]) add(e.a, e.b, Complex(e.k - w * w * e.m, w * e.c));
      for (size_t n = 0; n < d.lags.size(); ++n) {
        const auto& [d_re, d_im, e_re, e_im] = lag[n];
        for (const Slopes::LagEntry& e : d.lags[n].entries) {
          const auto dv = [&](const ParameterJet& on_d, const ParameterJet& on_e) {
            return Slope(on_d, q) * e.fd.a + on_d.a * Slope(e.fd, q) + Slope(on_e, q) * e.fe.a +
                   on_e.a * Slope(e.fe, q);
          };
          const Complex v(dv(d_re, e_re), dv(d_im, e_im));
          if (v != Complex(0)) add(e.a, e.b, v);
        }
      }
      for (size_t f = 0; f < request.pairs.size(); ++f) {
        const auto [o, i] = request.pairs[f];
        const Complex* y = Y_.data() + static_cast<size_t>(o) * k;
        Complex h = 0;
        for (int a : d.rows[j]) h -= Mul(y[a], T_[a + k * i]);
        for (const Slopes::Row& g : d.G[j]) {
          if (g.output == o) h += Mul(Complex(g.displacement, w * g.velocity), X_[g.a + k * i]);
        }
        for (const Slopes::Force& b : d.B[j]) {
          if (b.input == i) h += y[b.a] * b.value;
        }
        r->dH(static_cast<Eigen::Index>(f) * lines + l, static_cast<Eigen::Index>(j)) = h;
      }
    }
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
    std::vector<Complex> lu;  // with derivatives: the line's LU (row-major) and pivots
    std::vector<int> pivot;
  };
  // An output's row of G: its nonzero coefficients (Term::x the active row).
  struct Output {
    bool channel;
    int order;
    std::vector<Term> terms;
  };

  void OutputRows(const MechanicalSystem& s, const ResponseRequest& request) {
    const int k = on_.size();
    const auto G_d = s.axle_displacement();
    const auto G_v = s.axle_velocity();
    for (const ResponseOutput& out : request.outputs) {
      Output row{out.channel.has_value(), out.order, {}};
      for (int a = 0; a < k; ++a) {
        double c = 0, v = 0;
        if (out.channel) {
          c = G_d(static_cast<int>(*out.channel), on_.dofs[a]);
          v = G_v(static_cast<int>(*out.channel), on_.dofs[a]);
        } else {
          for (const auto& [dof, coef] : out.coordinates) c += on_[dof] == a ? coef : 0;
        }
        if (c != 0 || v != 0) row.terms.push_back({a, c, v});
      }
      outputs_.push_back(std::move(row));
    }
    Y_.assign(outputs_.size() * k, Complex(0));
    for (Block& b : blocks_) {
      b.lu.resize(b.rows.size() * b.rows.size());
      b.pivot.resize(b.rows.size());
    }
  }

  // Row o of Y = G D^-1 at w: each block's D^T y = g, by its LU (P D = L U:
  // U^T s = g, L^T t = s, y = P^T t).
  void OutputRow(int o, double w) {
    const int k = on_.size();
    const Output& out = outputs_[o];
    Complex factor = 1;  // (i w)^order
    for (int n = 0; !out.channel && n < out.order; ++n) factor = Complex(-w * factor.imag(), w * factor.real());
    Complex* y = Y_.data() + static_cast<size_t>(o) * k;
    std::fill(y, y + k, Complex(0));
    for (const Term& t : out.terms) {
      y[t.x] = out.channel ? Complex(t.displacement, w * t.velocity) : t.displacement * factor;
    }
    for (const Block& b : blocks_) {
      const int m = static_cast<int>(b.rows.size());
      Complex v[kNumDofs];
      bool reads = false;
      for (int x = 0; x < m; ++x) reads |= (v[x] = y[b.rows[x]]) != Complex(0);
      if (!reads) continue;
      const Complex* A = b.lu.data();
      for (int c = 0; c < m; ++c) {
        for (int x = 0; x < c; ++x) v[c] -= Mul(A[x * m + c], v[x]);
        v[c] = Mul(v[c], A[c * m + c]);
      }
      for (int c = m - 1; c >= 0; --c) {
        for (int x = c + 1; x < m; ++x) v[c] -= Mul(A[x * m + c], v[x]);
      }
      for (int c = m - 1; c >= 0; --c) std::swap(v[c], v[b.pivot[c]]);
      for (int x = 0; x < m; ++x) y[b.rows[x]] = v[x];
    }
  }

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
  bool Solve(Block& b, double w) {
    switch (b.rows.size()) {
      case 1: { Complex A[1][1], v[1]; return Solve<1>(b, w, A, v); }
      case 2: { Complex A[2][2], v[2]; return Solve<2>(b, w, A, v); }
      case 3: { Complex A[3][3], v[3]; return Solve<3>(b, w, A, v); }
      case 4: { Complex A[4][4], v[4]; return Solve<4>(b, w, A, v); }
      default: return Solve<0>(b, w, A_, v_);
    }
  }
  template <int kSize, class Square, class Column>  // kSize 0: b's
  bool Solve(Block& b, double w, Square& A, Column& v) {
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
    for (int x = 0; keep_ && x < m; ++x) {
      b.pivot[x] = pivot[x];
      for (int y = 0; y < m; ++y) b.lu[x * m + y] = A[x][y];
    }
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
  const bool keep_;  // the LU, for derivatives
  std::vector<Block> blocks_;
  std::vector<Output> outputs_;
  std::vector<Complex> Y_, T_;  // G D^-1 (row-major, outputs x k); dD X as X
  std::vector<Function> functions_;
  std::vector<Term> terms_;
  // D^-1 B over the active rows (column-major), zero where an input misses a block.
  std::vector<Complex> X_;
  // A block's LU and a right-hand side: members, as std::complex zeroes the
  // arrays it constructs.
  Complex A_[kNumDofs][kNumDofs], v_[kNumDofs];
};

void Respond(const MechanicalSystem& s, const Parameters& p, const ResponseRequest& request,
             const Slopes* slopes, ResponseResult* out) {
  ResponseResult& r = *out;
  const int lines = static_cast<int>(request.frequencies_hz.size());
  const int functions = static_cast<int>(request.pairs.size());
  r.H.resize(lines, functions);
  r.dH.resize(slopes ? static_cast<Eigen::Index>(functions) * lines : 0,
              slopes ? static_cast<Eigen::Index>(slopes->params.size()) : 0);
  Lines solver(s, p, request, slopes != nullptr);
  for (int l = 0; l < lines; ++l) {
    const double w = 2 * M_PI * request.frequencies_hz[l];
    if (!solver.At(w, l, &r)) {
      r.error = "the dynamic stiffness is singular at " +
                std::to_string(request.frequencies_hz[l]) + " Hz (an undamped resonance)";
      return;
    }
    if (slopes) solver.Derive(w, l, *slopes, request, &r);
  }
  if (!r.H.allFinite()) {
    r.error = "the response is not finite";
    return;
  }
  if (!r.dH.allFinite()) {
    r.error = "the response's derivatives are not finite";
    return;
  }
  r.ok = true;
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
  FrequencyResponse(model, p, speed_m_s, request, params, &r);
  return r;
}

void FrequencyResponse(const ModalModel& model, const Parameters& p, double speed_m_s,
                       const ResponseRequest& request, const std::vector<int>* params,
                       ResponseResult* out) {
  ResponseResult& r = *out;
  r.ok = false;
  r.error.clear();
  if (!(speed_m_s >= 0) || !std::isfinite(speed_m_s)) {
    r.error = "the speed must be finite and not negative";
    return;
  }
  for (double hz : request.frequencies_hz) {
    if (!(hz > 0) || !std::isfinite(hz)) {
      r.error = "every frequency must be positive";
      return;
    }
  }
  for (Param q : model.parameters()) {
    if (!std::isfinite(p[q])) {
      r.error = std::string("parameter ") + ParamName(q) + " is not finite";
      return;
    }
  }
  const MechanicalSystem s = model.Assemble(p, speed_m_s);
  for (const ResponseInput& in : request.inputs) {
    if (auto d = Missing(s, in.coordinates, in.on_rim)) {
      r.error = std::string("an input acts on ") + DofName(*d) + ", which the model lacks";
      return;
    }
  }
  for (const ResponseOutput& out : request.outputs) {
    if (auto d = Missing(s, out.coordinates, out.on_rim)) {
      r.error = std::string("an output reads ") + DofName(*d) + ", which the model lacks";
      return;
    }
  }
  if (!params) return Respond(s, p, request, nullptr, &r);
  const ParameterArray<ParameterJet> jets = Seeded(p);
  const Slopes slopes(model.Assemble(jets, speed_m_s), jets, request, Active(s), *params);
  Respond(s, p, request, &slopes, &r);
}

}  // namespace ringid
