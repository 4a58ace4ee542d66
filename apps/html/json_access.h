// Reads of a JSON report that never throw: a missing key or a value of the
// wrong type reads as null, an empty list, no number or "". Pages use these
// until they read typed reports.
#ifndef RINGID_APPS_HTML_JSON_ACCESS_H_
#define RINGID_APPS_HTML_JSON_ACCESS_H_

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace ringid::html {

using json = nlohmann::json;

const json& Get(const json& object, const char* key);
bool Has(const json& object, const char* key);
// The array at `key`, else an empty one.
const json& List(const json& object, const char* key);
// A finite number, else none.
std::optional<double> Num(const json& value);
std::optional<double> Num(const json& object, const char* key);
std::string Str(const json& value);
std::string Str(const json& object, const char* key);
bool IsTrue(const json& object, const char* key);
// Any value as short plain text: "–" for null, "yes"/"no", lists joined.
std::string Text(const json& value);

}  // namespace ringid::html

#endif  // RINGID_APPS_HTML_JSON_ACCESS_H_
