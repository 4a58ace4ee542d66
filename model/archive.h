// The two archives a report's one field list drives: a struct lists its
// fields once, in `template <class Archive> void Serialize(Archive* a)`, and
// JsonWriter writes them while JsonReader reads them back strictly (a missing
// field, a wrong type or an unknown key is an error naming its path). Drake's
// config structs work the same way.
//
// In Serialize:
//   a->Visit("name", &field);          // any type below
//   a->VisitIfSet("name", &optional);  // written only when set; absent reads as unset
//   a->VisitKeyed("name", &list, &T::key);  // a list as an object keyed by a member
//   a->Group("name", [&](auto* g) { g->Visit(...); });  // a nested object
//   a->Derived("name", value);         // computed from the fields listed before it: written,
//                                      // and on reading checked against them
//
// Types: bool, integers, double (null where not finite), std::string, enums
// with EnumNames, pointers to objects with PointerNames (an effect or "none"), std::complex<double> ({re, im}), std::optional (null),
// std::vector (array), std::pair (two-element array), std::map keyed by a
// string or an enum (object), Eigen vectors (array) and matrices (rows),
// std::variant (read as its first alternative the value reads as: a number
// or an array of them, say), and structs with Serialize (object).
#ifndef RINGID_MODEL_ARCHIVE_H_
#define RINGID_MODEL_ARCHIVE_H_

#include <cmath>
#include <cstdint>
#include <complex>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "model/enum_names.h"

namespace ringid {

// Reports keep their fields in the order Serialize lists them.
using Json = nlohmann::ordered_json;

namespace detail {  // of the templates below, installed with them


template <class T> struct IsOptional : std::false_type {};
template <class T> struct IsOptional<std::optional<T>> : std::true_type {};
template <class T> struct IsVector : std::false_type {};
template <class T, class A> struct IsVector<std::vector<T, A>> : std::true_type {};
template <class T> struct IsPair : std::false_type {};
template <class A, class B> struct IsPair<std::pair<A, B>> : std::true_type {};
template <class T> struct IsMap : std::false_type {};
template <class K, class V> struct IsMap<std::map<K, V>> : std::true_type {};
template <class T> struct IsEigen : std::is_base_of<Eigen::EigenBase<T>, T> {};
template <class T> struct IsVariant : std::false_type {};
template <class... T> struct IsVariant<std::variant<T...>> : std::true_type {};

template <class T>
using PointerNamesOf = PointerNames<std::remove_const_t<std::remove_pointer_t<T>>>;

template <class K>
std::string KeyText(const K& key) {
  if constexpr (std::is_enum_v<K>) {
    return ToString(key);
  } else if constexpr (!std::is_same_v<K, std::string>) {
    return key.Text();
  } else {
    return key;
  }
}

template <class K>
bool KeyFromText(const std::string& text, K* key) {
  if constexpr (std::is_enum_v<K>) {
    const auto parsed = FromString<K>(text);
    if (parsed) *key = *parsed;
    return parsed.has_value();
  } else if constexpr (!std::is_same_v<K, std::string>) {
    return K::Parse(text, key);
  } else {
    *key = text;
    return true;
  }
}

}  // namespace detail

class JsonWriter {
 public:
  explicit JsonWriter(Json* object) : object_(object) { *object_ = Json::object(); }

  template <class T>
  void Visit(const char* name, T* value) {
    (*object_)[name] = ToJson(*value);
  }
  template <class T>
  void VisitIfSet(const char* name, std::optional<T>* value) {
    if (*value) (*object_)[name] = ToJson(**value);
  }
  template <class T, class K>
  void VisitKeyed(const char* name, std::vector<T>* items, K T::*key) {
    Json object = Json::object();
    for (const T& item : *items) object[detail::KeyText(item.*key)] = ToJson(item);
    (*object_)[name] = std::move(object);
  }
  template <class F>
  void Group(const char* name, F&& fields) {
    Json object;
    JsonWriter group(&object);
    fields(&group);
    (*object_)[name] = std::move(object);
  }
  template <class T>
  void Derived(const char* name, const T& value) {
    (*object_)[name] = ToJson(value);
  }

