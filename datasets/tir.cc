#include "datasets/tir.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>

#include "datasets/load_failure.h"

namespace ringid {
namespace {

using internal::Fail;  // caught in ParseTir
using internal::Captured;
using internal::Failure;
using internal::Quoted;

std::string Upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string Trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const size_t e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}


// A key, section or column name: a letter or '_', then letters, digits, '_'.
bool ValidName(const std::string& s) {
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  for (const char c : s) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (!(u < 128 && (std::isalnum(u) || c == '_'))) return false;
  }
  return true;
}

// A whole decimal number: [+-] digits [. digits] [e [+-] digits], with digits
// on at least one side of the point. No hex, no inf or nan.
bool NumberSyntax(const std::string& s) {
  size_t i = 0;
  const auto digits = [&] {
    const size_t start = i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    return i - start;
  };
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  size_t mantissa = digits();
  if (i < s.size() && s[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == s.size();
}

// The number `s`, or a failure at `field`.
double Number(const std::string& s, const std::string& field) {
  if (!NumberSyntax(s)) Fail(field, "not a number or a quoted string: " + Quoted(s));
  const double v = std::strtod(s.c_str(), nullptr);
  if (!std::isfinite(v)) Fail(field, "number out of range: " + Quoted(s));
  return v;
}

// `line` without its comment ('$' or '!' outside quotes to the end).
std::string WithoutComment(const std::string& line, const std::string& field) {
  char quote = 0;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '$' || c == '!') {
      return line.substr(0, i);
    }
  }
  if (quote) Fail(field, "unterminated quoted string");
  return line;
}

std::string LineField(int n) { return "line " + std::to_string(n); }

class Parser {
 public:
  Parser(const std::string& text, TirFile* file, const std::vector<std::string>* strict)
      : text_(text), file_(file), strict_(strict) {}

  void Run() {
    size_t start = 0;
    if (text_.compare(0, 3, "\xEF\xBB\xBF") == 0) start = 3;  // a UTF-8 byte order mark
    int n = 0;
    while (start < text_.size() || n == 0) {
      size_t end = text_.find('\n', start);
      if (end == std::string::npos) end = text_.size();
      std::string line = text_.substr(start, end - start);
      ++n;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      Line(line, n);
      start = end + 1;
      if (end == text_.size()) break;
    }
  }

 private:
  // Whether `section` (as written) is read strictly.
  bool Strict(const std::string& section) const {
    if (!strict_ || section.empty()) return true;
    return std::find(strict_->begin(), strict_->end(), Upper(section)) != strict_->end();
  }

  // A line; in a section not read strictly, what cannot be read skips the
  // rest of the section with a note.
  void Line(const std::string& raw, int n) {
    for (const char c : raw) {
      if (c == '\0') Fail(LineField(n), "a NUL byte: not a text file");
      if (static_cast<unsigned char>(c) < 32 && c != '\t') {
        Fail(LineField(n), "a control character: not a text file");
      }
    }
    const std::string head = Trim(raw);
    if (skipping_ && (head.empty() || head[0] != '[')) return;
    try {
      Read(raw, n);
    } catch (const Failure& f) {
      if (Strict(section_) || skipping_) throw;
      file_->notes.push_back(f.field + ": " + f.message + "; the rest of [" + section_ +
                             "] is skipped (ringid does not read it)");
      skipping_ = true;
    }
  }

  void Read(const std::string& raw, int n) {
    // Where an unterminated quote is: the key of its line, if it has one.
    const std::string key = Trim(raw.substr(0, raw.find('=')));
    const std::string where = raw.find('=') != std::string::npos && ValidName(key) && !section_.empty()
                                  ? "[" + section_ + "] " + key + " (" + LineField(n) + ")"
                                  : Context(n);
    const std::string line = Trim(WithoutComment(raw, where));
    if (line.empty()) return;
    switch (line[0]) {
      case '[': return Section(line, n);
      case '(': return Subsection(line, n);
      case '{': return TableHeader(line, n);
      default: break;
    }
    if (line.find('=') != std::string::npos) return Entry(line, n);
    if (table_) return TableRow(line, n);
    Fail(Context(n), "cannot read " + Quoted(line) +
                         " (expected [SECTION], KEY = value, or a comment after $ or !)");
  }

  // "[SECTION] (line N)" inside a section, else "line N".
  std::string Context(int n) const {
    if (section_.empty()) return LineField(n);
    return "[" + section_ + "]" + (subsection_.empty() ? "" : " (" + subsection_ + ")") + " (" +
           LineField(n) + ")";
  }

  // The name between `open` and `close` of a header line.
  std::string HeaderName(const std::string& line, char close, const char* what, int n) {
    if (line.back() != close) {
      Fail(LineField(n), std::string(what) + " header " + Quoted(line) + " is not closed by '" +
                             close + "'");
    }
    const std::string name = Trim(line.substr(1, line.size() - 2));
    if (!ValidName(name)) {
      Fail(LineField(n), std::string(what) + " name " + Quoted(name) +
                             " must be letters, digits and '_'");
    }
    return name;
  }

  void Section(const std::string& line, int n) {
    const std::string name = HeaderName(line, ']', "section", n);
    const auto [it, fresh] = section_lines_.emplace(Upper(name), n);
    skipping_ = false;
    subsection_.clear();
    table_ = nullptr;
    if (!fresh) {
      const std::string message =
          "section appears twice (first on line " + std::to_string(it->second) + ")";
      section_ = name;  // the failure is this section's
      if (Strict(name)) Fail("[" + name + "] (" + LineField(n) + ")", message);
      file_->notes.push_back("[" + name + "] (" + LineField(n) + "): " + message +
                             "; the second is skipped (ringid does not read it)");
      section_ = name;
      skipping_ = true;
      return;
    }
    section_ = name;
    file_->sections.push_back(name);
  }

