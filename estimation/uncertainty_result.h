// What the Jacobian says at a fitted point: covariance, rank, the class of
// each coordinate and what the model cannot see (estimation/uncertainty.h
// computes it).
#ifndef RINGID_ESTIMATION_UNCERTAINTY_RESULT_H_
#define RINGID_ESTIMATION_UNCERTAINTY_RESULT_H_

#include <string>
#include <vector>

#include <Eigen/Core>

#include "estimation/types.h"
#include "model/parameters.h"

namespace ringid {

// A free coordinate that the model separates from a known (fixed) parameter
// only because that one is fixed: with `known` freed as well, a direction
// along which no condition's system changes moves both.
struct KnownDependence {
  int coordinate = 0;
  Param known = Param::m_b;
  double known_value = 0;  // of the first condition
  // The combination of the two the model sees along that direction:
  // "K_cx/sigma_cx" (logs moving together), "K_cx*sigma_cx" (opposite),
  // "A + B" / "A - B" (values moving opposite / alike), "A/B^0.5" (logs in
  // another ratio), else the linear combination that stays, "A + 0.25 B (to
  // first order)".
  std::string measured;
  // True: the model cannot tell them apart (this test); false: the data
  // hardly can (the Schur-complement test in estimation/identify.cc).
  bool structural = true;
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
  // because that one is fixed (FindStructuralFreedom).
  std::vector<KnownDependence> known_dependence;

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

}  // namespace ringid

#endif  // RINGID_ESTIMATION_UNCERTAINTY_RESULT_H_
