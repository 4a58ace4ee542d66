// How a run ended, the same for every analysis: success, or why not.
#ifndef RINGID_ESTIMATION_STATUS_H_
#define RINGID_ESTIMATION_STATUS_H_

#include <array>
#include <string>
#include <utility>

#include "model/enum_names.h"

namespace ringid {

enum class Outcome {
  kSuccess,       // the analysis ran to its end (message: how it stopped)
  kInvalidInput,  // the options or the dataset were unusable; nothing ran
  kFailed,        // it ran but failed numerically (message: why)
};

template <>
struct EnumNames<Outcome> {
  static constexpr std::array<const char*, 3> kNames = {"success", "invalid_input", "failed"};
};

struct Status {
  Outcome outcome = Outcome::kFailed;
  std::string message;

  static Status Success(std::string message = "") { return {Outcome::kSuccess, std::move(message)}; }
  static Status InvalidInput(std::string message) {
    return {Outcome::kInvalidInput, std::move(message)};
  }
  static Status Failed(std::string message) { return {Outcome::kFailed, std::move(message)}; }
  bool ok() const { return outcome == Outcome::kSuccess; }
  bool invalid_input() const { return outcome == Outcome::kInvalidInput; }

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("status", &outcome);
    a->Visit("message", &message);
  }
};

}  // namespace ringid

#endif  // RINGID_ESTIMATION_STATUS_H_
