// Least-squares frequency-domain (LSFD) residues (issue 37): with the poles
// held, each measured frequency response function's residues and its lower
// and upper residual terms by linear least squares.
#ifndef RINGID_ESTIMATION_LSFD_H_
#define RINGID_ESTIMATION_LSFD_H_

#include <complex>
#include <vector>

#include "datasets/frf.h"

namespace ringid {

// One function's modal model (contract §8's phasor convention, s = iω):
//   H(ω) = sum_r [R_r / (s - λ_r) + conj(R_r) / (s - conj(λ_r))]
//          + sum_j Q_j / (s - σ_j) + s^q (lower / s² + upper),
// q the output's order of differentiation (0 displacement or an axle
// channel, 1 velocity, 2 acceleration): the lower residual is the modes
// below the band (mass-like), the upper those above (stiffness-like); for
// an accelerance, lower also holds the direct term that its modes' sum
// leaves out. The real poles σ_j < 0 (real residues Q_j) are a rolling
// tire's slip lags (docs/rolling.md §2): first-order, in the band at speed.
struct LsfdFunction {
  int output = 0, input = 0;                   // as the Frf's function
  int order = 0;                               // q above
  std::vector<std::complex<double>> residues;  // R_r, one per pole
  std::vector<double> real_residues;           // Q_j, one per real pole
  double lower = 0, upper = 0;                 // real: H(-ω) = conj(H(ω))

  // The model's H at `hz`, at the poles the residues were fitted with.
  std::complex<double> At(double hz, const std::vector<std::complex<double>>& poles,
                          const std::vector<double>& real_poles = {}) const;
};

// The residues of each function of `frf` (in its order) at `poles` (each
// with Im > 0; its conjugate is implied), fitted over the lines `lines`
// (indices into frf.frequencies_hz; at least as many as 2 poles + 1) with
// each value's real and imaginary part weighted by 1 / sigma where
// `weigh_by_sigma` and the function has a positive sigma at each line used,
// else equally.
std::vector<LsfdFunction> Lsfd(const Frf& frf, const std::vector<int>& lines,
                               const std::vector<std::complex<double>>& poles, bool weigh_by_sigma,
                               const std::vector<double>& real_poles = {});

}  // namespace ringid

#endif  // RINGID_ESTIMATION_LSFD_H_
