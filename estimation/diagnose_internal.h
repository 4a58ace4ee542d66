// What estimation/diagnose.cc shares with its tests, not installed.
#ifndef RINGID_ESTIMATION_DIAGNOSE_INTERNAL_H_
#define RINGID_ESTIMATION_DIAGNOSE_INTERNAL_H_

#include <string>

#include "estimation/diagnose.h"

namespace ringid {
namespace internal {
// The explanation's words on held-out modes: the leave-one-mode-out
// chi-square of the baseline (`before`) and of the verdict (`after`), said to
// fall or to rise.
std::string HeldOutChange(double before, double after);
}  // namespace internal
}  // namespace ringid

#endif  // RINGID_ESTIMATION_DIAGNOSE_INTERNAL_H_
