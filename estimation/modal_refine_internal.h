// The refinement's residuals and their analytic Jacobian
// (estimation/modal_refine.h), open to the tests.
#ifndef RINGID_ESTIMATION_MODAL_REFINE_INTERNAL_H_
#define RINGID_ESTIMATION_MODAL_REFINE_INTERNAL_H_

#include <complex>
#include <vector>

#include "datasets/frf.h"

namespace ringid {
namespace internal {

// One function's values over the lines fitted.
struct RefinedFunctionData {
  int order = 0;                        // q of LsfdFunction
  std::vector<std::complex<double>> s;  // iω per line
  std::vector<std::complex<double>> h;  // measured
  // The residual terms' basis per line: s^q / s² (lower) and s^q (upper).
  std::vector<std::complex<double>> lower_basis, upper_basis;
  std::vector<double> weight;           // 1 / sigma, or 1
};

// `f`'s values over `lines`, weighted by 1 / sigma where `weighted`.
RefinedFunctionData FunctionData(const Frf& frf, int function, const std::vector<int>& lines,
                                 bool weighted);

// The weighted residuals weight (H_model - h), rows 2k (real part) and
// 2k + 1 (imaginary) per line k, at `poles` (per pole log(-Re λ), log(Im λ);
// then per real pole log(-σ)) and `own` (per pole Re R, Im R; per real pole
// Q; then lower, upper); with their Jacobians by each (row-major, as Ceres
// lays them out) where not null. `m` poles, `mr` real poles.
void FunctionResiduals(const RefinedFunctionData& f, int m, const double* poles,
                       const double* own, double* residuals, double* jacobian_poles,
                       double* jacobian_own, int mr = 0);

}  // namespace internal
}  // namespace ringid

#endif  // RINGID_ESTIMATION_MODAL_REFINE_INTERNAL_H_
