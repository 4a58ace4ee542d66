#include "validation/coverage.h"

#include <cmath>
#include <cstdio>

#include "estimation/statistics.h"

namespace ringid {
namespace {

// The error of `estimate` in units of its std: in log space for a positive
// parameter (the covariance's coordinates), linear otherwise.
double ErrorOverStd(double estimate, double std, double truth) {
  if (estimate > 0 && truth > 0) return std::log(estimate / truth) / (std / estimate);
  return (estimate - truth) / std;
}

}  // namespace

void CoverageTally::Add(const ParameterEstimate& e, double truth, bool yes_only) {
  ++classes_[static_cast<int>(e.identifiable)];
  if (yes_only && e.identifiable != Identifiability::kYes) return;
  if (!e.std || !(*e.std > 0) || !std::isfinite(*e.std)) return;
  const double z = ErrorOverStd(e.value, *e.std, truth);
  ++intervals_;
  inside_ += std::abs(z) <= kNormal95;
  z_sum_ += z;
  z2_sum_ += z * z;
}

void CoverageTally::Into(ParameterCoverage* c) const {
  const double n = static_cast<double>(intervals_);
  c->yes = classes_[static_cast<int>(Identifiability::kYes)];
  c->practically_no = classes_[static_cast<int>(Identifiability::kPracticallyNo)];
  c->no = classes_[static_cast<int>(Identifiability::kNo)];
  c->intervals = intervals_;
  c->coverage_95 = intervals_ ? inside_ / n : NAN;
  c->mean_z = intervals_ ? z_sum_ / n : NAN;
  c->rms_z = intervals_ ? std::sqrt(z2_sum_ / n) : NAN;
}

std::string CoverageTableHeader() {
  return "| parameter | yes | practically_no | no | intervals | 95 % coverage | mean z | rms z |\n"
         "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
}

std::string CoverageRow(Param p, const ParameterCoverage& c) {
  char line[256];
  std::snprintf(line, sizeof line, "| %s | %d | %d | %d | %ld | %.1f %% | %+.2f | %.2f |\n",
                ToString(p), c.yes, c.practically_no, c.no, c.intervals, 100 * c.coverage_95,
                c.mean_z, c.rms_z);
  return line;
}

}  // namespace ringid
