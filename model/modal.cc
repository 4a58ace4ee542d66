#include "model/modal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>

#include "model/assignment.h"

namespace ringid {

using internal::AssignMaxScore;

namespace {

constexpr int kMaxLags = 2;
constexpr int kMaxState = 2 * kNumDofs + kMaxLags;
// Real matrices on the stack (Eigen leaves them uninitialised); complex ones
// on the heap, since std::complex zero-initialises a fixed-size array.
using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxState,
                          kMaxState>;
using CMat = Eigen::MatrixXcd;
using CVec = Eigen::VectorXcd;
// Over the degrees of freedom of one block: small enough to zero-initialise.
using DofVec = Eigen::Matrix<std::complex<double>, Eigen::Dynamic, 1, 0, kNumDofs, 1>;

// |z| without std::abs's guard against overflow (hypot): the moduli here
// (eigenvalues, strain energies) are far from it.
double Modulus(const std::complex<double>& z) { return std::sqrt(std::norm(z)); }

int Root(std::array<int, kNumDofs>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// w^T K_block v over the degrees of freedom `dofs`.
std::complex<double> Bilinear(const DofVec& w, const MechanicalSystem::Matrix& K,
                const std::vector<int>& dofs, const DofVec& v) {
  std::complex<double> sum = 0;
  const int k = static_cast<int>(dofs.size());
  for (int a = 0; a < k; ++a) {
    for (int b = 0; b < k; ++b) {
      const double kab = K(dofs[a], dofs[b]);
      if (kab != 0) sum += w[a] * (kab * v[b]);  // a label's stiffness is sparse
    }
  }
  return sum;
}

int Index(const std::vector<int>& dofs, Dof d) {
  const auto it = std::find(dofs.begin(), dofs.end(), static_cast<int>(d));
  return it == dofs.end() ? -1 : static_cast<int>(it - dofs.begin());
}

// The lags whose force acts on the block, by index into s.lags(); only at
// speed are they states.
template <class T>
std::vector<int> BlockLags(const BasicSystem<T>& s, const std::vector<int>& dofs) {
  std::vector<int> lags;
  if (!(s.speed() > 0)) return lags;
  for (int i = 0; i < static_cast<int>(s.lags().size()); ++i) {
    for (const auto& [dof, f] : s.lags()[i].force) {
      if (Index(dofs, dof) >= 0) {
        lags.push_back(i);
        break;
      }
    }
  }
  return lags;
}

double Value(double v) { return v; }
double Value(const ParameterJet& v) { return v.a; }

// On the stack for double; a matrix of jets is too large for it.
template <class T>
struct MatrixOf {
  using type = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxState, kMaxState>;
};
template <>
struct MatrixOf<ParameterJet> {
  using type = Eigen::Matrix<ParameterJet, Eigen::Dynamic, Eigen::Dynamic>;
};
template <class T>
using MatOf = typename MatrixOf<T>::type;

// Eq. (13): A = [[0, I], [-M^-1 K, -M^-1 C]] over the block; rolling,
// docs/rolling.md eq. (R8) appends the slip states zeta, whose force
// replaces the standing stiffness (K / sigma) f d^T that K holds. M is
// diagonal by construction (BasicSystem::AddMass). Also returns the balancing
// frequency w (rad/s). Written once for double and ParameterJet (the
// derivatives).
template <class T>
MatOf<T> StateMatrix(const BasicSystem<T>& s, const std::vector<int>& dofs,
                     const std::vector<int>& lags, double* w_out) {
  const int k = static_cast<int>(dofs.size());
  const int m = static_cast<int>(lags.size());
  MatOf<T> K(k, k);
  for (int a = 0; a < k; ++a) {
    for (int b = 0; b < k; ++b) K(a, b) = s.K()(dofs[a], dofs[b]);
  }
  MatOf<T> A = MatOf<T>::Zero(2 * k + m, 2 * k + m);
  MatOf<T> F = MatOf<T>::Zero(k, m);
  for (int j = 0; j < m; ++j) {
    const auto& lag = s.lags()[lags[j]];
    const T v = s.speed() / lag.relaxation_length;
    A(2 * k + j, 2 * k + j) = -v;
    for (const auto& [dof, d] : lag.velocity) {
      const int b = Index(dofs, dof);
      if (b >= 0) A(2 * k + j, k + b) = -d / lag.relaxation_length;
    }
    for (const auto& [dof, e] : lag.heading) {
      const int b = Index(dofs, dof);
      if (b >= 0) A(2 * k + j, b) = v * e;
    }
    for (const auto& [dof, f] : lag.force) {
      const int a = Index(dofs, dof);
      if (a < 0) continue;
      F(a, j) = f * lag.stiffness;
      for (const auto& [dof_b, d] : lag.velocity) {
        const int b = Index(dofs, dof_b);
        if (b >= 0) K(a, b) -= lag.stiffness / lag.relaxation_length * f * d;
      }
    }
  }
  // Balanced: the velocities in units of a typical angular frequency w, a
  // power of two (no rounding), so that A's blocks are of one size. Eigen's
  // solver does not balance, and unbalanced (entries 1 to 1e6) it loses
  // about 3e-10 in frequency against LAPACK. A similarity: eigenvalues and
  // the displacement rows of eigenvectors are unchanged (docs/model.md §8).
  double w2 = 0;
  for (int a = 0; a < k; ++a) w2 = std::max(w2, Value(K(a, a)) / Value(s.M()(dofs[a], dofs[a])));
  const double w = BalancingFrequency(w2);
  for (int j = 0; j < m; ++j) {
    for (int b = 0; b < k; ++b) A(2 * k + j, k + b) *= T(w);
  }
  for (int a = 0; a < k; ++a) {
    const T inverse_mass = T(1) / s.M()(dofs[a], dofs[a]);
    A(a, k + a) = T(w);
    for (int b = 0; b < k; ++b) {
      A(k + a, b) = -K(a, b) * inverse_mass / T(w);
      A(k + a, k + b) = -s.C()(dofs[a], dofs[b]) * inverse_mass;
    }
    for (int j = 0; j < m; ++j) A(k + a, 2 * k + j) = F(a, j) * inverse_mass / T(w);
  }
  *w_out = w;
  return A;
}

// A null vector of B = lambda^2 M + lambda C + K over the block, of rank
// k - 1 at an eigenvalue: left (w^T B = 0) or right (B v = 0). Up to 3 x 3
// the largest row or column of the adjugate ((adj B) B = B adj B = det B I =
// 0), else the singular vector with the least singular value. Empty where
// the adjugate vanishes (rank k - 2: a repeated eigenvalue).
DofVec NullVector(const MechanicalSystem& s, const std::vector<int>& dofs,
                  const std::complex<double>& lambda, bool left) {
  const int k = static_cast<int>(dofs.size());
  const std::complex<double> lambda2 = lambda * lambda;
  const double abs_lambda = Modulus(lambda), abs_lambda2 = std::norm(lambda);
  const auto B = [&](int a, int b) {
    const int i = left ? dofs[a] : dofs[b], j = left ? dofs[b] : dofs[a];
    const double m = s.M()(i, j), c = s.C()(i, j), kk = s.K()(i, j);
    return std::complex<double>(lambda2.real() * m + lambda.real() * c + kk,
                                lambda2.imag() * m + lambda.imag() * c);
  };  // B^T for the right vector: B v = 0 is v^T B^T = 0
  DofVec w(k);
  if (k == 1) {
    w[0] = 1;
    return w;
  }
  if (k <= 3) {
    std::complex<double> b[3][3];
    double size = 0;  // of the pencil's terms, entry by entry
    for (int i = 0; i < k; ++i) {
      for (int j = 0; j < k; ++j) {
        b[i][j] = B(i, j);
        const int r = dofs[i], c = dofs[j];
        size += abs_lambda2 * std::abs(s.M()(r, c)) + abs_lambda * std::abs(s.C()(r, c)) +
                std::abs(s.K()(r, c));
      }
    }
    double largest = -1;
    if (k == 2) {
      const bool first = std::norm(b[1][1]) + std::norm(b[0][1]) >= std::norm(b[1][0]) + std::norm(b[0][0]);
      w[0] = first ? b[1][1] : -b[1][0];
      w[1] = first ? -b[0][1] : b[0][0];
      largest = w.squaredNorm();
    } else {
      // w^T b = 0: w is the cross product of two columns of b.
      for (int i = 0; i < 3; ++i) {
        const int p = (i + 1) % 3, q = (i + 2) % 3;
        const std::complex<double> c0 = b[1][p] * b[2][q] - b[2][p] * b[1][q];
        const std::complex<double> c1 = b[2][p] * b[0][q] - b[0][p] * b[2][q];
        const std::complex<double> c2 = b[0][p] * b[1][q] - b[1][p] * b[0][q];
        const double norm = std::norm(c0) + std::norm(c1) + std::norm(c2);
        if (norm > largest) {
          largest = norm;
          w[0] = c0, w[1] = c1, w[2] = c2;
        }
      }
    }
    // A cofactor is a minor of order k - 1; where all are rounding, so is w.
    const double floor = 1e-10 * (k == 2 ? size : size * size);
    return largest > floor * floor ? w : DofVec();
  }
  CMat b(k, k);
  for (int i = 0; i < k; ++i) {
    for (int j = 0; j < k; ++j) b(i, j) = B(i, j);
  }
  const Eigen::JacobiSVD<CMat> svd(b.transpose(), Eigen::ComputeFullV);
  w = svd.matrixV().col(k - 1);
  return w;
}

// The derivatives of every oscillating mode of the block (docs/model.md
// §15), from the eigen-decomposition A V = V diag(lambda), Y = V^-1, and
// A's derivatives in `dA`. False where two eigenvalues coincide.
bool AddDerivatives(const MatOf<ParameterJet>& dA, const CVec& lambda, const CMat& V,
                    const CMat& Y, const std::vector<int>& dofs, const std::vector<int>& columns,
                    std::vector<Mode>* modes, std::string* why) {
  const int n = static_cast<int>(lambda.size());
  const int k = static_cast<int>(dofs.size());
  // dA is sparse: each parameter moves a few entries of A.
  struct Entry {
    int row, col;
    double value;
  };
  std::vector<std::pair<int, std::vector<Entry>>> partials;  // (parameter, its entries)
  for (int p = 0; p < kNumParams; ++p) {
    std::vector<Entry> entries;
    for (int a = 0; a < n; ++a) {
      for (int b = 0; b < n; ++b) {
        if (dA(a, b).v[p] != 0) entries.push_back({a, b, dA(a, b).v[p]});
      }
    }
    if (!entries.empty()) partials.emplace_back(p, std::move(entries));
  }
  for (size_t c = 0; c < columns.size(); ++c) {
    const int j = columns[c];
    Mode& mode = (*modes)[c];
    for (int o = 0; o < n; ++o) {
      if (o != j && std::abs(lambda[o] - lambda[j]) <= 1e-8 * std::abs(lambda[j])) {
        *why = std::string("two eigenvalues coincide at ") + std::to_string(mode.frequency_hz) +
               " Hz, where the mode shapes have no derivative";
        return false;
      }
    }
    auto d = std::make_shared<ModeDerivatives>();
    d->eigenvalue.setZero();
    d->shape.setZero();
    const CVec v = V.col(j);
    int big = 0;
    for (int a = 1; a < k; ++a) {
      if (std::norm(v[a]) > std::norm(v[big])) big = a;
    }
    CVec inverse_gap(n);
    for (int o = 0; o < n; ++o) inverse_gap[o] = o == j ? 0.0 : 1.0 / (lambda[j] - lambda[o]);
    // Column q of R is dA_q v, of G = Y R: G_jq = d lambda, G_oq / (lambda_j -
    // lambda_o) the share of v_o in d v.
    const int np = static_cast<int>(partials.size());
    CMat R = CMat::Zero(n, np);
    for (int q = 0; q < np; ++q) {
      for (const Entry& e : partials[q].second) R(e.row, q) += e.value * v[e.col];
    }
    const CMat G = Y * R;
    const CMat dV = V.topRows(k) * (inverse_gap.asDiagonal() * G);
    // shape = v / v_big: d shape = (dv - shape dv_big) / v_big.
    const std::complex<double> inverse_big = 1.0 / v[big];
    for (int q = 0; q < np; ++q) {
      const int p = partials[q].first;
      d->eigenvalue[p] = G(j, q);
      for (int a = 0; a < k; ++a) {
        d->shape(dofs[a], p) = (dV(a, q) - v[a] * inverse_big * dV(big, q)) * inverse_big;
      }
    }
    mode.derivatives = std::move(d);
  }
  return true;
}

using RootVec = Eigen::Matrix<std::complex<double>, Eigen::Dynamic, 1, 0, kMaxState, 1>;

// Whether root j opens a pair u +- i v (v > 0, the first), whose eigenvectors
// are P_j +- i P_j+1; a pair whose v is rounding is two real roots
// (EigenSolver::pseudoEigenvalueMatrix).
bool IsPair(const RootVec& ev, int j) {
  const int n = static_cast<int>(ev.size());
  return j + 1 < n &&
         !(std::abs(ev[j].imag()) <= 2 * std::numeric_limits<double>::epsilon() * std::abs(ev[j].real()));
}

// The roots of the block's state matrix A (eq. 13), into `ev` (of A's size).
// Standing, one degree of freedom without vectors: m lambda^2 + c lambda + k
// = 0 in closed form, Eigen's order (the root with Im > 0 first); real roots
// without cancellation. Else Eigen's, in `es` with the vectors unless
// `values_only`. False, with `error`, where the solver does not converge.
bool Roots(const MechanicalSystem& s, const std::vector<int>& dofs, const Mat& A,
           bool values_only, Eigen::EigenSolver<Mat>* es, RootVec* ev, std::string* error) {
  if (values_only && dofs.size() == 1) {
    const int d = dofs[0];
    const double mass = s.M()(d, d), c = s.C()(d, d), kk = s.K()(d, d);
    const double disc = c * c - 4 * mass * kk;
    if (disc < 0) {
      const double re = -c / (2 * mass), im = std::sqrt(-disc) / (2 * mass);
      *ev << std::complex<double>(re, im), std::complex<double>(re, -im);
    } else {
      const double q = -0.5 * (c + std::copysign(std::sqrt(disc), c));
      *ev << q / mass, q != 0 ? kk / q : 0.0;
    }
    return true;
  }
  es->compute(A, /*computeEigenvectors=*/!values_only);
  if (es->info() != Eigen::Success) {
    *error = "eigen-solution did not converge";
    return false;
  }
  *ev = es->eigenvalues();
  return true;
}

// The eigenvectors V of the state matrix from its pseudo-eigenvectors P, their
// eigenvalues `lambda` (a real root's rounding imaginary part dropped), and
// the left eigenvectors, the rows of Y = V^-1. False where V is singular.
bool LeftVectors(const RootVec& ev, const Mat& P, CVec* lambda, CMat* V, CMat* Y) {
  const int n = static_cast<int>(ev.size());
  *lambda = ev;
  V->resize(n, n);
  for (int j = 0; j < n; ++j) {
    if (IsPair(ev, j)) {
      const std::complex<double> i(0, 1);
      V->col(j) = P.col(j) + i * P.col(j + 1);
      V->col(j + 1) = P.col(j) - i * P.col(j + 1);
      ++j;
    } else {
      (*lambda)[j] = ev[j].real();
      V->col(j) = P.col(j);
    }
  }
  *Y = Eigen::PartialPivLU<CMat>(*V).inverse();
  return Y->allFinite();
}

// The labels whose element lies in the block (LabelHome), in catalogue order.
std::vector<ModeLabel> BlockLabels(const std::vector<int>& dofs) {
  std::vector<ModeLabel> labels;
  labels.reserve(dofs.size());
  for (int l = 0; l < kNumLabels; ++l) {
    const auto label = static_cast<ModeLabel>(l);
    const int home = static_cast<int>(LabelHome(label));
    if (std::find(dofs.begin(), dofs.end(), home) != dofs.end()) {
      labels.push_back(label);
    }
  }
  return labels;
}

// Whether M, C and K are symmetric over the block: left and right vectors of
// lambda^2 M + lambda C + K then coincide.
bool Symmetric(const MechanicalSystem& s, const std::vector<int>& dofs) {
  const int k = static_cast<int>(dofs.size());
  bool symmetric = true;
  for (int a = 0; a < k && symmetric; ++a) {
    for (int b = 0; b < a && symmetric; ++b) {
      const int i = dofs[a], j = dofs[b];
      symmetric = s.M()(i, j) == s.M()(j, i) && s.C()(i, j) == s.C()(j, i) &&
                  s.K()(i, j) == s.K()(j, i);
    }
  }
  return symmetric;
}

// What the modes of one block are made from (SolveBlock).
struct Block {
  const MechanicalSystem& s;
  const std::vector<int>& dofs;
  int m;             // slip lags in the state vector
  bool values_only;  // the roots alone: each mode's vectors are null vectors
  const Mat& P;      // the pseudo-eigenvectors, unless values_only
  bool have_left;    // Y holds the left eigenvectors
  const CMat& Y;
  bool symmetric;
  const std::vector<ModeLabel>& labels;
};

// The mode of the oscillating root `lam`, root j of the state matrix and
// column `col` of its eigenvector in V: its displacements v, the left vector
// w, the shares of strain energy |w^T K_label v| (docs/model.md §9) and the
// shape v / v_big. False where the null vector v is not defined (a repeated
// eigenvalue; only where values_only).
bool ModeFromRoot(const Block& b, const std::complex<double>& lam, int j, int col, Mode* mode) {
  const MechanicalSystem& s = b.s;
  const std::vector<int>& dofs = b.dofs;
  const int k = static_cast<int>(dofs.size());
  const double modulus = Modulus(lam);
  mode->eigenvalue = lam;
  mode->frequency_hz = lam.imag() / (2 * M_PI);
  mode->damping_ratio = -lam.real() / modulus;
  DofVec v(k);
  if (b.values_only) {
    v = NullVector(s, dofs, lam, /*left=*/false);
    if (v.size() == 0) return false;
  } else {
    const double sign = col == j ? 1 : -1;
    for (int a = 0; a < k; ++a) v[a] = {b.P(a, j), sign * b.P(a, j + 1)};
  }
  // w^T (lambda^2 M + lambda C + K) = 0 (docs/model.md section 9): at
  // standstill v if symmetric, else the left null vector; at speed, or
  // where that is not defined (a repeated eigenvalue), w = M^-T y2 from
  // the left eigenvector y of the state matrix.
  DofVec w_left;
  if (b.m == 0) w_left = b.symmetric ? v : NullVector(s, dofs, lam, /*left=*/true);
  if (w_left.size() == 0 && b.have_left) {
    w_left.resize(k);
    for (int a = 0; a < k; ++a) w_left[a] = b.Y(col, k + a) / s.M()(dofs[a], dofs[a]);
  } else if (w_left.size() == 0) {
    w_left = b.m > 0 ? DofVec(v.conjugate()) : v;
  }
  mode->energy.fill(0);
  // Unlabelled couplings (k_xy) count in the total, not for any label.
  std::complex<double> rest = Bilinear(w_left, s.K(), dofs, v);
  double total = 0;
  for (ModeLabel l : b.labels) {
    const std::complex<double> e = Bilinear(w_left, s.K_label(l), dofs, v);
    mode->energy[static_cast<int>(l)] = Modulus(e);
    total += Modulus(e);
    rest -= e;
  }
  total += Modulus(rest);
  if (!(total > 0) || !std::isfinite(total)) total = 1;
  for (double& e : mode->energy) e /= total;
  int big = 0;
  for (int a = 1; a < k; ++a) {
    if (std::norm(v[a]) > std::norm(v[big])) big = a;
  }
  const std::complex<double> inverse_pivot = 1.0 / v[big];
  mode->shape.setZero();
  for (int a = 0; a < k; ++a) mode->shape[dofs[a]] = v[a] * inverse_pivot;
  return true;
}

// The derivatives of the block's modes (AddDerivatives, from A's derivatives
// in `jets`), where the left eigenvectors exist; else why not, in
// out->derivatives_undefined, and none.
void BlockDerivatives(const BasicSystem<ParameterJet>& jets, const std::vector<int>& dofs,
                      bool have_left, const CVec& lambda, const CMat& V, const CMat& Y,
                      const std::vector<int>& columns, std::vector<Mode>* modes,
                      ModalSolution* out) {
  if (have_left && out->derivatives_undefined.empty()) {
    double same_w;
    const MatOf<ParameterJet> dA = StateMatrix(jets, dofs, BlockLags(jets, dofs), &same_w);
    if (!AddDerivatives(dA, lambda, V, Y, dofs, columns, modes, &out->derivatives_undefined)) {
      for (Mode& mode : *modes) mode.derivatives.reset();
    }
  } else if (!have_left) {
    out->derivatives_undefined = "the eigenvectors of a block are not independent";
  }
}

// One-to-one labels: maximise the product of energy shares. The modes are
// appended to out->modes, labels left without a mode to out->vanished. False
// where a mode gets no label.
bool AssignLabels(std::vector<Mode>* modes, const std::vector<ModeLabel>& labels,
                  ModalSolution* out) {
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kNumLabels, kNumLabels> score(
      modes->size(), labels.size());
  for (size_t i = 0; i < modes->size(); ++i) {
    for (size_t l = 0; l < labels.size(); ++l) {
      const double e = (*modes)[i].energy[static_cast<int>(labels[l])];
      score(i, l) = std::log(std::max(e, 1e-300));
    }
  }
  const std::vector<int> pick = AssignMaxScore(score);
  std::array<bool, kNumLabels> used{};
  for (size_t i = 0; i < modes->size(); ++i) {
    if (pick[i] < 0) {
      out->error = "could not label the modes of a block";
      return false;
    }
    (*modes)[i].label = labels[pick[i]];
    used[pick[i]] = true;
    out->modes.push_back(std::move((*modes)[i]));
  }
  for (size_t l = 0; l < labels.size(); ++l) {
    if (!used[l]) out->vanished.push_back(labels[l]);
  }
  return true;
}

// Solves one block of coupled degrees of freedom and appends its modes: the
// roots, the left vectors where needed, a mode from each oscillating root
// (the others are real roots), their derivatives and labels.
bool SolveBlock(const MechanicalSystem& s, const BasicSystem<ParameterJet>* jets,
                const std::vector<int>& dofs, ModalSolution* out,
                bool vectors_from_solver = false) {
  const int k = static_cast<int>(dofs.size());
  const std::vector<int> lags = BlockLags(s, dofs);
  const int m = static_cast<int>(lags.size());
  if (m > kMaxLags) {
    out->error = "more slip lags than the state vector holds";
    return false;
  }
  double w = 1;
  const Mat A = StateMatrix(s, dofs, lags, &w);
  if (!A.allFinite()) {
    out->error = "state matrix is not finite";
    return false;
  }
  // Standing, without derivatives, up to three degrees of freedom (the
  // paper's blocks): the eigenvalues alone, and each mode's displacements
  // the null vector of its pencil (docs/model.md §8), cheaper than Eigen's
  // eigenvectors; where the null vector is not defined, Eigen's.
  const bool values_only = !jets && m == 0 && k <= 3 && !vectors_from_solver;
  const int n = 2 * k + m;
  // A P = P D (EigenSolver::pseudoEigenvectors).
  Eigen::EigenSolver<Mat> es;
  RootVec ev(n);
  if (!Roots(s, dofs, A, values_only, &es, &ev, &out->error)) return false;
  static const Mat kNone;
  const Mat& P = values_only ? kNone : es.pseudoEigenvectors();
  if (!ev.allFinite() || !P.allFinite()) {
    out->error = "eigen-solution is not finite";
    return false;
  }
  // Left eigenvectors (rows of V^-1) where the modes need them: at speed,
  // for the energy shares, for derivatives, and at a repeated eigenvalue.
  CVec lambda;
  CMat V, Y;
  bool have_left = false;
  if (jets || m > 0 || vectors_from_solver) have_left = LeftVectors(ev, P, &lambda, &V, &Y);
  const std::vector<ModeLabel> labels = BlockLabels(dofs);
  const Block block{s, dofs, m, values_only, P, have_left, Y, Symmetric(s, dofs), labels};

  std::vector<Mode> modes;
  std::vector<int> columns;  // of each mode in V
  modes.reserve(k + m);
  columns.reserve(k + m);
  const size_t real_roots_before = out->real_roots.size();
  for (int j = 0; j < n; ++j) {
    const bool pair = IsPair(ev, j);
    const std::complex<double> lam(ev[j].real(), pair ? std::abs(ev[j].imag()) : 0.0);
    const double modulus = Modulus(lam);
    const double tiny = 1e-10 * std::max(1.0, modulus);
    // A rigid-body root (a free spin) is a double zero, which rounding
    // splits into a real or an imaginary pair near sqrt(eps) w: zero either way.
    const bool zero = modulus <= 1e-6 * w;
    if (zero || std::abs(lam.imag()) <= tiny) {
      out->real_roots.push_back(zero ? 0.0 : lam.real());
      if (pair) out->real_roots.push_back(zero ? 0.0 : lam.real());
      j += pair;
      continue;
    }
    const int col = ev[j].imag() > 0 ? j : j + 1;  // of v in V
    Mode mode;
    if (!ModeFromRoot(block, lam, j, col, &mode)) {  // a repeated eigenvalue: Eigen's vectors
      out->real_roots.resize(real_roots_before);
      return SolveBlock(s, jets, dofs, out, /*vectors_from_solver=*/true);
    }
    modes.push_back(std::move(mode));
    columns.push_back(col);
    ++j;
  }
  if (jets) BlockDerivatives(*jets, dofs, have_left, lambda, V, Y, columns, &modes, out);
  return AssignLabels(&modes, labels, out);
}

}  // namespace

double BalancingFrequency(double largest_k_over_m) {
  const double x = largest_k_over_m;
  return x > 0 && std::isfinite(x) ? std::exp2(std::round(0.5 * std::log2(x))) : 1;
}

double ModeDerivatives::Frequency(int p) const { return eigenvalue[p].imag() / (2 * M_PI); }

// zeta = -Re(lambda) / |lambda|.
double ModeDerivatives::DampingRatio(const std::complex<double>& lambda, int p) const {
  const std::complex<double> d = eigenvalue[p];
  const double r = std::abs(lambda);
  return -d.real() / r + lambda.real() * (std::conj(lambda) * d).real() / (r * r * r);
}

RealShapeVector Mode::PaperShape() const {
  int big = 0;
  for (int i = 1; i < kNumDofs; ++i) {
    if (std::norm(shape[i]) > std::norm(shape[big])) big = i;
  }
  // dgeev: unit 2-norm over [v; lambda v], largest component real.
  const std::complex<double> largest =
      std::abs(eigenvalue) >= 1 ? eigenvalue * shape[big] : shape[big];
  const double norm =
      std::sqrt(shape.squaredNorm() * (1 + std::norm(eigenvalue)));
  return (shape * (std::conj(largest) / std::abs(largest)) / norm).real();
}

const Mode* ModalSolution::Find(ModeLabel label) const {
  for (const Mode& m : modes) {
    if (m.label == label) return &m;
  }
  return nullptr;
}

ModalSolution SolveModes(const MechanicalSystem& s, const BasicSystem<ParameterJet>* jets) {
  ModalSolution out;
  out.modes.reserve(kNumLabels);
  std::vector<int> active;
  active.reserve(kNumDofs);
  for (int i = 0; i < kNumDofs; ++i) {
    if (s.active(static_cast<Dof>(i))) active.push_back(i);
  }
  for (int a : active) {
    for (int b : active) {
      if (!std::isfinite(s.M()(a, b)) || !std::isfinite(s.C()(a, b)) ||
          !std::isfinite(s.K()(a, b))) {
        out.error = std::string("system matrices are not finite at ") +
                    DofName(static_cast<Dof>(a));
        return out;
      }
    }
    if (!(s.M()(a, a) > 0)) {
      out.error = std::string("mass matrix is singular: no positive mass on ") +
                  DofName(static_cast<Dof>(a));
      return out;
    }
  }
  // Blocks: connected components of the coupling graph of M, C and K.
  std::array<int, kNumDofs> parent;
  std::iota(parent.begin(), parent.end(), 0);
  for (int a : active) {
    for (int b : active) {
      if (a != b && (s.M()(a, b) != 0 || s.C()(a, b) != 0 || s.K()(a, b) != 0)) {
        parent[Root(parent, a)] = Root(parent, b);
      }
    }
  }
  // Rolling, a lag joins every degree of freedom it touches.
  for (const auto& lag : s.speed() > 0 ? s.lags() : std::vector<MechanicalSystem::SlipLag>{}) {
    int first = -1;
    for (const auto* part : {&lag.force, &lag.velocity, &lag.heading}) {
      for (const auto& [dof, c] : *part) {
        const int d = static_cast<int>(dof);
        if (!s.active(dof)) continue;
        if (first < 0) first = d;
        parent[Root(parent, d)] = Root(parent, first);
      }
    }
  }
  for (int r : active) {
    if (Root(parent, r) != r) continue;
    std::vector<int> dofs;
    dofs.reserve(active.size());
    for (int a : active) {
      if (Root(parent, a) == r) dofs.push_back(a);
    }
    if (!SolveBlock(s, jets, dofs, &out)) {
      out.modes.clear();
      out.vanished.clear();
      out.real_roots.clear();
      return out;
    }
  }
  std::sort(out.real_roots.begin(), out.real_roots.end());
  std::sort(out.modes.begin(), out.modes.end(),
            [](const Mode& a, const Mode& b) {
              return a.frequency_hz < b.frequency_hz;
            });
  out.ok = true;
  return out;
}

}  // namespace ringid
