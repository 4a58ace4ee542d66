#include "apps/html/text.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace ringid::html {

std::string Format(double value, const char* format) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

std::string StreamFormat(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string Join(const std::vector<std::string>& items, const std::string& separator) {
  std::string out;
  for (size_t i = 0; i < items.size(); ++i) out += (i ? separator : "") + items[i];
  return out;
}

void AppendOnce(std::vector<std::string>* list, const std::string& item) {
  if (std::find(list->begin(), list->end(), item) == list->end()) list->push_back(item);
}

}  // namespace ringid::html
