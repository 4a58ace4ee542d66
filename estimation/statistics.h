// Statistical constants, defined once.
#ifndef RINGID_ESTIMATION_STATISTICS_H_
#define RINGID_ESTIMATION_STATISTICS_H_

namespace ringid {

// The two-sided 95 % point of the standard normal: a 95 % Wald interval is
// value +- kNormal95 std.
inline constexpr double kNormal95 = 1.959963984540054;

// The 95 % point of chi-square with one degree of freedom (= kNormal95^2):
// a profile-likelihood 95 % interval ends where 2 delta cost passes it.
inline constexpr double kChiSquare1Dof95 = 3.841458820694124;

// P(chi-square(dof) >= x); NaN without a degree of freedom.
double ChiSquareTail(double x, double dof);

// The chi-square that would be significant at level alpha: the x with
// ChiSquareTail(x, dof) = alpha; NaN without a degree of freedom or for
// alpha outside (0, 1). ChiSquareCritical(0.05, 1) is kChiSquare1Dof95.
double ChiSquareCritical(double alpha, double dof);

}  // namespace ringid

#endif  // RINGID_ESTIMATION_STATISTICS_H_
