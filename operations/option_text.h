// An option's value as text, the one spelling both front ends read: the
// command line's --NAME=TEXT, and the Python module's keyword arguments
// (spelt so first: lists comma-joined, dicts NAME=VALUE or NAME:LO:HI). Each
// reader is false with the one line naming the option, the same from either.
// The archives below walk an option list (operations/options.h): its options
// with their kinds, defaults and meanings, and the setting of one by name.
#ifndef RINGID_OPERATIONS_OPTION_TEXT_H_
#define RINGID_OPERATIONS_OPTION_TEXT_H_

#include <algorithm>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "model/spelling.h"
#include "operations/options.h"

namespace ringid {

// What an option's text must be, before its own reader sees it: the kinds of
// flag gflags keeps (a number's text as gflags reads it).
enum class OptionKind { kBool, kInteger, kNumber, kText };

// Whether `text` is of `kind`: a boolean true, false, 1, 0, yes, no, t, f,
// y, n (any case); an integer in 32 bits (0x for hexadecimal); a number
// strtod reads whole and in range.
bool OfKind(OptionKind kind, const std::string& text);
// "--NAME: bad value 'TEXT' (an integer expected)" and the like.
std::string BadValue(const std::string& name, const std::string& text, OptionKind kind);

// A value from its text; false with the line naming --NAME.
bool OptionFromText(const std::string& name, const std::string& text, bool* value,
                    std::string* error);
bool OptionFromText(const std::string& name, const std::string& text, int* value,
                    std::string* error);
bool OptionFromText(const std::string& name, const std::string& text, double* value,
                    std::string* error);
bool OptionFromText(const std::string& name, const std::string& text, std::string* value,
                    std::string* error);
// X1,X2,...: finite numbers, each >= 0 (> 0 when positive), none twice.
bool OptionFromText(const std::string& name, const std::string& text, NumberList* value,
                    std::string* error);
// NAME=VALUE,...: each a parameter of the catalogue (the nearest named when
// it is not one) and a finite number in its domain (docs/conventions.md §1);
// the last of a name given twice wins.
bool OptionFromText(const std::string& name, const std::string& text, ParameterValues* value,
                    std::string* error);
// EFFECT,...: effects of the catalogue.
bool OptionFromText(const std::string& name, const std::string& text,
                    std::vector<const Effect*>* value, std::string* error);
// NAME,...: parameters of the catalogue.
bool OptionFromText(const std::string& name, const std::string& text,
                    std::vector<Param>* value, std::string* error);
// NAME:LO:HI,...
bool OptionFromText(const std::string& name, const std::string& text, Bounds* value,
                    std::string* error);
// One of the enum's names.
template <class E, class = std::enable_if_t<std::is_enum_v<E>>>
bool OptionFromText(const std::string& name, const std::string& text, E* value,
                    std::string* error) {
  const std::optional<E> parsed = FromString<E>(text);
  if (parsed) *value = *parsed;
  else *error = "--" + name + ": " + UnknownName("value", text, NamesOf<E>());
  return parsed.has_value();
}

// NAME,...: names of the enum, none twice (an empty text: none).
std::vector<std::string> OptionItems(const std::string& text);
template <class E, class = std::enable_if_t<std::is_enum_v<E>>>
bool OptionFromText(const std::string& name, const std::string& text, std::vector<E>* value,
                    std::string* error) {
  std::vector<E> list;
  for (const std::string& item : OptionItems(text)) {
    E e;
    if (!OptionFromText(name, item, &e, error)) return false;
    if (std::find(list.begin(), list.end(), e) != list.end()) {
      *error = "--" + name + ": '" + item + "' given twice";
      return false;
    }
    list.push_back(e);
  }
  *value = list;
  return true;
}

// A value's text, which OptionFromText reads back (numbers as gflags
// writes them, %.17g).
std::string OptionText(bool value);
std::string OptionText(int value);
std::string OptionText(double value);
std::string OptionText(const std::string& value);
std::string OptionText(const NumberList& value);
std::string OptionText(const ParameterValues& value);
std::string OptionText(const std::vector<const Effect*>& value);
std::string OptionText(const std::vector<Param>& value);
std::string OptionText(const Bounds& value);
template <class E, class = std::enable_if_t<std::is_enum_v<E>>>
std::string OptionText(E value) {
  return ToString(value);
}
template <class E, class = std::enable_if_t<std::is_enum_v<E>>>
std::string OptionText(const std::vector<E>& value) {
  std::string text;
  for (E e : value) text += (text.empty() ? "" : ",") + std::string(ToString(e));
  return text;
}

template <class T> struct IsEnumList : std::false_type {};
template <class E, class A>
struct IsEnumList<std::vector<E, A>> : std::is_enum<E> {};

// The values an option takes where the library names them (an enum's names,
// the effects of the catalogue); empty for a free value.
template <class T>
std::vector<std::string> OptionChoices() {
  if constexpr (std::is_enum_v<T>) {
    return NamesOf<T>();
  } else if constexpr (IsEnumList<T>::value) {
    return NamesOf<typename T::value_type>();
  } else if constexpr (std::is_same_v<T, std::vector<const Effect*>>) {
    return EffectNames(EffectCatalogue());
  } else {
    return {};
  }
}

template <class T>
constexpr OptionKind KindOf() {
  if constexpr (std::is_same_v<T, bool>) return OptionKind::kBool;
  else if constexpr (std::is_same_v<T, int>) return OptionKind::kInteger;
  else if constexpr (std::is_same_v<T, double>) return OptionKind::kNumber;
  else return OptionKind::kText;
}

// One option of a list.
struct OptionInfo {
  std::string name;
  OptionKind kind = OptionKind::kText;
  std::string default_text;  // the default value's text
  std::string help;
  std::vector<std::string> choices;  // OptionChoices
};

// Lists the options of a Serialize, with the values they hold as defaults.
class OptionLister {
 public:
  template <class T>
  void Visit(const char* name, T* value, const char* help) {
    options.push_back({name, KindOf<T>(), OptionText(*value), help, OptionChoices<T>()});
  }
  std::vector<OptionInfo> options;
};

// The options of settings S, defaults those of S{}.
template <class S>
std::vector<OptionInfo> OptionsOf() {
  S settings;
  OptionLister lister;
  settings.Serialize(&lister);
  return lister.options;
}

// Every option of the lists of operations/options.h, each once (an option
// several lists take has one meaning: option::Effects, ...), in the order
// the lists first give them.
const std::vector<OptionInfo>& EveryOption();
// The option called `name`, or null.
const OptionInfo* FindOption(const std::string& name);

// Sets the option `name` of a Serialize from `text`.
class OptionSetter {
 public:
  OptionSetter(const std::string& name, const std::string& text, std::string* error)
      : name_(name), text_(text), error_(error) {}
  template <class T>
  void Visit(const char* name, T* value, const char*) {
    if (name_ != name) return;
    found_ = true;
    ok_ = OptionFromText(name_, text_, value, error_);
  }
  bool found() const { return found_; }
  bool ok() const { return ok_; }

 private:
  std::string name_, text_;
  std::string* error_;
  bool found_ = false, ok_ = false;
};

// Sets option `name` of `settings` from its text: false with the line naming
// it when the text is not a value of it, or when S has no such option.
template <class S>
bool SetOption(S* settings, const std::string& name, const std::string& text,
               std::string* error) {
  OptionSetter setter(name, text, error);
  settings->Serialize(&setter);
  if (!setter.found()) *error = "--" + name + ": not an option here";
  return setter.found() && setter.ok();
}

}  // namespace ringid

#endif  // RINGID_OPERATIONS_OPTION_TEXT_H_
