// The smallest effects a diagnosis could not have seen: for each effect
// parameter, the size whose signature a re-calibration of the baseline cannot
// absorb, first linearised, then checked against the re-calibrated baseline
// (Diagnose's "none" verdict states them).
#ifndef RINGID_ESTIMATION_DETECTABLE_H_
#define RINGID_ESTIMATION_DETECTABLE_H_

#include <map>
#include <string>
#include <vector>

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

// The parameters of `effect` that free baseline parameters absorb whatever
// their size, each with those parameters: a parameter that can be 0 (it
// sizes the effect) and takes part, with free baseline parameters, in a
// structural invariance of `fit`, the fit of `model` (the baseline with
// `effect`) to `dataset` (estimation/structure.h: exact derivatives of every
// condition's system; a sensor mass and free m_b, I_by, I_bx, I_bz), which
// the data's exact Jacobian at the fit confirms. No data of this kind show
// such a size while those parameters are free.
std::map<std::string, std::vector<std::string>> AbsorbedBy(const RigidRingModel& model,
                                                           const Dataset& dataset,
                                                           const Effect& effect,
                                                           const IdentifyResult& fit,
                                                           const ResidualOptions& options);

// AbsorbedBy at the start of `at` (the baseline with `effect` seeded there),
// without a fit: the invariances found there (estimation/structure.h).
std::map<std::string, std::vector<std::string>> AbsorbedAt(const RigidRingModel& model,
                                                           const Dataset& at,
                                                           const Effect& effect,
                                                           const ResidualOptions& options);

// The baseline's initial values of `dataset` from `fit` (as AbsorbedBy): the
// effect's absorbed parameters moved to 0 along their invariances, which the
// baseline's parameters take up (the same model to first order), then the
// effect's parameters dropped.
Dataset BaselineFrom(const RigidRingModel& model, const Dataset& dataset, const Effect& effect,
                     const IdentifyResult& fit, const ResidualOptions& options);

// For a "none" verdict: the sizes the explanation promises (each ranking
// row's minimal_detectable), checked beyond first order and updated in `r`,
// as text ("" when there are none).
std::string DetectableSizes(const RigidRingModel& baseline, const Dataset& warm,
                            const DiagnoseOptions& o, DiagnosisResult* r);

}  // namespace internal
}  // namespace ringid

#endif  // RINGID_ESTIMATION_DETECTABLE_H_
