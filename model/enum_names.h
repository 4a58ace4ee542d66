// Every enum of the library with its names, in one place beside the enum (as
// Ceres' types.h pairs XToString with StringToX): a specialisation of
// EnumNames<E> lists kNames in the order of E's values 0, 1, 2, ...
#ifndef RINGID_MODEL_ENUM_NAMES_H_
#define RINGID_MODEL_ENUM_NAMES_H_

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace ringid {

template <class E>
struct EnumNames;  // static constexpr std::array<const char*, N> kNames

template <class E>
const char* ToString(E e) {
  return EnumNames<E>::kNames[static_cast<std::size_t>(e)];
}

template <class E>
std::optional<E> FromString(std::string_view name) {
  const auto& names = EnumNames<E>::kNames;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (name == names[i]) return static_cast<E>(i);
  }
  return std::nullopt;
}

// "a, b or c": the valid names, for an error message.
template <class E>
std::string EnumChoices() {
  const auto& names = EnumNames<E>::kNames;
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + std::string(names[i]);
  }
  return out;
}

// Objects a report names by pointer, the null pointer included (an effect,
// or "none"): a specialisation of PointerNames<T> provides
//   static const char* ToString(const T*);
//   static std::optional<const T*> FromString(std::string_view);
//   static std::string Choices();  // for an error message
template <class T>
struct PointerNames;

}  // namespace ringid

#endif  // RINGID_MODEL_ENUM_NAMES_H_
