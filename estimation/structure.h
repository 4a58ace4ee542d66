// Parameter combinations the model cannot see, whatever the data: directions
// of the free coordinates along which no condition's system changes, from
// the exact derivatives of the system (model/structure.h).
#ifndef RINGID_ESTIMATION_STRUCTURE_H_
#define RINGID_ESTIMATION_STRUCTURE_H_

#include <string>
#include <vector>

#include <Eigen/Core>

#include "estimation/residuals.h"
#include "estimation/uncertainty_result.h"
#include "estimation/setup.h"

namespace ringid::internal {

struct StructuralFreedom {
  // Orthonormal columns spanning the free directions no prior decides.
  Eigen::MatrixXd directions;
  // One readable basis of the same span, each vector with its invariance in
  // words ("only K_cx / sigma_cx enters the model").
  std::vector<Eigen::VectorXd> readable;
  std::vector<std::string> invariances;
  // Every known parameter the model reads (ties to it follow it), as if
  // freed by the same test: the free coordinates with a component in a
  // direction it gains that moves the known one, that direction's part along
  // the coordinates' own free directions removed.
  std::vector<KnownDependence> known_dependence;
  // The invariances coordinate i takes part in, joined; empty if none.
  std::string InvarianceOf(int i) const;
};

// At x. A direction leaves every condition's M, C, K and slip lags unchanged
// up to one factor per condition (which changes no mode), and every lag pole
// unchanged. Rank is decided on row-normalised exact derivatives, where free
// directions have singular values at rounding level (below 1e-9 of the
// largest) and every other one is far above. One set of exact derivatives
// and one small SVD for all of it.
StructuralFreedom FindStructuralFreedom(const ModalResiduals& residuals,
                                        const Eigen::VectorXd& x);

// What the data measure of coordinate i and known q when a direction moves
// coordinate i by vi and q by vq, both in coordinate units (log for positive
// parameters); ratios, products, sums and differences recognised within
// relative `tolerance`.
std::string MeasuredCombination(const ParameterSetup& setup, const Parameters& p, int i, Param q,
                                double vi, double vq, double tolerance);

}  // namespace ringid::internal

#endif  // RINGID_ESTIMATION_STRUCTURE_H_
