// Covariance, rank and identifiability at a fitted point.
#ifndef RINGID_ESTIMATION_UNCERTAINTY_H_
#define RINGID_ESTIMATION_UNCERTAINTY_H_

#include <string>
#include <vector>

#include <Eigen/Core>

#include "estimation/residuals.h"
#include "estimation/setup.h"
#include "estimation/structure.h"

namespace ringid {

enum class Identifiability { kYes, kPracticallyNo, kNo };
template <>
struct EnumNames<Identifiability> {
  static constexpr std::array<const char*, 3> kNames = {"yes", "practically_no", "no"};
};

struct UncertaintyOptions {
  // Singular values below rank_tolerance * largest count as zero; the same
  // cut (squared) drops eigenvalues in ceres::Covariance.
  double rank_tolerance = 1e-7;
  // A coordinate whose unit vector has at least this much of its length in
  // the null space moves without changing any residual: class "no".
  double null_projection = 1e-3;
  // Relative standard deviation (of the value; log-space std for positive
  // parameters) above which a determined parameter is "practically_no":
  // 0.354 makes the 95 % interval wider than a factor of 2 either way.
  double practical_relative_std = 0.354;
  bool IsValid(std::string* why) const;
};

struct Uncertainty {
  bool ok = false;           // the Jacobian could be evaluated
  std::string error;
  bool covariance_ok = false;  // ceres::Covariance::Compute succeeded
  std::string covariance_error;  // why not, when !covariance_ok
  Eigen::MatrixXd jacobian;        // weighted residuals by coordinates
  Eigen::VectorXd singular_values;  // descending, min(m, n) of them
  int rank = 0;
  double condition_number = 0;  // largest / smallest of n; inf if rank < n
  Eigen::MatrixXd null_space;   // columns: coordinate directions left free
  // Pseudo-inverse of J^T J on the determined subspace, in coordinates.
  Eigen::MatrixXd covariance;
  std::vector<Identifiability> classes;  // per coordinate
  std::vector<std::string> reasons;
  std::vector<double> std;  // per coordinate; NaN where not defined
  // Directions the model cannot see whatever the data (estimation/structure.h);
  // jacobian, singular_values, rank and null_space are those of the data
  // Jacobian with these directions projected out.
  Eigen::MatrixXd structural_directions;   // orthonormal columns
  std::vector<Eigen::VectorXd> structural_readable;  // the same span, one invariance each
  std::vector<std::string> structural_invariances;
  // Free coordinates the model separates from a known parameter only
  // because that one is fixed (FindKnownDependence).
  std::vector<internal::KnownDependence> known_dependence;

  // The report's part; classes and std go with each parameter.
  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("rank", &rank);
    a->Visit("structural_invariances", &structural_invariances);
    a->Visit("computed", &covariance_ok);
    a->Visit("error", &covariance_error);
    a->Visit("matrix", &covariance);
    a->Visit("singular_values", &singular_values);
    a->Visit("condition_number", &condition_number);
  }
};

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
