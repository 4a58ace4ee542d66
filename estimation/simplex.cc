#include "estimation/simplex.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "estimation/interrupt.h"

namespace ringid {

bool SimplexOptions::IsValid(std::string* why) const {
  if (max_evaluations < 1) *why = "max_evaluations must be at least 1";
  else if (!(initial_step > 0)) *why = "initial_step must be positive";
  else if (!(f_tolerance >= 0) || !(x_tolerance >= 0)) *why = "tolerances must not be negative";
  else return true;
  return false;
}

namespace internal {

SimplexResult MinimizeNelderMead(
    const std::function<double(const Eigen::VectorXd&)>& f,
    const Eigen::VectorXd& x0, const Eigen::VectorXd& lower,
    const Eigen::VectorXd& upper, const SimplexOptions& o) {
  const int n = static_cast<int>(x0.size());
  SimplexResult result;
  auto eval = [&](const Eigen::VectorXd& x) {
    ++result.evaluations;
    const double v = f(x.cwiseMax(lower).cwiseMin(upper));
    return std::isfinite(v) ? v : std::numeric_limits<double>::infinity();
  };
  std::vector<Eigen::VectorXd> p(n + 1, x0);
  std::vector<double> v(n + 1);
  for (int i = 0; i < n; ++i) {
    p[i + 1][i] += (x0[i] + o.initial_step <= upper[i]) ? o.initial_step
                                                         : -o.initial_step;
  }
  for (int i = 0; i <= n; ++i) v[i] = eval(p[i]);
  std::vector<int> order(n + 1);
  while (true) {
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return v[a] < v[b]; });
    const int best = order[0], worst = order[n], second = order[n - 1];
    result.history.emplace_back(result.evaluations, v[best]);
    double diameter = 0;
    for (int i = 0; i <= n; ++i) {
      diameter = std::max(diameter, (p[i] - p[best]).cwiseAbs().maxCoeff());
    }
    const double spread = v[worst] - v[best];
    if (n == 0 || (spread <= o.f_tolerance * (std::abs(v[best]) + 1e-300) &&
                   diameter <= o.x_tolerance) ||
        (v[best] == 0.0)) {
      result.converged = std::isfinite(v[best]);
      result.message = "simplex collapsed below the tolerances";
      break;
    }
    if (result.evaluations >= o.max_evaluations) {
      result.message = "evaluation budget exhausted";
      break;
    }
    if (InterruptRequested()) {
      result.message = "interrupted";
      break;
    }
    Eigen::VectorXd centroid = Eigen::VectorXd::Zero(n);
    for (int i = 0; i <= n; ++i) {
      if (i != worst) centroid += p[i];
    }
    centroid /= n;
    const Eigen::VectorXd xr = centroid + (centroid - p[worst]);
    const double vr = eval(xr);
    if (vr < v[best]) {  // expand
      const Eigen::VectorXd xe = centroid + 2 * (centroid - p[worst]);
      const double ve = eval(xe);
      if (ve < vr) { p[worst] = xe; v[worst] = ve; }
      else { p[worst] = xr; v[worst] = vr; }
    } else if (vr < v[second]) {  // reflect
      p[worst] = xr;
      v[worst] = vr;
    } else {  // contract, outside or inside
      const bool outside = vr < v[worst];
      const Eigen::VectorXd xc =
          outside ? Eigen::VectorXd(centroid + 0.5 * (xr - centroid))
                  : Eigen::VectorXd(centroid + 0.5 * (p[worst] - centroid));
      const double vc = eval(xc);
      if (vc < (outside ? vr : v[worst])) {
        p[worst] = xc;
        v[worst] = vc;
      } else {  // shrink towards the best
        for (int i = 0; i <= n; ++i) {
          if (i == best) continue;
          p[i] = p[best] + 0.5 * (p[i] - p[best]);
          v[i] = eval(p[i]);
        }
      }
    }
  }
  const int best = static_cast<int>(std::min_element(v.begin(), v.end()) - v.begin());
  result.x = p[best].cwiseMax(lower).cwiseMin(upper);
  result.cost = v[best];
  return result;
}

}  // namespace internal
}  // namespace ringid
