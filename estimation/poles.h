// The poles of measured FRFs alone: no tire model, no labels. pLSCF's
// stabilisation diagram chooses the physical poles and the maximum-likelihood
// refinement gives their standard errors (estimation/plscf.h), with what a
// raw file needs around them:
// - the model order the data need: pLSCF from orders 1 to 30, the highest
//   order doubled while that finds more physical poles (without the
//   refinement), the noise estimated and the poles refined at the last;
// - more references than responses (a roving hammer): the transpose fitted,
//   H^T = B' A'^-1 (reciprocity, Maxwell-Betti), so that the denominator is
//   over the responses; the poles are the same and the shape is over the
//   references;
// - no sigma for some function: the noise from the fit's residuals. Each
//   line's sigma is taken as contract §9's shape, |H| with the floor of
//   kFrfSigmaFloor of the function's peak (a sensor's noise and leakage grow
//   with the response), times a factor per function: a_f^2 = sum over its
//   lines of |r / shape|^2 / (2 lines) x values / degrees of freedom (at
//   least a thousandth of the largest a_f), from the extraction weighted by
//   the shape alone; then the extraction again with sigma = a_f shape.
#ifndef RINGID_ESTIMATION_POLES_H_
#define RINGID_ESTIMATION_POLES_H_

#include <limits>
#include <string>

#include "datasets/frf.h"
#include "estimation/plscf.h"
#include "estimation/status.h"

namespace ringid {

struct PolesOptions {
  double band_low_hz = 0;
  double band_high_hz = std::numeric_limits<double>::infinity();

  bool IsValid(std::string* why) const;
};

// The fewest lines in the band (the orders up to 6: a pole is physical at 5
// stable orders).
inline constexpr int kMinPoleLines = 7;

struct FoundPoles {
  Status status;
  // The functions as fitted: the given Frf, or its transpose where it has
  // more inputs than outputs; sigma the estimate where it was not given.
  Frf fitted;
  bool transposed = false;
  bool noise_from_residuals = false;
  int max_order = 0;
  PlscfResult plscf;  // of `fitted`
};

// The physical poles of `frf` in the band, their standard errors and
// residues. Invalid input: bad options, fewer than kMinPoleLines lines in the
// band.
void FindPoles(const Frf& frf, const PolesOptions& options, FoundPoles* out);

}  // namespace ringid

#endif  // RINGID_ESTIMATION_POLES_H_
