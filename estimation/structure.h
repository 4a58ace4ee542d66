// Parameter combinations the model cannot see, whatever the data: directions
// of the free coordinates along which no condition's system changes, from
// the exact derivatives of the system (model/structure.h).
#ifndef RINGID_ESTIMATION_STRUCTURE_H_
#define RINGID_ESTIMATION_STRUCTURE_H_

#include <string>
#include <vector>

#include <Eigen/Core>

#include "estimation/residuals.h"
#include "estimation/setup.h"

namespace ringid::internal {

struct StructuralFreedom {
  // Orthonormal columns spanning the free directions no prior decides.
  Eigen::MatrixXd directions;
  // One readable basis of the same span, each vector with its invariance in
  // words ("only K_cx / sigma_cx enters the model").
  std::vector<Eigen::VectorXd> readable;
  std::vector<std::string> invariances;
  // The invariances coordinate i takes part in, joined; empty if none.
  std::string InvarianceOf(int i) const;
};

// At x. A direction leaves every condition's M, C, K and slip lags unchanged
// up to one factor per condition (which changes no mode), and every lag pole
// unchanged. Rank is decided on row-normalised exact derivatives, where free
// directions have singular values at rounding level (below 1e-9 of the
// largest) and every other one is far above.
StructuralFreedom FindStructuralFreedom(const ModalResiduals& residuals,
                                        const Eigen::VectorXd& x);

}  // namespace ringid::internal

#endif  // RINGID_ESTIMATION_STRUCTURE_H_
