// What a strict reader throws inside itself and turns into its LoadError
// where it returns (datasets/dataset.cc, frf.cc, tir.cc, tir_contact.cc):
// the field that failed, as a path, and why.
#ifndef RINGID_DATASETS_LOAD_FAILURE_H_
#define RINGID_DATASETS_LOAD_FAILURE_H_

#include <string>

namespace ringid::internal {

struct Failure {
  std::string field;
  std::string message;
};

[[noreturn]] inline void Fail(const std::string& field, const std::string& message) {
  throw Failure{field, message};
}

}  // namespace ringid::internal

#endif  // RINGID_DATASETS_LOAD_FAILURE_H_
