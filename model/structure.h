// What the modes of one condition depend on, with its exact derivatives with
// respect to every parameter (ceres::Jet through the assembly): the basis for
// deciding which parameter combinations the model cannot see at all.
#ifndef RINGID_MODEL_STRUCTURE_H_
#define RINGID_MODEL_STRUCTURE_H_

#include <Eigen/Core>

#include "model/parameters.h"
#include "model/rigid_ring_model.h"

namespace ringid {

struct SystemDerivatives {
  // Entries of M, C, K and, at speed, of each slip lag's (K/sigma) f d^T and
  // (K/sigma) V f e^T (docs/rolling.md, R8): scaling all of them by one
  // factor changes no mode, nor does rescaling a lag's state.
  Eigen::VectorXd scaling_value;
  Eigen::MatrixXd scaling;  // d entry / d parameter, rows x kNumParams
  // At speed, each lag's V / sigma: its pole, which no factor may change.
  Eigen::MatrixXd invariant;  // rows x kNumParams
};

// At `p` (every parameter the model reads set) and `speed_m_s`.
SystemDerivatives Differentiate(const ModalModel& model, const Parameters& p, double speed_m_s);

}  // namespace ringid

#endif  // RINGID_MODEL_STRUCTURE_H_
