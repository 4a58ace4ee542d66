#include "estimation/statistics.h"

#include <cmath>

#include <boost/math/distributions/chi_squared.hpp>

namespace ringid {

double ChiSquareTail(double x, double dof) {
  if (!(dof > 0)) return std::nan("");
  if (!(x > 0)) return 1.0;
  boost::math::chi_squared_distribution<double> d(dof);
  return boost::math::cdf(boost::math::complement(d, x));
}

double ChiSquareCritical(double alpha, double dof) {
  if (!(dof > 0) || !(alpha > 0 && alpha < 1)) return std::nan("");
  boost::math::chi_squared_distribution<double> d(dof);
  return boost::math::quantile(boost::math::complement(d, alpha));
}

}  // namespace ringid
