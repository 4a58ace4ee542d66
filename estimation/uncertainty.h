// Covariance, rank and identifiability at a fitted point.
#ifndef RINGID_ESTIMATION_UNCERTAINTY_H_
#define RINGID_ESTIMATION_UNCERTAINTY_H_

#include <string>
#include <vector>

#include <Eigen/Core>

#include "estimation/options.h"
#include "estimation/uncertainty_result.h"
#include "estimation/residuals.h"
#include "estimation/setup.h"
#include "estimation/structure.h"

namespace ringid {

namespace internal {

// The weighted Jacobian dr/dx at x by the fit's own central differences.
bool EvaluateJacobian(const ModalResiduals& residuals, const Eigen::VectorXd& x,
                      Eigen::MatrixXd* jacobian);

Uncertainty AnalyzeUncertainty(const ModalResiduals& residuals,
                               const ParameterSetup& setup,
                               const Eigen::VectorXd& x,
                               const UncertaintyOptions& options);

}  // namespace internal
}  // namespace ringid

#endif  // RINGID_ESTIMATION_UNCERTAINTY_H_
