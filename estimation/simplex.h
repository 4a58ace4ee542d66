// Downhill Simplex (Nelder and Mead 1965), the method of the paper
// (docs/model.md section 10), on the same objective as Levenberg-Marquardt
// for a like-for-like comparison.
#ifndef RINGID_ESTIMATION_SIMPLEX_H_
#define RINGID_ESTIMATION_SIMPLEX_H_

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "estimation/options.h"
namespace ringid {

namespace internal {

struct SimplexResult {
  Eigen::VectorXd x;
  double cost = 0;
  int evaluations = 0;
  bool converged = false;
  std::string message;
  // (evaluations so far, best value) at each iteration.
  std::vector<std::pair<int, double>> history;
};

// Minimises f over the box [lower, upper]; f may return +inf where undefined.
SimplexResult MinimizeNelderMead(
    const std::function<double(const Eigen::VectorXd&)>& f,
    const Eigen::VectorXd& x0, const Eigen::VectorXd& lower,
    const Eigen::VectorXd& upper, const SimplexOptions& options);


}  // namespace internal
}  // namespace ringid

#endif  // RINGID_ESTIMATION_SIMPLEX_H_
