// What estimation/identifiability.cc shares with its tests, not installed.
#ifndef RINGID_ESTIMATION_IDENTIFIABILITY_INTERNAL_H_
#define RINGID_ESTIMATION_IDENTIFIABILITY_INTERNAL_H_

#include <Eigen/Core>

#include "estimation/identifiability.h"
#include "estimation/problem.h"

namespace ringid {
namespace internal {

// The profile of free coordinate i about the optimum xhat (cost cost_min),
// as AnalyzeIdentifiability computes it; wald_std its Wald standard
// deviation in coordinates (not finite where there is none).
// In estimation/profile.cc.
ProfileInterval ProfileCoordinate(const Problem& problem, const Eigen::VectorXd& xhat,
                                  double cost_min, int i, double wald_std,
                                  const IdentifiabilityOptions& options);

}  // namespace internal
}  // namespace ringid

#endif  // RINGID_ESTIMATION_IDENTIFIABILITY_INTERNAL_H_
