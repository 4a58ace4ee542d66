// Plain-text helpers shared by the page and figure toolkits.
#ifndef RINGID_APPS_HTML_TEXT_H_
#define RINGID_APPS_HTML_TEXT_H_

#include <string>
#include <vector>

namespace ringid::html {

// `value` printed with a printf `format` for one double.
std::string Format(double value, const char* format = "%.4g");

// `value` as an std::ostream prints it (6 significant digits).
std::string StreamFormat(double value);

std::string Join(const std::vector<std::string>& items, const std::string& separator);

// Appends `item` to `list` unless it is there already.
void AppendOnce(std::vector<std::string>* list, const std::string& item);

}  // namespace ringid::html

#endif  // RINGID_APPS_HTML_TEXT_H_
