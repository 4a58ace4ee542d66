#include "estimation/statistics.h"

#include <cmath>
#include <stdexcept>

#include <boost/math/distributions/chi_squared.hpp>

namespace ringid {

double ChiSquareTail(double x, double dof) {
  if (!(dof > 0)) return std::nan("");
  if (!(x > 0)) return 1.0;
  boost::math::chi_squared_distribution<double> d(dof);
  try {
    return boost::math::cdf(boost::math::complement(d, x));
  } catch (const std::overflow_error&) {
    // Boost's incomplete gamma overflows far from the mean of many degrees
    // of freedom (x = 1e-10 on 26,000, a noise-free FRF fit): the tail is 1
    // below the mean and 0 above it, to double precision; nothing thrown.
    return x < dof ? 1.0 : 0.0;
  }
}

double ChiSquareCritical(double alpha, double dof) {
  if (!(dof > 0) || !(alpha > 0 && alpha < 1)) return std::nan("");
  boost::math::chi_squared_distribution<double> d(dof);
  return boost::math::quantile(boost::math::complement(d, alpha));
}

}  // namespace ringid
