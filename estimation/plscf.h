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
//
// The model needs outputs measured at every input it references. A drum's
// layout has none (in-plane channels per in-plane force, out-of-plane per
// lateral force), so the functions are fitted in blocks (PlscfBlock): each
// connected part of the measured pairs, with its outputs measured at all its
// inputs; where a part has none, one block per set of its inputs measured at
// the same outputs. The physical poles of all blocks (one where two blocks
// see the same pole) then go to LSFD and the refinement over every function.
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
  // After the refinement, the poles whose part of the synthesis is below the
  // 1e-3 critical value of chi-square over their coordinates dropped
  // (estimation/plscf_poles.cc); weighted fits only.
  bool drop_insignificant = false;

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
  // Its real poles (λ real, frequency 0): stable in frequency where λ is
  // within stable_frequency of the nearest real pole below (relative).
  std::vector<PlscfPole> real_poles;
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
  // On the inputs, as PlscfPole's: its block's, or where the block lacks
  // inputs, the rank-one fit of its residues.
  Eigen::VectorXcd participation;
  // LSFD's (or the refinement's) residues, outputs x inputs (NaN where the Frf has no function),
  // of H as measured (an accelerance's are λ² times the receptance's), and
  // the outputs' shape psi: the least-squares fit of psi x participation^T
  // to them, over the functions given (0 on an output measured at no input
  // of its participation).
  Eigen::MatrixXcd residues;
  Eigen::VectorXcd shape;
};

// One pLSCF fit: its inputs (the references) and its outputs, each
// measured at all of them (indices into the Frf's), and its diagram.
struct PlscfBlock {
  std::vector<int> inputs, outputs;
  std::vector<PlscfOrder> diagram;  // min_order..max_order
};

struct PlscfResult {
  Status status;
  std::vector<int> lines;            // the lines used (indices into frf.frequencies_hz)
  double dt = 0;                     // Δt of the basis (s)
  std::vector<PlscfBlock> blocks;    // one for a full layout
  std::vector<ExtractedMode> modes;  // ascending frequency
  // The physical real poles σ < 0 (estimation/lsfd.h: a rolling tire's slip
  // lags), stable at min_stable_orders orders with |σ| / 2π below the band's
  // top, ascending |σ|, then any a misfit added (plscf.cc, AddMissedPoles);
  // the refinement's where it succeeded. Each function's real_residues
  // follow this order.
  std::vector<double> real_poles;
  // Per function of the Frf (its order): LSFD at the modes' eigenvalues and
  // the real poles, or the refinement's.
  std::vector<LsfdFunction> functions;
  // How the refinement went; where it failed (or was not asked for), the
  // modes are pLSCF's and LSFD's.
  RefinementFit refinement;
};

// pLSCF over the blocks of `frf` (an output missing one of its block's
// inputs joins LSFD only), their stabilisation diagrams, the physical poles
// and their residues. Invalid input: bad options, fewer lines in the band
// than the highest order needs.
void ExtractModes(const Frf& frf, const PlscfOptions& options, PlscfResult* result);

}  // namespace ringid

#endif  // RINGID_ESTIMATION_PLSCF_H_
