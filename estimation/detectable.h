// The smallest effects a diagnosis could not have seen: for each effect
// parameter, the size whose signature a re-calibration of the baseline cannot
// absorb, first linearised, then checked against the re-calibrated baseline
// (Diagnose's "none" verdict states them).
#ifndef RINGID_ESTIMATION_DETECTABLE_H_
#define RINGID_ESTIMATION_DETECTABLE_H_

#include <map>
#include <string>

#include <Eigen/Core>

#include "estimation/diagnose.h"
#include "model/rigid_ring_model.h"

namespace ringid {
namespace internal {

// The smallest value of each effect parameter a re-calibration of the
// baseline cannot absorb: the part of its Jacobian column outside the span of
// the baseline's columns (J_base, of rank `rank`) must reach a likelihood
// ratio of `detect`. `warm` is the dataset seeded at the calibrated point.
std::map<std::string, double> MinimalDetectable(const RigidRingModel& baseline,
                                                const Effect& effect, const Dataset& warm,
                                                const Eigen::MatrixXd& J_base, int rank,
                                                const DiagnoseOptions& o, double detect);

// For a "none" verdict: the sizes the explanation promises (each ranking
// row's minimal_detectable), checked beyond first order and updated in `r`,
// as text ("" when there are none).
std::string DetectableSizes(const RigidRingModel& baseline, const Dataset& warm,
                            const DiagnoseOptions& o, DiagnosisResult* r);

}  // namespace internal
}  // namespace ringid

#endif  // RINGID_ESTIMATION_DETECTABLE_H_
