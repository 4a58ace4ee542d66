// The cursor of the UFF reader (datasets/uff_internal.h).
#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "datasets/uff_internal.h"

namespace ringid::uff_internal {
namespace {

bool Blank(std::string_view s) { return Trim(s).empty(); }

// Columns [begin, begin + width) of `line`, clipped to its length.
std::string_view Column(std::string_view line, size_t begin, size_t width) {
  if (begin >= line.size()) return {};
  return line.substr(begin, width);
}

// Digits, and how many.
size_t Digits(std::string_view s, size_t* i) {
  const size_t start = *i;
  while (*i < s.size() && std::isdigit(static_cast<unsigned char>(s[*i]))) ++*i;
  return *i - start;
}

// A Fortran real: [+-] digits [. digits] [exponent], with digits on at least
// one side of the point; the exponent (E|D) [+-] digits, or +-digits alone
// (how Fortran writes a three-digit exponent: "1.00000-100"). No hex, inf or
// nan. Sets `*exponent` to where the exponent's sign or letter is (npos: none).
bool RealSyntax(std::string_view s, size_t* exponent) {
  size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  size_t mantissa = Digits(s, &i);
  if (i < s.size() && s[i] == '.') {
    ++i;
    mantissa += Digits(s, &i);
  }
  if (mantissa == 0) return false;
  *exponent = i < s.size() ? i : std::string_view::npos;
  if (i < s.size() && std::strchr("EeDd+-", s[i]) != nullptr) {
    const bool letter = std::isalpha(static_cast<unsigned char>(s[i]));
    ++i;
    if (letter && i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    if (Digits(s, &i) == 0) return false;
  }
  return i == s.size();
}

// A Fortran integer of at most 18 digits: [+-] digits.
bool IntSyntax(std::string_view s) {
  size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  const size_t n = Digits(s, &i);
  return n > 0 && n <= 18 && i == s.size();
}

}  // namespace

std::string_view Trim(std::string_view s) {
  const size_t b = s.find_first_not_of(" \t");
  if (b == std::string_view::npos) return {};
  const size_t e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

bool IsDelimiter(std::string_view line) {
  const size_t b = line.find_first_not_of(' ');
  return b != std::string_view::npos && b + 2 <= 6 && line.substr(b, 2) == "-1" &&
         Blank(line.substr(b + 2));
}

Line Reader::PeekLine() const {
  size_t end = bytes_.find('\n', pos_);
  if (end == std::string::npos) end = bytes_.size();
  std::string_view text(bytes_.data() + pos_, end - pos_);
  if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
  return {text, line_};
}

Line Reader::NextLine() {
  const Line l = PeekLine();
  const size_t end = bytes_.find('\n', pos_);
  pos_ = end == std::string::npos ? bytes_.size() : end + 1;
  ++line_;
  return l;
}

void Reader::SkipBytes(size_t n) {
  line_ += static_cast<int>(std::count(bytes_.begin() + pos_, bytes_.begin() + pos_ + n, '\n'));
  pos_ += n;
}

void Reader::CheckText(const Line& line, const std::string& field) {
  for (const char c : line.text) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u < 32 && c != '\t') {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02X", u);
      Fail(field, std::string("a control character (byte ") + hex + ") where a text line must be");
    }
  }
}

void Reader::BeginDataset(const std::string& number, int ordinal, int line) {
  dataset_ = "dataset " + number + " #" + std::to_string(ordinal) + " (line " +
             std::to_string(line) + ")";
}

std::string Reader::Field(const std::string& record, int line) const {
  return dataset_ + " " + record + " (line " + std::to_string(line) + ")";
}

Line Reader::Record(const std::string& record) {
  if (AtEnd()) {
    Fail(Field(record, line_), "missing: the file ends (the dataset is not closed by '    -1')");
  }
  const Line l = NextLine();
  if (IsDelimiter(l.text)) Fail(Field(record, l.number), "missing: the dataset closes here");
  CheckText(l, Field(record, l.number));
  return l;
}

bool Reader::AtClose() const {
  if (AtEnd()) {
    Fail(dataset_, "not closed by '    -1': the file ends at line " + std::to_string(line_));
  }
  return IsDelimiter(PeekLine().text);
}

void Reader::Close(const std::string& last_record) {
  if (AtClose()) {
    NextLine();
    return;
  }
  const Line l = PeekLine();
  Fail(Field("after " + last_record, l.number),
       "expected '    -1' closing the dataset, found " + Quoted(l.text));
}

void Reader::CloseAfterBinary(const std::string& last_record) {
  if (!AtEnd() && PeekLine().text.empty()) NextLine();  // one line ending
  if (AtEnd()) {
    Fail(dataset_, "not closed by '    -1': the file ends right after the binary data");
  }
  const Line l = PeekLine();
  if (!IsDelimiter(l.text)) {
    Fail(Field("after " + last_record, l.number),
         "expected '    -1' right after the binary data, found " + Quoted(l.text));
  }
  NextLine();
}

std::string Reader::Text(const Line& l, size_t begin, size_t width) {
  return std::string(Trim(Column(l.text, begin, width)));
}

std::optional<int64_t> Reader::OptionalInt(const Line& l, const std::string& record, size_t begin,
                                           size_t width, const std::string& what) const {
  const std::string_view s = Trim(Column(l.text, begin, width));
  if (s.empty()) return std::nullopt;
  if (!IntSyntax(s)) Fail(Field(record, l.number), what + ": not an integer: " + Quoted(s));
  return std::strtoll(std::string(s).c_str(), nullptr, 10);
}

int64_t Reader::Int64(const Line& l, const std::string& record, size_t begin, size_t width,
                      const std::string& what) const {
  const std::optional<int64_t> v = OptionalInt(l, record, begin, width, what);
  if (!v) Fail(Field(record, l.number), what + ": missing (blank)");
  return *v;
}

int Reader::Int(const Line& l, const std::string& record, size_t begin, size_t width,
                const std::string& what) const {
  const int64_t v = Int64(l, record, begin, width, what);
  if (v < INT_MIN || v > INT_MAX) {
    Fail(Field(record, l.number), what + ": out of range: " + std::to_string(v));
  }
  return static_cast<int>(v);
}

double Reader::Real(const Line& l, const std::string& record, size_t begin, size_t width,
                    const std::string& what) const {
  const std::string_view s = Trim(Column(l.text, begin, width));
  if (s.empty()) Fail(Field(record, l.number), what + ": missing (blank)");
  size_t exponent = 0;
  if (!RealSyntax(s, &exponent)) {
    Fail(Field(record, l.number), what + ": not a number: " + Quoted(s));
  }
  std::string t(s);
  if (exponent != std::string::npos) {
    if (t[exponent] == '+' || t[exponent] == '-') {
      t.insert(exponent, "E");
    } else {
      t[exponent] = 'E';
    }
  }
  const double v = std::strtod(t.c_str(), nullptr);
  if (!std::isfinite(v)) Fail(Field(record, l.number), what + ": out of range: " + Quoted(s));
  return v;
}

void Reader::NothingAfter(const Line& l, const std::string& record, size_t end) const {
  const std::string_view rest = Column(l.text, end, std::string_view::npos);
  if (!Blank(rest)) {
    Fail(Field(record, l.number), "unexpected text after column " + std::to_string(end) + ": " +
                                      Quoted(Trim(rest)));
  }
}

std::vector<double> Reader::Reals(const std::string& record, size_t count,
                                  const std::vector<size_t>& widths) {
  const size_t narrowest = *std::min_element(widths.begin(), widths.end());
  std::vector<double> out;
  out.reserve(std::min(count, Remaining() / narrowest + 1));
  while (out.size() < count) {
    const Line l = Record(record);
    size_t column = 0;
    for (size_t k = 0; k < widths.size() && out.size() < count; ++k) {
      out.push_back(Real(l, record, column, widths[k], "value " + std::to_string(out.size() + 1)));
      column += widths[k];
    }
    NothingAfter(l, record, column);
  }
  return out;
}

void CheckRange(const Reader& r, const std::string& record, const Line& l,
                const std::string& what, int64_t value, int64_t lo, int64_t hi) {
  if (value < lo || value > hi) {
    Fail(r.Field(record, l.number), what + " must be " + std::to_string(lo) + " to " +
                                        std::to_string(hi) + ", not " + std::to_string(value));
  }
}

BinaryHeader ReadBinaryHeader(const Reader& r, const Line& n) {
  const std::string rec = "number line";
  BinaryHeader h;
  h.byte_order = r.Int(n, rec, 7, 6, "field 3 (byte ordering)");
  h.float_format = r.Int(n, rec, 13, 6, "field 4 (floating-point format)");
  h.ascii_lines = r.Int(n, rec, 19, 12, "field 5 (number of ASCII lines)");
  h.bytes = r.Int64(n, rec, 31, 12, "field 6 (number of bytes)");
  r.OptionalInt(n, rec, 43, 6, "field 7 (unused)");
  r.OptionalInt(n, rec, 49, 6, "field 8 (unused)");
  r.OptionalInt(n, rec, 55, 12, "field 9 (unused)");
  r.OptionalInt(n, rec, 67, 12, "field 10 (unused)");
  r.NothingAfter(n, rec, 79);
  if (h.ascii_lines < 0) Fail(r.Field(rec, n.number), "negative number of ASCII lines");
  if (h.bytes < 0) Fail(r.Field(rec, n.number), "negative number of bytes");
  return h;
}

}  // namespace ringid::uff_internal
