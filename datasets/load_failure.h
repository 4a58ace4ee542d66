// What a strict reader throws inside itself and turns into its LoadError
// where it returns (datasets/dataset.cc, frf.cc, tir.cc, tir_contact.cc):
// the field that failed, as a path, and why; and how a message quotes the file.
#ifndef RINGID_DATASETS_LOAD_FAILURE_H_
#define RINGID_DATASETS_LOAD_FAILURE_H_

#include <string>
#include <string_view>

#include "datasets/dataset.h"

namespace ringid::internal {

struct Failure {
  std::string field;
  std::string message;
};

[[noreturn]] inline void Fail(const std::string& field, const std::string& message) {
  throw Failure{field, message};
}

// Runs `read`; a Failure it throws becomes `error`'s field and message, and
// the answer false.
template <class Read>
bool Captured(LoadError* error, Read&& read) {
  try {
    read();
  } catch (const Failure& f) {
    error->field = f.field;
    error->message = f.message;
    return false;
  }
  return true;
}

// `s` as a message may quote it: at most 40 characters, printable ASCII.
inline std::string Quoted(std::string_view s) {
  std::string out;
  for (const char c : s.substr(0, 40)) out += (c >= 32 && c < 127) ? c : '?';
  return "'" + out + (s.size() > 40 ? "...'" : "'");
}

}  // namespace ringid::internal

#endif  // RINGID_DATASETS_LOAD_FAILURE_H_
