// LSFD (estimation/lsfd.h): per function, a real linear least-squares
// problem in Re R_r, Im R_r, lower and upper over the real and imaginary
// parts of its lines.
#include "estimation/lsfd.h"

#include <cmath>

#include <Eigen/Dense>

namespace ringid {
namespace {

using Complex = std::complex<double>;

// The complex basis at s = iω: per pole the pair's terms in Re R and Im R,
// per real pole its term, then the lower and the upper residual.
void Basis(Complex s, int order, const std::vector<Complex>& poles,
           const std::vector<double>& real_poles, Eigen::VectorXcd* phi) {
  const int m = static_cast<int>(poles.size()), mr = static_cast<int>(real_poles.size());
  phi->resize(2 * m + mr + 2);
  for (int r = 0; r < m; ++r) {
    const Complex a = 1.0 / (s - poles[r]), b = 1.0 / (s - std::conj(poles[r]));
    (*phi)(2 * r) = a + b;                        // Re R_r
    (*phi)(2 * r + 1) = Complex(0, 1) * (a - b);  // Im R_r
  }
  for (int j = 0; j < mr; ++j) (*phi)(2 * m + j) = 1.0 / (s - real_poles[j]);  // Q_j
  const Complex sq = std::pow(s, order);
  (*phi)(2 * m + mr) = sq / (s * s);
  (*phi)(2 * m + mr + 1) = sq;
}

}  // namespace

Complex LsfdFunction::At(double hz, const std::vector<Complex>& poles,
                         const std::vector<double>& real_poles) const {
  Eigen::VectorXcd phi;
  Basis(Complex(0, 2 * M_PI * hz), order, poles, real_poles, &phi);
  Complex h = lower * phi(phi.size() - 2) + upper * phi(phi.size() - 1);
  for (size_t r = 0; r < residues.size(); ++r) {
    h += residues[r].real() * phi(2 * r) + residues[r].imag() * phi(2 * r + 1);
  }
  for (size_t j = 0; j < real_residues.size(); ++j) h += real_residues[j] * phi(2 * poles.size() + j);
  return h;
}

std::vector<LsfdFunction> Lsfd(const Frf& frf, const std::vector<int>& lines,
                               const std::vector<Complex>& poles, bool weigh_by_sigma,
                               const std::vector<double>& real_poles) {
  const int m = static_cast<int>(poles.size()), mr = static_cast<int>(real_poles.size());
  const int n = 2 * m + mr + 2;
  const int rows = 2 * static_cast<int>(lines.size());
  std::vector<LsfdFunction> out;
  Eigen::MatrixXd A(rows, n);
  Eigen::VectorXd b(rows);
  Eigen::VectorXcd phi;
  for (const FrfFunction& f : frf.functions) {
    LsfdFunction fit;
    fit.output = f.output;
    fit.input = f.input;
    fit.order = static_cast<int>(frf.outputs[f.output].quantity);  // as model/frequency_response
    // Weighted only where every line used has a positive sigma (the public
    // API may pass a zero one; files cannot, contract §9).
    bool weigh = weigh_by_sigma && f.sigma.size() == f.h.size();
    for (size_t k = 0; weigh && k < lines.size(); ++k) weigh = f.sigma[lines[k]] > 0;
    for (size_t k = 0; k < lines.size(); ++k) {
      const int l = lines[k];
      Basis(Complex(0, 2 * M_PI * frf.frequencies_hz[l]), fit.order, poles, real_poles, &phi);
      const double w = weigh ? 1 / f.sigma[l] : 1.0;
      A.row(2 * k) = w * phi.real().transpose();
      A.row(2 * k + 1) = w * phi.imag().transpose();
      b(2 * k) = w * f.h[l].real();
      b(2 * k + 1) = w * f.h[l].imag();
    }
    // Columns to unit norm: the residual terms differ from the modes' by
    // powers of ω.
    const Eigen::VectorXd scale = A.colwise().norm().cwiseMax(1e-300).cwiseInverse();
    const Eigen::VectorXd x =
        scale.asDiagonal() * (A * scale.asDiagonal()).colPivHouseholderQr().solve(b);
    for (int r = 0; r < m; ++r) fit.residues.emplace_back(x(2 * r), x(2 * r + 1));
    for (int j = 0; j < mr; ++j) fit.real_residues.push_back(x(2 * m + j));
    fit.lower = x(2 * m + mr);
    fit.upper = x(2 * m + mr + 1);
    out.push_back(std::move(fit));
  }
  return out;
}

}  // namespace ringid
