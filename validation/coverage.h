// One parameter's classes and 95 % coverage over the replicates of a Monte
// Carlo suite (rolling, static): the record, its tally and its table row.
#ifndef RINGID_VALIDATION_COVERAGE_H_
#define RINGID_VALIDATION_COVERAGE_H_

#include <array>
#include <string>

#include "estimation/identify.h"

namespace ringid {

struct ParameterCoverage {
  // Fits classing it so (a failed fit classes nothing).
  int yes = 0, practically_no = 0, no = 0;
  long intervals = 0;      // fits that gave it a counted interval
  double coverage_95 = 0;  // of those intervals, the share holding the truth
  // z = log(estimate / truth) / (std / estimate) (linear where not positive):
  // the mean shows a bias, the rms is 1 when the std is right.
  double mean_z = 0;
  double rms_z = 0;
  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("yes", &yes);
    a->Visit("practically_no", &practically_no);
    a->Visit("no", &no);
    a->Visit("intervals", &intervals);
    a->Visit("coverage_95", &coverage_95);
    a->Visit("mean_z", &mean_z);
    a->Visit("rms_z", &rms_z);
  }
};

// The sums behind a ParameterCoverage, one fit's estimate at a time.
class CoverageTally {
 public:
  // Counts e's class and, where it has a std (and is classed yes, with
  // yes_only), its interval against `truth`.
  void Add(const ParameterEstimate& e, double truth, bool yes_only);
  void Into(ParameterCoverage* c) const;
  long inside() const { return inside_; }
  long intervals() const { return intervals_; }

 private:
  std::array<int, 3> classes_{};
  long inside_ = 0, intervals_ = 0;
  double z_sum_ = 0, z2_sum_ = 0;
};

// "| k_bx | 200 | 0 | 0 | 200 | 96.5 % | +0.10 | 0.92 |": the table's header
// and one row, as the suites' Markdown prints them.
std::string CoverageTableHeader();
std::string CoverageRow(Param p, const ParameterCoverage& c);

}  // namespace ringid

#endif  // RINGID_VALIDATION_COVERAGE_H_