  template <class T>
  static Json ToJson(const T& v) {
    if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, std::string>) {
      return v;
    } else if constexpr (std::is_enum_v<T>) {
      return ToString(v);
    } else if constexpr (std::is_pointer_v<T>) {
      return detail::PointerNamesOf<T>::ToString(v);
    } else if constexpr (std::is_integral_v<T>) {
      return v;
    } else if constexpr (std::is_floating_point_v<T>) {
      return std::isfinite(v) ? Json(v) : Json(nullptr);
    } else if constexpr (std::is_same_v<T, std::complex<double>>) {
      return Json{{"re", ToJson(v.real())}, {"im", ToJson(v.imag())}};
    } else if constexpr (detail::IsOptional<T>::value) {
      return v ? ToJson(*v) : Json(nullptr);
    } else if constexpr (detail::IsVector<T>::value) {
      Json array = Json::array();
      for (const auto& item : v) array.push_back(ToJson(item));
      return array;
    } else if constexpr (detail::IsPair<T>::value) {
      return Json::array({ToJson(v.first), ToJson(v.second)});
    } else if constexpr (detail::IsVariant<T>::value) {
      return std::visit([](const auto& item) { return ToJson(item); }, v);
    } else if constexpr (detail::IsMap<T>::value) {
      Json object = Json::object();
      for (const auto& [key, item] : v) object[detail::KeyText(key)] = ToJson(item);
      return object;
    } else if constexpr (detail::IsEigen<T>::value) {
      Json rows = Json::array();
      for (Eigen::Index i = 0; i < v.rows(); ++i) {
        if (T::ColsAtCompileTime == 1) {
          rows.push_back(ToJson(double(v(i, 0))));
          continue;
        }
        Json row = Json::array();
        for (Eigen::Index j = 0; j < v.cols(); ++j) row.push_back(ToJson(double(v(i, j))));
        rows.push_back(std::move(row));
      }
      return rows;
    } else {
      Json object;
      JsonWriter writer(&object);
      const_cast<T&>(v).Serialize(&writer);  // Serialize only reads when writing
      return object;
    }
  }

 private:
  Json* object_;
};

class JsonReader {
 public:
  // Reads fields of `object`; errors name `path` (e.g. "modes[2]").
  JsonReader(const Json& object, std::string path, std::string* error)
      : object_(object), path_(std::move(path)), error_(error) {}

  bool ok() const { return error_->empty(); }

  template <class T>
  void Visit(const char* name, T* value) {
    const Json* field = Field(name);
    if (!field) {
      if (ok()) Fail(Path(name) + ": missing");
      return;
    }
    FromJson(*field, Path(name), value, error_);
  }
  template <class T>
  void VisitIfSet(const char* name, std::optional<T>* value) {
    const Json* field = Field(name);
    value->reset();
    if (!field) return;
    value->emplace();
    FromJson(*field, Path(name), &**value, error_);
  }
  template <class T, class K>
  void VisitKeyed(const char* name, std::vector<T>* items, K T::*key) {
    const Json* field = Field(name);
    if (!field) {
      if (ok()) Fail(Path(name) + ": missing");
      return;
    }
    if (!Expect(*field, field->is_object(), Path(name), "an object", error_)) return;
    items->clear();
    for (const auto& [text, item] : field->items()) {
      const std::string path = Path(name) + "." + text;
      T value{};
      if (!detail::KeyFromText(text, &(value.*key))) {
        Fail(path + ": unknown name '" + text + "'");
        return;
      }
      if (!FromJson(item, path, &value, error_)) return;
      items->push_back(std::move(value));
    }
  }
  template <class F>
  void Group(const char* name, F&& fields) {
    const Json* field = Field(name);
    if (!field) {
      if (ok()) Fail(Path(name) + ": missing");
      return;
    }
    if (!Expect(*field, field->is_object(), Path(name), "an object", error_)) return;
    JsonReader group(*field, Path(name), error_);
    fields(&group);
    group.Finish();
  }
  // A derived field must be there and agree with the fields read before it.
  template <class T>
  void Derived(const char* name, const T& value) {
    const Json* field = Field(name);
    if (!ok()) return;
    if (!field) {
      Fail(Path(name) + ": missing");
    } else if (*field != JsonWriter::ToJson(value)) {
      Fail(Path(name) + ": does not agree with the fields it is derived from");
    }
  }

