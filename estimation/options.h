// The options of the fits, their residuals and their uncertainty: plain
// structs whose fields are the documentation, each with IsValid.
#ifndef RINGID_ESTIMATION_OPTIONS_H_
#define RINGID_ESTIMATION_OPTIONS_H_

#include <string>
#include <utility>

#include "estimation/types.h"

namespace ringid {

// The measurements' weights and conventions (datasets/measurement_options.h)
// and how the residuals' Jacobians are made.
struct ResidualOptions : MeasurementOptions {
  Derivatives derivatives = Derivatives::kAuto;
  bool IsValid(std::string* why) const;
};

// The Downhill Simplex (estimation/simplex.h).
struct SimplexOptions {
  int max_evaluations = 20000;
  double initial_step = 0.1;  // edge of the first simplex, per coordinate
  // Stops when the spread of values over the simplex is below
  // f_tolerance * (|f_best| + tiny) and its diameter below x_tolerance.
  double f_tolerance = 1e-14;
  double x_tolerance = 1e-10;
  bool IsValid(std::string* why) const;
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
  // The 95 % interval relative to the value (ParameterSetup::Interval95) of
  // a parameter at practical_relative_std, within which a determined one is
  // "yes": exp(-+ kNormal95 t) fitted in its log (a factor 2 either way),
  // 1 -+ kNormal95 t fitted linearly.
  std::pair<double, double> PracticalBand(bool fitted_in_log) const;
};

// Levenberg-Marquardt stops once no step can change chi-square by more than
// this (estimation/fit.cc, StatisticalStop); 0 leaves only Ceres' own
// relative tolerances of 1e-14.
inline constexpr double kStopChiSquare = 1e-4;

}  // namespace ringid

#endif  // RINGID_ESTIMATION_OPTIONS_H_
