// A third archive over the same Serialize lists: the schema of a report as
// Markdown, one line per field with its path and type. docs/reports.md is its
// output (`ringid schema`), so the documented fields are the written ones.
#ifndef RINGID_REPORT_SCHEMA_H_
#define RINGID_REPORT_SCHEMA_H_

#include <string>
#include <utility>

#include "model/archive.h"

namespace ringid {

class SchemaWriter {
 public:
  // A report writes a VisitIfSet field only when set and null for a number
  // that is not finite; an input file may leave such a field out, and its
  // numbers are numbers.
  enum class Of { kReport, kInput };
  SchemaWriter(std::string prefix, std::string* out, Of of = Of::kReport)
      : prefix_(std::move(prefix)), out_(out), of_(of) {}

  template <class T>
  void Visit(const char* name, T* value) {
    if constexpr (std::is_same_v<T, std::string>) {
      if (Format(name, *value)) return;
    }
    Field<T>(name, "");
  }
  template <class T>
  void VisitIfSet(const char* name, std::optional<T>*) {
    Field<T>(name, of_ == Of::kInput ? " (optional)" : " (only when set)");
  }
  template <class T, class K>
  void VisitKeyed(const char* name, std::vector<T>*, K T::*) {
    Line(Path(name), "object keyed by " + KeyName<K>());
    Entry<T>(Path(name) + ".<" + ShortKey<K>() + ">", "");
  }
  template <class F>
  void Group(const char* name, F&& fields) {
    Line(Path(name), "object");
    SchemaWriter group(Path(name), out_, of_);
    fields(&group);
  }
  template <class T>
  void Derived(const char* name, const T& value) {
    if constexpr (std::is_same_v<T, std::string>) {
      if (Format(name, value)) return;
    }
    Field<T>(name, " (derived from the fields above, and checked against them when read)");
  }

  // The lines of T's fields under `path`, or one line for a plain type.
  template <class T>
  void Describe(const std::string& path) {
    if constexpr (IsStruct<T>()) {
      T value{};
      SchemaWriter inner(path, out_, of_);
      value.Serialize(&inner);
    } else {
      Line(path, TypeName<T>());
    }
  }

  template <class T>
  std::string TypeName() const {
    if constexpr (std::is_same_v<T, bool>) {
      return "true or false";
    } else if constexpr (std::is_same_v<T, std::string>) {
      return "string";
    } else if constexpr (std::is_enum_v<T>) {
      return "one of " + EnumChoices<T>();
    } else if constexpr (std::is_pointer_v<T>) {
      return "one of " + detail::PointerNamesOf<T>::Choices();
    } else if constexpr (std::is_integral_v<T>) {
      return "integer";
    } else if constexpr (std::is_floating_point_v<T>) {
      return of_ == Of::kInput ? "number" : "number (null where not available)";
    } else if constexpr (std::is_same_v<T, std::complex<double>>) {
      return "{re, im}";
    } else if constexpr (detail::IsOptional<T>::value) {
      if constexpr (std::is_floating_point_v<typename T::value_type>) return "number or null";
      return TypeName<typename T::value_type>() + " or null";
    } else if constexpr (detail::IsVector<T>::value) {
      return "list of " + TypeName<typename T::value_type>();
    } else if constexpr (detail::IsPair<T>::value) {
      return "[" + TypeName<typename T::first_type>() + ", " +
             TypeName<typename T::second_type>() + "]";
    } else if constexpr (detail::IsMap<T>::value) {
      return "object keyed by " + KeyName<typename T::key_type>() + " of " +
             TypeName<typename T::mapped_type>();
    } else if constexpr (detail::IsEigen<T>::value) {
      return T::ColsAtCompileTime == 1 ? "list of numbers" : "list of rows (lists of numbers)";
    } else if constexpr (detail::IsVariant<T>::value) {
      return VariantName<T, 0>();
    } else {
      return "object";
    }
  }
  // "A or B or ...", the alternatives from I on.
  template <class T, size_t I>
  std::string VariantName() const {
    const std::string here = TypeName<std::variant_alternative_t<I, T>>();
    if constexpr (I + 1 < std::variant_size_v<T>) {
      return here + " or " + VariantName<T, I + 1>();
    } else {
      return here;
    }
  }

 private:
  template <class T>
  static constexpr bool IsStruct() {
    return std::is_class_v<T> && !std::is_same_v<T, std::string> &&
           !std::is_same_v<T, std::complex<double>> && !detail::IsOptional<T>::value &&
           !detail::IsVector<T>::value && !detail::IsPair<T>::value &&
           !detail::IsMap<T>::value && !detail::IsEigen<T>::value && !detail::IsVariant<T>::value;
  }
  template <class K>
  static std::string KeyName() {
    if constexpr (std::is_enum_v<K>) {
      return "name (" + EnumChoices<K>() + ")";
    } else if constexpr (!std::is_same_v<K, std::string>) {
      return K::kKeyDescription;
    } else {
      return "name";
    }
  }
  template <class K>
  static std::string ShortKey() {
    return std::is_enum_v<K> || !std::is_same_v<K, std::string> ? "name" : "key";
  }
  // An input file's `format`: the string to write, which its reader checks.
  bool Format(const char* name, const std::string& value) {
    if (of_ != Of::kInput || std::string(name) != "format" || value.empty()) return false;
    Line(Path(name), "`\"" + value + "\"` (this string exactly)");
    return true;
  }
  template <class T>
  void Field(const char* name, const std::string& note) {
    Entry<T>(Path(name), note);
  }
  // The line of a value of type T at `path`, and those of its parts.
  template <class T>
  void Entry(const std::string& path, const std::string& note) {
    if constexpr (detail::IsVector<T>::value) {
      if constexpr (IsStruct<typename T::value_type>()) {
        Line(path, "list of objects" + note);
        Describe<typename T::value_type>(path + "[]");
      } else {
        Line(path, TypeName<T>() + note);
      }
    } else if constexpr (detail::IsMap<T>::value) {
      using Key = typename T::key_type;
      Line(path, "object keyed by " + KeyName<Key>() + note);
      Entry<typename T::mapped_type>(path + ".<" + ShortKey<Key>() + ">", "");
    } else if constexpr (IsStruct<T>()) {
      Line(path, "object" + note);
      Describe<T>(path);
    } else if constexpr (std::is_same_v<T, std::complex<double>>) {
      Line(path, "object: a complex number" + note);
      Line(path + ".re", TypeName<double>());
      Line(path + ".im", TypeName<double>());
    } else {
      Line(path, TypeName<T>() + note);
    }
  }
  std::string Path(const std::string& name) const {
    return prefix_.empty() ? name : prefix_ + "." + name;
  }
  void Line(const std::string& path, const std::string& type) {
    *out_ += "- `" + path + "`: " + type + "\n";
  }

  std::string prefix_;
  std::string* out_;
  Of of_;
};

// The schema of report type R as Markdown lines.
template <class R>
std::string ReportSchema() {
  std::string out;
  SchemaWriter writer("", &out);
  R report{};
  report.Serialize(&writer);
  return out;
}

// The same of an input file's fields, `file` as the fields read (a dataset's
// format decides which follow).
template <class T>
std::string InputSchema(T file) {
  std::string out;
  SchemaWriter writer("", &out, SchemaWriter::Of::kInput);
  file.Serialize(&writer);
  return out;
}

}  // namespace ringid

#endif  // RINGID_REPORT_SCHEMA_H_
