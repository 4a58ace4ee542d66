// The tire's static stiffnesses at the contact (contract §10): the force at
// the contact per unit displacement of the road under it, in one direction,
// from the standing system's stiffness matrix K (model/system.h) with the
// axle held in translation, the rim locked in rotation (theta_a = 0) and
// every contact element in K. For the baseline these are the .tir's series
// formulas (docs/tir.md); with an effect (a compliant hub, lug coupling) the
// solve includes it.
#ifndef RINGID_MODEL_STATIC_STIFFNESS_H_
#define RINGID_MODEL_STATIC_STIFFNESS_H_

#include <string>

#include <Eigen/Core>

#include "model/names.h"  // StaticDirection
#include "model/parameters.h"
#include "model/rigid_ring_model.h"

namespace ringid {

struct StaticStiffnessResult {
  bool ok = false;
  std::string error;  // why not, where !ok (K singular with theta_a locked)
  double value = 0;   // N/m
  // d value / d (catalogue parameter), kNumParams entries; set when asked.
  Eigen::RowVectorXd derivative;
};

// At `p` (every parameter the model reads set); with `derivatives`, the exact
// derivatives through model.Assemble's jets.
StaticStiffnessResult StaticStiffness(const ModalModel& model, const Parameters& p,
                                      StaticDirection direction, bool derivatives = false);

}  // namespace ringid

#endif  // RINGID_MODEL_STATIC_STIFFNESS_H_
