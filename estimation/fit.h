// One local fit from one start, the building block of identify, compare and
// the profile likelihood.
#ifndef RINGID_ESTIMATION_FIT_H_
#define RINGID_ESTIMATION_FIT_H_

#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "estimation/options.h"
#include "estimation/residuals.h"
#include "estimation/setup.h"
#include "estimation/simplex.h"

namespace ringid {

namespace internal {

struct Box {
  Eigen::VectorXd lower, upper;
  // The side x's coordinate i sits on, within 0.1 % of the box's width.
  std::optional<BoundSide> On(int i, double x) const;
};

// Free coordinates within a factor `bound_factor` of x0 (log coordinates),
// or x0 +- bound_factor * max(|x0|, 1) (others; non-negative ones from 0);
// `bounds` replace that for their parameters.
Box BoundsAround(const ParameterSetup& setup, const Eigen::VectorXd& x0,
                 double bound_factor, const Bounds& bounds = {});
// False, with why naming the parameter, when a bounded parameter is not free
// or its start lies outside its bounds.
bool CheckBounds(const ParameterSetup& setup, const Eigen::VectorXd& x0, const Bounds& bounds,
                 std::string* why);

// Levenberg-Marquardt's stop (StatisticalStop, estimation/fit.cc): besides
// kStopChiSquare, the gains of the last kShrinkingGains successful steps each
// at most kGainShrink times the one before, extrapolated at their slowest
// ratio but at least kSlowestShrink; Ceres' function and gradient
// tolerances kCeresTolerance behind it (docs/development.md, which a test
// keeps saying these figures).
inline constexpr int kShrinkingGains = 3;
inline constexpr double kGainShrink = 0.8;
inline constexpr double kSlowestShrink = 0.5;
inline constexpr double kCeresTolerance = 1e-14;
// From this many residuals (FRFs: lines x functions x 2) each step solves
// the normal equations (J'J, blocked and vectorised) in place of a
// Householder QR of J, several times its cost for tens of thousands of rows
// and a score of columns; modal data keep the QR.
inline constexpr int kNormalEquationsRows = 2000;

// 1/2 |r(x)|^2, or +inf where the model cannot be solved.
double CostAt(const ModalResiduals& residuals, const Eigen::VectorXd& x);

struct LocalFit {
  Eigen::VectorXd x;
  double cost = std::numeric_limits<double>::infinity();
  bool converged = false;
  // Stopped by its limit: max_iterations (Levenberg-Marquardt) or
  // SimplexOptions::max_evaluations, not by a convergence test or a failure.
  bool at_limit = false;
  std::string message;
  long evaluations = 0;  // model solutions this fit used
  double seconds = 0;
  // (model solutions so far, cost) per iteration, thinned to at most 200.
  std::vector<std::pair<long, double>> history;
};

// Levenberg-Marquardt (ceres::Solve on the residuals' Jacobians) or the
// Downhill Simplex from `start`. `fixed` >= 0 holds that coordinate at its
// start value (a profile). With no free coordinate it evaluates the start.
LocalFit FitLocally(const ModalResiduals& residuals, Method method,
                    const Eigen::VectorXd& start, const Box& box,
                    int max_iterations, const SimplexOptions& simplex,
                    int fixed = -1, double stop_chi_square = kStopChiSquare);

// What to try where `fit`, the best start, did not converge: more
// iterations where it ran out of them, else what it stopped on.
std::string NotConverged(const LocalFit& fit, Method method, int max_iterations,
                         const SimplexOptions& simplex);

}  // namespace internal

}  // namespace ringid

#endif  // RINGID_ESTIMATION_FIT_H_
