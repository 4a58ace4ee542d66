#include "apps/html/json_access.h"

#include <cmath>
#include <vector>

#include "apps/html/text.h"

namespace ringid::html {
namespace {

const json& Null() {
  static const json null;
  return null;
}

const json& EmptyList() {
  static const json list = json::array();
  return list;
}

}  // namespace

const json& Get(const json& object, const char* key) {
  if (!object.is_object()) return Null();
  const auto it = object.find(key);
  return it == object.end() ? Null() : *it;
}

bool Has(const json& object, const char* key) { return object.is_object() && object.contains(key); }

const json& List(const json& object, const char* key) {
  const json& value = Get(object, key);
  return value.is_array() ? value : EmptyList();
}

std::optional<double> Num(const json& value) {
  if (!value.is_number()) return std::nullopt;
  const double number = value.get<double>();
  if (!std::isfinite(number)) return std::nullopt;
  return number;
}

std::optional<double> Num(const json& object, const char* key) { return Num(Get(object, key)); }

std::string Str(const json& value) { return value.is_string() ? value.get<std::string>() : ""; }

std::string Str(const json& object, const char* key) { return Str(Get(object, key)); }

bool IsTrue(const json& object, const char* key) {
  const json& value = Get(object, key);
  return value.is_boolean() && value.get<bool>();
}

std::string Text(const json& value) {
  if (value.is_null()) return "–";
  if (value.is_string()) return value.get<std::string>();
  if (value.is_boolean()) return value.get<bool>() ? "yes" : "no";
  if (value.is_number_integer()) return std::to_string(value.get<long long>());
  if (value.is_number_unsigned()) return std::to_string(value.get<unsigned long long>());
  if (value.is_number()) return Format(value.get<double>());
  std::vector<std::string> items;
  if (value.is_array()) {
    for (const json& x : value) items.push_back(x.is_structured() ? "…" : Text(x));
  } else {
    for (const auto& [key, x] : value.items())
      items.push_back(key + " = " + (x.is_structured() ? "…" : Text(x)));
  }
  return Join(items, ", ");
}

}  // namespace ringid::html
