// The maximum-likelihood refinement of modes from FRFs (issue 37, step 2), as
// PolyMAX Plus and MLMM do after the poles' first estimate: a nonlinear least-
// squares fit (Ceres, Levenberg-Marquardt) of LSFD's modal model
// (estimation/lsfd.h) to every function of the Frf over the lines pLSCF used,
// the poles free together with the residues and the residual terms. pLSCF is
// biased on close, damped modes by several of its standard deviations, and
// LSFD holds the poles: neither gives honest standard errors; this fit's
// covariance does.
//
// Weights: each value's real and imaginary part by 1 / sigma when every
// function has one sigma per line (and weigh_by_sigma): chi-square is then
// the likelihood's (about its degrees of freedom where the model holds) and
// the covariance is (J^T J)^-1 as it is. Otherwise all values count equally
// (residuals in H's units) and the covariance is scaled by the residual
// variance, chi-square / degrees of freedom.
//
// Coordinates: per pole log(-Re λ) and log(Im λ) (damping and frequency stay
// positive), per real pole log(-σ); per function Re R_r and Im R_r per pole,
// Q_j per real pole, lower and upper. The
// Jacobian is analytic. The poles' covariance is the whole fit's with the
// residues and residual terms marginalised: the pseudo-inverse of J_p^T (I -
// P_f) J_p summed over the functions (P_f the projection on the span of the
// function's own columns), from the SVD of the projected J_p stacked.
#ifndef RINGID_ESTIMATION_MODAL_REFINE_H_
#define RINGID_ESTIMATION_MODAL_REFINE_H_

#include <cmath>
#include <complex>
#include <vector>

#include "datasets/frf.h"
#include "estimation/lsfd.h"
#include "estimation/status.h"

namespace ringid {

struct RefinedPole {
  std::complex<double> eigenvalue;  // λ, Im > 0
  double frequency_hz = 0;          // damped: Im λ / 2π (contract §2)
  double damping_ratio = 0;         // -Re λ / |λ|
  // Standard errors from the covariance; NaN where the fit does not
  // determine the pole (its coordinates touch the Jacobian's null space).
  double frequency_std_hz = NAN;
  double damping_ratio_std = NAN;
};

// How the fit went.
struct RefinementFit {
  Status status = Status::Failed("not run");
  bool weighted = false;  // by sigma; else the covariance scaled as above
  double chi_square = NAN;  // sum of the squared (weighted) residuals at the end
  int degrees_of_freedom = 0;  // 2 x functions x lines minus the coordinates
  int iterations = 0;
};

struct ModalRefinement {
  RefinementFit fit;
  std::vector<RefinedPole> poles;        // in the order given
  std::vector<double> real_poles;        // σ_j, in the order given
  std::vector<LsfdFunction> functions;  // per function of the Frf, residues per pole
};

// Refines `poles` (Im > 0, Re < 0), `real_poles` (< 0, lsfd.h) and `start`,
// LSFD's functions at them
// (one per function of `frf`, in its order), over `lines` (indices into
// frf.frequencies_hz). Invalid input: no poles, a pole off the open upper-
// left quadrant, `start` not matching or not finite, no degrees of freedom
// left. Failed: Ceres does not converge (100 iterations), or a pole leaves
// the band of the lines.
void RefineModes(const Frf& frf, const std::vector<int>& lines,
                 const std::vector<std::complex<double>>& poles,
                 const std::vector<double>& real_poles, const std::vector<LsfdFunction>& start,
                 bool weigh_by_sigma, ModalRefinement* out);

}  // namespace ringid

#endif  // RINGID_ESTIMATION_MODAL_REFINE_H_
