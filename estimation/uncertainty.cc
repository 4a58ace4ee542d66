#include "estimation/uncertainty.h"

#include <cmath>
#include <iomanip>
#include <memory>
#include <limits>
#include <sstream>

#include <Eigen/SVD>

#include "estimation/statistics.h"
#include "estimation/structure.h"

namespace ringid {

bool UncertaintyOptions::IsValid(std::string* why) const {
  if (!(rank_tolerance > 0 && rank_tolerance < 1)) {
    *why = "rank_tolerance must lie in (0, 1)";
  } else if (!(null_projection > 0 && null_projection < 1)) {
    *why = "null_projection must lie in (0, 1)";
  } else if (!(practical_relative_std > 0)) {
    *why = "practical_relative_std must be positive";
  } else {
    return true;
  }
  return false;
}

std::pair<double, double> UncertaintyOptions::PracticalBand(bool fitted_in_log) const {
  const double half = kNormal95 * practical_relative_std;
  if (fitted_in_log) return {std::exp(-half), std::exp(half)};
  return {1 - half, 1 + half};
}

namespace internal {

bool EvaluateJacobian(const ModalResiduals& residuals, const Eigen::VectorXd& x,
                      Eigen::MatrixXd* jacobian) {
  const int n = static_cast<int>(x.size());
  const int m = residuals.num_residuals();
  // The same cost function as the fit.
  std::unique_ptr<ceres::CostFunction> cost(NewResidualCost(residuals));
  Eigen::VectorXd r(m);
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> J(m, n);
  double* jac[] = {J.data()};
  const double* params[] = {x.data()};
  if (!cost->Evaluate(params, r.data(), jac) || !AllFinite(J.data(), J.size())) return false;
  *jacobian = J;
  return true;
}

namespace {

// Ceres' dense-SVD covariance with the null space dropped, from J's SVD:
// V diag(1 / s_i^2) V^T over the singular values within `tolerance` of the
// largest (Ceres' min_reciprocal_condition_number is tolerance^2, on s^2).
// Fewer rows than parameters leave V's last columns without a singular value:
// null space too. False where it is not finite (J zero).
bool Covariance(const Eigen::JacobiSVD<Eigen::MatrixXd>& svd, double tolerance,
                Eigen::MatrixXd* covariance) {
  const Eigen::VectorXd& s = svd.singularValues();
  Eigen::VectorXd inverse_squared = Eigen::VectorXd::Zero(svd.matrixV().cols());
  for (int i = 0; i < s.size(); ++i) {
    if (s[i] / s[0] < tolerance) break;
    inverse_squared[i] = 1.0 / (s[i] * s[i]);
  }
  *covariance = svd.matrixV() * inverse_squared.asDiagonal() * svd.matrixV().transpose();
  return covariance->allFinite();
}

}  // namespace

Uncertainty AnalyzeUncertainty(const ModalResiduals& residuals,
                               const ParameterSetup& setup,
                               const Eigen::VectorXd& x_in,
                               const UncertaintyOptions& options) {
  Uncertainty u;
  const int n = setup.size();
  const int m = residuals.num_residuals();
  u.classes.assign(n, Identifiability::kNo);
  u.reasons.assign(n, "");
  u.std.assign(n, std::numeric_limits<double>::quiet_NaN());
  if (n == 0) {
    u.ok = true;
    u.error = u.covariance_error = "no free parameters";
    return u;
  }
  Eigen::VectorXd x = x_in;
  Eigen::MatrixXd J;
  if (!EvaluateJacobian(residuals, x, &J)) {
    u.error = u.covariance_error = "the Jacobian could not be evaluated at the fitted point";
    return u;
  }
  u.ok = true;
  // Finite differences leave noise along directions the model cannot see;
  // those are decided exactly and projected out.
  const StructuralFreedom freedom = FindStructuralFreedom(residuals, x);
  const Eigen::MatrixXd& S = freedom.directions;
  u.structural_directions = S;
  u.structural_readable = freedom.readable;
  u.structural_invariances = freedom.invariances;
  u.known_dependence = freedom.known_dependence;
  u.jacobian = S.cols() ? Eigen::MatrixXd(J - (J * S) * S.transpose()) : J;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(u.jacobian, Eigen::ComputeFullV);
  u.singular_values = svd.singularValues();
  const double smax = u.singular_values.size() ? u.singular_values[0] : 0;
  u.rank = 0;
  for (int i = 0; i < u.singular_values.size(); ++i) {
    if (u.singular_values[i] > options.rank_tolerance * smax) ++u.rank;
  }
  u.condition_number =
      (u.rank == n && n > 0) ? smax / u.singular_values[n - 1]
                             : std::numeric_limits<double>::infinity();
  u.null_space = svd.matrixV().rightCols(n - u.rank);

  // The covariance of the Jacobian as evaluated (dense SVD, null space
  // dropped below the same cut): its SVD above where nothing was projected.
  u.covariance_ok =
      S.cols() ? Covariance(Eigen::JacobiSVD<Eigen::MatrixXd>(J, Eigen::ComputeFullV),
                            options.rank_tolerance, &u.covariance)
               : Covariance(svd, options.rank_tolerance, &u.covariance);
  if (!u.covariance_ok) u.covariance_error = "the covariance is not finite";

  for (int i = 0; i < n; ++i) {
    const double in_null =
        u.null_space.cols() ? u.null_space.row(i).norm() : 0.0;
    std::ostringstream why;
    if (S.cols() && S.row(i).norm() > options.null_projection) {
      u.classes[i] = Identifiability::kNo;
      u.reasons[i] = "structurally free: " + freedom.InvarianceOf(i);
      continue;
    }
    if (in_null > options.null_projection) {
      u.classes[i] = Identifiability::kNo;
      why << "moves along a direction the data leaves free ("
          << static_cast<int>(std::round(100 * in_null * in_null))
          << " % of it in the null space; rank " << u.rank << " of " << n
          << ")";
      u.reasons[i] = why.str();
      continue;
    }
    if (!u.covariance_ok) {
      u.classes[i] = Identifiability::kPracticallyNo;
      u.reasons[i] = "covariance not available: " + u.covariance_error;
      continue;
    }
    u.std[i] = std::sqrt(std::max(0.0, u.covariance(i, i)));
    const double relative =
        setup.is_log(i) ? u.std[i]
                        : u.std[i] / std::max(std::abs(x[i]), 1e-300);
    if (relative > options.practical_relative_std) {
      u.classes[i] = Identifiability::kPracticallyNo;
      const auto [low, high] = options.PracticalBand(setup.is_log(i));
      why << "determined, but its relative standard deviation " << relative << " is above "
          << options.practical_relative_std << ": its 95 % interval reaches beyond "
          << std::setprecision(3) << low << "-" << high << " times its value";
    } else {
      u.classes[i] = Identifiability::kYes;
      why << "relative standard deviation " << relative;
    }
    u.reasons[i] = why.str();
  }
  return u;
}

}  // namespace internal
}  // namespace ringid