  // After Serialize: every key of the object must have been a field.
  bool Finish() {
    if (!ok()) return false;
    for (const auto& [key, value] : object_.items()) {
      if (!seen_.count(key)) return Fail(Path(key) + ": unknown key");
    }
    return true;
  }

  template <class T>
  static bool FromJson(const Json& j, const std::string& path, T* v, std::string* error) {
    if constexpr (std::is_same_v<T, bool>) {
      if (!Expect(j, j.is_boolean(), path, "true or false", error)) return false;
      *v = j.get<bool>();
    } else if constexpr (std::is_same_v<T, std::string>) {
      if (!Expect(j, j.is_string(), path, "a string", error)) return false;
      *v = j.get<std::string>();
    } else if constexpr (std::is_enum_v<T>) {
      if (!Expect(j, j.is_string(), path, "a name", error)) return false;
      const auto parsed = FromString<T>(j.get<std::string>());
      if (!parsed) {
        *error = path + ": unknown name '" + j.get<std::string>() + "' (expected " +
                 EnumChoices<T>() + ")";
        return false;
      }
      *v = *parsed;
    } else if constexpr (std::is_pointer_v<T>) {
      if (!Expect(j, j.is_string(), path, "a name", error)) return false;
      const auto parsed = detail::PointerNamesOf<T>::FromString(j.get<std::string>());
      if (!parsed) {
        *error = path + ": unknown name '" + j.get<std::string>() + "' (expected " +
                 detail::PointerNamesOf<T>::Choices() + ")";
        return false;
      }
      *v = *parsed;
    } else if constexpr (std::is_integral_v<T>) {
      if (!Expect(j, j.is_number_integer(), path, "a whole number", error)) return false;
      // nlohmann converts out of range silently: 2^32 + 20 would read as 20.
      const bool fits = j.is_number_unsigned()
                            ? j.get<std::uint64_t>() <= static_cast<std::uint64_t>(std::numeric_limits<T>::max())
                            : j.get<std::int64_t>() >= static_cast<std::int64_t>(std::numeric_limits<T>::min()) &&
                                  (std::numeric_limits<T>::max() >= std::numeric_limits<std::int64_t>::max() ||
                                   j.get<std::int64_t>() <= static_cast<std::int64_t>(std::numeric_limits<T>::max()));
      if (!fits) {
        *error = path + ": out of range";
        return false;
      }
      *v = j.get<T>();
    } else if constexpr (std::is_floating_point_v<T>) {
      if (!Expect(j, j.is_number() || j.is_null(), path, "a number", error)) return false;  // null: not finite
      *v = j.is_null() ? std::numeric_limits<T>::quiet_NaN() : j.get<T>();
    } else if constexpr (std::is_same_v<T, std::complex<double>>) {
      double re = 0, im = 0;
      JsonReader reader(j, path, error);
      if (!Expect(j, j.is_object(), path, "an object", error)) return false;
      reader.Visit("re", &re);
      reader.Visit("im", &im);
      if (!reader.Finish()) return false;
      *v = {re, im};
    } else if constexpr (detail::IsOptional<T>::value) {
      if (j.is_null()) {
        v->reset();
        return true;
      }
      v->emplace();
      return FromJson(j, path, &**v, error);
    } else if constexpr (detail::IsVector<T>::value) {
      if (!Expect(j, j.is_array(), path, "an array", error)) return false;
      v->assign(j.size(), typename T::value_type{});
      for (size_t i = 0; i < j.size(); ++i) {
        if (!FromJson(j[i], path + "[" + std::to_string(i) + "]", &(*v)[i], error)) return false;
      }
    } else if constexpr (detail::IsPair<T>::value) {
      if (!Expect(j, j.is_array() && j.size() == 2, path, "a pair [a, b]", error)) return false;
      return FromJson(j[0], path + "[0]", &v->first, error) &&
             FromJson(j[1], path + "[1]", &v->second, error);
    } else if constexpr (detail::IsMap<T>::value) {
      if (!Expect(j, j.is_object(), path, "an object", error)) return false;
      v->clear();
      for (const auto& [text, item] : j.items()) {
        typename T::key_type key{};
        if (!detail::KeyFromText(text, &key)) {
          *error = path + "." + text + ": unknown name '" + text + "'";
          return false;
        }
        if (!FromJson(item, path + "." + text, &(*v)[key], error)) return false;
      }
    } else if constexpr (detail::IsEigen<T>::value) {
      return EigenFromJson(j, path, v, error);
    } else if constexpr (detail::IsVariant<T>::value) {
      return VariantFromJson<T, 0>(j, path, v, error);
    } else {
      if (!Expect(j, j.is_object(), path, "an object", error)) return false;
      JsonReader reader(j, path, error);
      v->Serialize(&reader);
      return reader.Finish();
    }
    return true;
  }