  void Subsection(const std::string& line, int n) {
    if (section_.empty()) Fail(LineField(n), "a (sub-section) before any [SECTION]");
    const std::string name = HeaderName(line, ')', "sub-section", n);
    const auto [it, fresh] = subsection_lines_.emplace(Upper(section_) + "/" + Upper(name), n);
    if (!fresh) {
      Fail("[" + section_ + "] (" + name + ") (" + LineField(n) + ")",
           "sub-section appears twice in its section (first on line " +
               std::to_string(it->second) + ")");
    }
    subsection_ = name;
    table_ = nullptr;
  }

  void TableHeader(const std::string& line, int n) {
    if (section_.empty()) Fail(LineField(n), "a {table} before any [SECTION]");
    if (line.back() != '}') Fail(Context(n), "table header " + Quoted(line) + " is not closed by '}'");
    TirTable t;
    t.section = section_;
    t.line = n;
    std::string name;
    for (const char c : line.substr(1, line.size() - 2) + " ") {
      if (c != ' ' && c != '\t') {
        name += c;
        continue;
      }
      if (name.empty()) continue;
      if (!ValidName(name)) {
        Fail(Context(n), "table column " + Quoted(name) + " must be letters, digits and '_'");
      }
      t.columns.push_back(name);
      name.clear();
    }
    if (t.columns.empty()) Fail(Context(n), "table header names no column");
    file_->tables.push_back(t);
    table_ = &file_->tables.back();
  }

  void TableRow(const std::string& line, int n) {
    std::vector<double> row;
    std::string token;
    for (const char c : line + " ") {
      if (c != ' ' && c != '\t') {
        token += c;
        continue;
      }
      if (token.empty()) continue;
      row.push_back(Number(token, Context(n)));
      token.clear();
    }
    if (row.size() != table_->columns.size()) {
      Fail(Context(n), "table row has " + std::to_string(row.size()) + " numbers for " +
                           std::to_string(table_->columns.size()) + " columns (header on line " +
                           std::to_string(table_->line) + ")");
    }
    table_->rows.push_back(row);
  }

  void Entry(const std::string& line, int n) {
    const size_t eq = line.find('=');
    TirEntry e;
    e.section = section_;
    e.subsection = subsection_;
    e.key = Trim(line.substr(0, eq));
    e.line = n;
    if (!ValidName(e.key)) {
      Fail(Context(n), "key " + Quoted(e.key) + " must be letters, digits and '_'");
    }
    if (section_.empty()) Fail(e.key + " (" + LineField(n) + ")", "KEY = value before any [SECTION]");
    table_ = nullptr;
    const std::string value = Trim(line.substr(eq + 1));
    if (value.empty()) Fail(e.Where(), "missing value");
    if (value[0] == '\'' || value[0] == '"') {
      const size_t close = value.find(value[0], 1);  // WithoutComment found it
      e.text = value.substr(1, close - 1);
      if (!Trim(value.substr(close + 1)).empty()) {
        Fail(e.Where(), "unexpected text after the quoted string: " + Quoted(value.substr(close + 1)));
      }
    } else {
      e.number = Number(value, e.Where());
    }
    const std::string id = Upper(section_) + "/" + Upper(subsection_) + "/" + Upper(e.key);
    const auto [it, fresh] = key_lines_.emplace(id, n);
    if (!fresh) {
      Fail(e.Where(), "key appears twice in its section (first on line " +
                          std::to_string(it->second) + ")");
    }
    file_->entries.push_back(e);
  }

  const std::string& text_;
  TirFile* file_;
  std::string section_, subsection_;
  TirTable* table_ = nullptr;  // the table whose rows follow, if any
  const std::vector<std::string>* strict_;  // upper case; nullptr: every section
  bool skipping_ = false;  // the rest of a lenient section that could not be read
  std::map<std::string, int> section_lines_, subsection_lines_, key_lines_;
};

}  // namespace

std::string TirEntry::Where() const {
  return "[" + section + "]" + (subsection.empty() ? "" : " (" + subsection + ")") + " " + key +
         " (line " + std::to_string(line) + ")";
}

const TirEntry* TirFile::Find(const std::string& section, const std::string& key) const {
  for (const TirEntry& e : entries) {
    if (e.subsection.empty() && Upper(e.section) == Upper(section) && Upper(e.key) == Upper(key)) {
      return &e;
    }
  }
  return nullptr;
}

bool TirFile::HasSection(const std::string& section) const {
  for (const std::string& s : sections) {
    if (Upper(s) == Upper(section)) return true;
  }
  return false;
}

bool ParseTir(const std::string& text, const std::string& path, TirFile* file,
              LoadError* error, const std::vector<std::string>* strict_sections) {
  *file = TirFile{};
  file->path = path;
  error->file = path;
  error->field.clear();
  error->message.clear();
  return Captured(error, [&] { Parser(text, file, strict_sections).Run(); });
}

bool LoadTir(const std::string& path, TirFile* file, LoadError* error,
             const std::vector<std::string>* strict_sections) {
  std::string text;
  return ReadInputFile(path, &text, error) &&
         ParseTir(text, path, file, error, strict_sections);
}

std::string TirNumber(double v) {
  char buffer[40];
  int digits = 1;
  for (; digits < 17; ++digits) {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
    if (std::strtod(buffer, nullptr) == v) break;
  }
  // Whole numbers below 1e17 in full (4000, not 4e+03).
  const double magnitude = std::abs(v);
  if (magnitude >= 1 && magnitude < 1e17) {
    digits = std::max(digits, static_cast<int>(std::floor(std::log10(magnitude))) + 1);
  }
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
  return buffer;
}

std::string ShortNumber(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

}  // namespace ringid
