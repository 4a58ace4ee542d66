// Modes from frequency response functions (issue 37, step 1): the
// poly-reference least-squares complex-frequency estimator (pLSCF, PolyMAX:
// Peeters, Van der Auweraer, Guillaume & Leuridan, Shock and Vibration 11
// (2004) 395-409) over a range of model orders, its stabilisation diagram,
// the automatic choice of the physical poles, and their residues by LSFD
// (estimation/lsfd.h); then, by default, the maximum-likelihood refinement of
// poles and residues together (estimation/modal_refine.h) with the poles'
// standard errors.
//
// The model is the right matrix fraction H(ω) = B(ω) A(ω)^-1 of an outputs x
// inputs H, with B's rows and A polynomials of order n in z = exp(-iωΔt),
// Δt = 1 / (2 f_max) (f_max the highest line used), real coefficients, A's
// highest one the identity. Its linearised least-squares problem is reduced
// to the denominator's normal equations, M = sum_o (T_o - S_o^T R_o^-1 S_o);
// the poles are λ = -ln(x) / Δt at the eigenvalues x of A's companion matrix,
// n x inputs of them (half with Im λ > 0), and each one's participation on
// the inputs is the left null vector of A(x).
#ifndef RINGID_ESTIMATION_PLSCF_H_
#define RINGID_ESTIMATION_PLSCF_H_

#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "datasets/frf.h"
#include "estimation/lsfd.h"
#include "estimation/modal_refine.h"
#include "estimation/status.h"

namespace ringid {

struct PlscfOptions {
  // The model orders n fitted, each giving n x inputs poles.
  int min_order = 1;
  int max_order = 30;
  // The lines used: those within [band_low_hz, band_high_hz].
  double band_low_hz = 0;
  double band_high_hz = std::numeric_limits<double>::infinity();
  // Each output's lines weighted by 1 / (the rms over its inputs of sigma)
  // in pLSCF, each value by 1 / sigma in LSFD; else all equally.
  bool weigh_by_sigma = true;
  // A pole is stable against the nearest pole of the order below when its
  // frequency is within `stable_frequency` of it (relative), its damping
  // ratio within `stable_damping` (relative), and the MAC of the two
  // participation vectors at least `stable_mac`.
  double stable_frequency = 0.01;
  double stable_damping = 0.05;
  double stable_mac = 0.98;
  // A physical pole: a cluster of stable poles (within the frequency and
  // damping tolerances of its centre, positive damping, in the band) found
  // at this many orders at least.
  int min_stable_orders = 5;
  // The physical poles and their residues refined together
  // (estimation/modal_refine.h), with standard errors; else pLSCF's poles
  // and LSFD's residues, without.
  bool refine = true;

  bool IsValid(std::string* why) const;
};

// A pole of one order's model.
struct PlscfPole {
  std::complex<double> eigenvalue;  // λ, Im > 0
  double frequency_hz = 0;          // damped: Im λ / 2π (contract §2)
  double damping_ratio = 0;         // -Re λ / |λ|
  // The participation on the inputs: unit norm, its largest component real
  // and positive.
  Eigen::VectorXcd participation;
  // Against the nearest pole (in λ) of the order below; false at the lowest.
  bool stable_frequency = false, stable_damping = false, stable_vector = false;

  bool stable() const { return stable_frequency && stable_damping && stable_vector; }
};

// One line of the stabilisation diagram: the poles of order n, ascending
// frequency.
struct PlscfOrder {
  int order = 0;
  std::vector<PlscfPole> poles;
};

// A physical pole, with its residues.
struct ExtractedMode {
  // λ of the cluster's highest order, or the refinement's where it succeeded.
  std::complex<double> eigenvalue;
  double frequency_hz = 0;          // damped, as PlscfPole's
  double damping_ratio = 0;
  // The refinement's standard errors; NaN without it.
  double frequency_std_hz = NAN;
  double damping_ratio_std = NAN;
  int order = 0;                   // the order λ was taken at
  int stable_orders = 0;           // the number of orders in its cluster
  Eigen::VectorXcd participation;  // inputs, as PlscfPole's
  // LSFD's (or the refinement's) residues, outputs x inputs (NaN where the Frf has no function),
  // of H as measured (an accelerance's are λ² times the receptance's), and
  // the outputs' shape psi: the least-squares fit of psi x participation^T
  // to them, over the functions given.
  Eigen::MatrixXcd residues;
  Eigen::VectorXcd shape;
};

struct PlscfResult {
  Status status;
  std::vector<int> outputs;          // those in the pLSCF fit: measured at every input
  std::vector<int> lines;            // the lines used (indices into frf.frequencies_hz)
  double dt = 0;                     // Δt of the basis (s)
  std::vector<PlscfOrder> diagram;   // min_order..max_order
  std::vector<ExtractedMode> modes;  // ascending frequency
  // Per function of the Frf (its order): LSFD at the modes' eigenvalues, or
  // the refinement's.
  std::vector<LsfdFunction> functions;
  // How the refinement went; where it failed (or was not asked for), the
  // modes are pLSCF's and LSFD's.
  RefinementFit refinement;
};

// pLSCF over every output of `frf` measured at all its inputs (an output
// missing an input joins LSFD only), the stabilisation diagram, the physical
// poles and their residues. Invalid input: bad options, fewer lines in the
// band than the highest order needs, no output measured at every input.
void ExtractModes(const Frf& frf, const PlscfOptions& options, PlscfResult* result);

}  // namespace ringid

#endif  // RINGID_ESTIMATION_PLSCF_H_