 private:
  // The first alternative from I on that j reads as; else the last one's error.
  template <class T, size_t I>
  static bool VariantFromJson(const Json& j, const std::string& path, T* v, std::string* error) {
    std::variant_alternative_t<I, T> item{};
    std::string why;
    if (FromJson(j, path, &item, &why)) {
      *v = std::move(item);
      return true;
    }
    if constexpr (I + 1 < std::variant_size_v<T>) {
      return VariantFromJson<T, I + 1>(j, path, v, error);
    } else {
      // A value neither a number nor an array (the one variant read, a
      // sigma, is those) says so; else the last alternative's error (an
      // array with one bad element, say).
      const bool typed = (j.is_number() || j.is_null()) ? false : !j.is_array();
      *error = typed ? path + ": must be a number or an array (found " + j.type_name() + ")" : why;
      return false;
    }
  }
  template <class T>
  static bool EigenFromJson(const Json& j, const std::string& path, T* v, std::string* error) {
    if (!Expect(j, j.is_array(), path, "an array", error)) return false;
    const Eigen::Index rows = static_cast<Eigen::Index>(j.size());
    if (T::ColsAtCompileTime == 1) {
      std::vector<double> values;
      if (!FromJson(j, path, &values, error)) return false;
      v->resize(rows, 1);
      for (Eigen::Index i = 0; i < rows; ++i) (*v)(i, 0) = values[i];
      return true;
    }
    std::vector<std::vector<double>> values;
    if (!FromJson(j, path, &values, error)) return false;
    const Eigen::Index cols = rows ? static_cast<Eigen::Index>(values[0].size()) : 0;
    v->resize(rows, cols);
    for (Eigen::Index i = 0; i < rows; ++i) {
      if (static_cast<Eigen::Index>(values[i].size()) != cols) {
        *error = path + "[" + std::to_string(i) + "]: rows differ in length";
        return false;
      }
      for (Eigen::Index k = 0; k < cols; ++k) (*v)(i, k) = values[i][k];
    }
    return true;
  }

  static bool Expect(const Json& j, bool good, const std::string& path, const char* what,
                     std::string* error) {
    if (!good) *error = path + ": must be " + what + " (found " + j.type_name() + ")";
    return good;
  }
  const Json* Field(const char* name) {
    seen_.insert(name);
    if (!ok()) return nullptr;
    const auto it = object_.find(name);
    return it == object_.end() ? nullptr : &*it;
  }
  std::string Path(const std::string& name) const {
    return path_.empty() ? name : path_ + "." + name;
  }
  bool Fail(const std::string& message) {
    if (ok()) *error_ = message;
    return false;
  }

  const Json& object_;
  std::string path_;
  std::string* error_;
  std::set<std::string> seen_;
};

}  // namespace ringid

#endif  // RINGID_MODEL_ARCHIVE_H_
