// "Did you mean": the one place that turns an unknown name (a flag, a mode
// label, a parameter, an effect) into a message that suggests the nearest
// valid name and lists the valid ones, so a typo costs one look, not a trip
// to the documentation.
#ifndef RINGID_MODEL_SPELLING_H_
#define RINGID_MODEL_SPELLING_H_

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/enum_names.h"

namespace ringid {

// Edits (insert, delete, substitute, swap two neighbours) from `a` to `b`.
int EditDistance(std::string_view a, std::string_view b);

// The candidate nearest to `text` if it is near enough to be a typo of it (at
// most (letters + 1) / 3 edits: none for one letter, one for two to four, two
// for five to seven, ...); the first of equally near ones.
std::optional<std::string> NearestName(std::string_view text,
                                       const std::vector<std::string>& candidates);

// "a, b or c".
std::string OneOf(const std::vector<std::string>& names);

// "unknown WHAT 'TEXT' (did you mean 'X'? expected A, B or C)", without the
// suggestion when nothing is near; `list` false leaves out the valid names
// (when there are too many to read, or another line lists them).
std::string UnknownName(const std::string& what, std::string_view text,
                        const std::vector<std::string>& candidates, bool list = true);

// The names of enum E (EnumNames<E>), in order.
template <class E>
std::vector<std::string> NamesOf() {
  const auto& names = EnumNames<E>::kNames;
  return std::vector<std::string>(names.begin(), names.end());
}

}  // namespace ringid

#endif  // RINGID_MODEL_SPELLING_H_
