#include "model/modal.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "model/assignment.h"

namespace ringid {

using internal::AssignMaxScore;

namespace {

constexpr int kMaxState = 2 * kNumDofs;
using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxState,
                          kMaxState>;
using CMat = Eigen::Matrix<std::complex<double>, Eigen::Dynamic,
                           Eigen::Dynamic, 0, kMaxState, kMaxState>;
using CVec = Eigen::Matrix<std::complex<double>, Eigen::Dynamic, 1, 0,
                           kMaxState, 1>;

int Root(std::array<int, kNumDofs>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// w^T K_block v over the degrees of freedom `dofs`.
double Bilinear(const CVec& w, const MechanicalSystem::Matrix& K,
                const std::vector<int>& dofs, const CVec& v) {
  std::complex<double> sum = 0;
  const int k = static_cast<int>(dofs.size());
  for (int a = 0; a < k; ++a) {
    for (int b = 0; b < k; ++b) sum += w[a] * K(dofs[a], dofs[b]) * v[b];
  }
  return std::abs(sum);
}

// Solves one block of coupled degrees of freedom and appends its modes.
bool SolveBlock(const MechanicalSystem& s, const std::vector<int>& dofs,
                ModalSolution* out) {
  const int k = static_cast<int>(dofs.size());
  Mat M(k, k), C(k, k), K(k, k);
  for (int a = 0; a < k; ++a) {
    for (int b = 0; b < k; ++b) {
      M(a, b) = s.M()(dofs[a], dofs[b]);
      C(a, b) = s.C()(dofs[a], dofs[b]);
      K(a, b) = s.K()(dofs[a], dofs[b]);
    }
  }
  Eigen::PartialPivLU<Mat> lu(M);
  const Mat Minv = lu.inverse();
  // Eq. (13): A = [[0, I], [-M^-1 K, -M^-1 C]].
  Mat A = Mat::Zero(2 * k, 2 * k);
  A.topRightCorner(k, k).setIdentity();
  A.bottomLeftCorner(k, k) = -Minv * K;
  A.bottomRightCorner(k, k) = -Minv * C;
  if (!A.allFinite()) {
    out->error = "state matrix is not finite";
    return false;
  }
  Eigen::EigenSolver<Mat> es(A, /*computeEigenvectors=*/true);
  if (es.info() != Eigen::Success) {
    out->error = "eigen-solution did not converge";
    return false;
  }
  const CVec lambda = es.eigenvalues();
  const CMat V = es.eigenvectors();
  if (!lambda.allFinite() || !V.allFinite()) {
    out->error = "eigen-solution is not finite";
    return false;
  }
  // Rows of V^-1 are the left eigenvectors, scaled so that Y V = I.
  Eigen::PartialPivLU<CMat> vlu(V);
  const CMat Y = vlu.inverse();
  const bool have_left = Y.allFinite();

  std::vector<ModeLabel> labels;
  for (int l = 0; l < kNumLabels; ++l) {
    const auto label = static_cast<ModeLabel>(l);
    const int home = static_cast<int>(LabelHome(label));
    if (std::find(dofs.begin(), dofs.end(), home) != dofs.end()) {
      labels.push_back(label);
    }
  }

  // Unlabelled couplings (k_xy) count in the total, not for any label.
  MechanicalSystem::Matrix rest = s.K();
  for (ModeLabel l : labels) rest -= s.K_label(l);
  const CMat Minv_T = Minv.transpose().cast<std::complex<double>>();

  std::vector<Mode> modes;
  for (int j = 0; j < 2 * k; ++j) {
    const std::complex<double> lam = lambda[j];
    if (!(lam.imag() > 1e-10 * std::max(1.0, std::abs(lam)))) continue;
    Mode mode;
    mode.eigenvalue = lam;
    mode.frequency_hz = lam.imag() / (2 * M_PI);
    mode.damping_ratio = -lam.real() / std::abs(lam);
    CVec v = V.col(j).head(k);
    // For w^T (lambda^2 M + lambda C + K) = 0: w = M^-T y2 (see docs/model.md
    // section 9).
    CVec w = have_left ? CVec(Minv_T * Y.row(j).tail(k).transpose()) : CVec(v.conjugate());
    mode.energy.fill(0);
    double labelled = 0;
    for (ModeLabel l : labels) {
      const double e = Bilinear(w, s.K_label(l), dofs, v);
      mode.energy[static_cast<int>(l)] = e;
      labelled += e;
    }
    double total = labelled + Bilinear(w, rest, dofs, v);
    if (!(total > 0) || !std::isfinite(total)) total = 1;
    for (double& e : mode.energy) e /= total;
    int big = 0;
    for (int a = 1; a < k; ++a) {
      if (std::abs(v[a]) > std::abs(v[big])) big = a;
    }
    const std::complex<double> pivot = v[big];
    mode.shape.setZero();
    for (int a = 0; a < k; ++a) mode.shape[dofs[a]] = v[a] / pivot;
    modes.push_back(mode);
  }
  // One-to-one labels: maximise the product of energy shares.
  Eigen::MatrixXd score(modes.size(), labels.size());
  for (size_t i = 0; i < modes.size(); ++i) {
    for (size_t l = 0; l < labels.size(); ++l) {
      const double e = modes[i].energy[static_cast<int>(labels[l])];
      score(i, l) = std::log(std::max(e, 1e-300));
    }
  }
  const std::vector<int> pick = AssignMaxScore(score);
  std::vector<bool> used(labels.size(), false);
  for (size_t i = 0; i < modes.size(); ++i) {
    if (pick[i] < 0) {
      out->error = "could not label the modes of a block";
      return false;
    }
    modes[i].label = labels[pick[i]];
    used[pick[i]] = true;
    out->modes.push_back(modes[i]);
  }
  for (size_t l = 0; l < labels.size(); ++l) {
    if (!used[l]) out->vanished.push_back(labels[l]);
  }
  return true;
}

}  // namespace

RealShapeVector Mode::PaperShape() const {
  int big = 0;
  for (int i = 1; i < kNumDofs; ++i) {
    if (std::abs(shape[i]) > std::abs(shape[big])) big = i;
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

ModalSolution SolveModes(const MechanicalSystem& s) {
  ModalSolution out;
  std::vector<int> active;
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
  for (int r : active) {
    if (Root(parent, r) != r) continue;
    std::vector<int> dofs;
    for (int a : active) {
      if (Root(parent, a) == r) dofs.push_back(a);
    }
    if (!SolveBlock(s, dofs, &out)) {
      out.modes.clear();
      out.vanished.clear();
      return out;
    }
  }
  std::sort(out.modes.begin(), out.modes.end(),
            [](const Mode& a, const Mode& b) {
              return a.frequency_hz < b.frequency_hz;
            });
  out.ok = true;
  return out;
}

}  // namespace ringid
