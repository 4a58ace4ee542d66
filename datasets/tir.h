// The syntax of a tire property file (.tir, the TeimOrbit format of ADAMS and
// MF-Tyre/MF-Swift), strictly: what this reader cannot read is refused with
// one line naming the file, the line, the section and the key. What the
// entries mean for the rigid-ring model is in datasets/tir_parameters.h.
//
// The syntax read:
//   $ comment            ! comment        (anywhere outside quotes, to the end of the line)
//   [SECTION]            a section header; every entry belongs to the last one
//   (SUB_SECTION)        a sub-section header inside a section
//   KEY = value          value: a number (12, -9.81, 1.0E-4) or a quoted string
//                        ('meter' or "meter"), then only blanks or a comment
//   {col_a col_b}        a table header; the lines after it up to the next
//                        header hold one number per column
// Keys and section names are letters, digits and '_'; they are matched without
// regard to case (tools write them in upper case), and a key appears at most
// once in its (sub-)section, a section at most once in the file. Given the
// sections a reader uses, the rest are read leniently: what cannot be read
// there (a section given twice, rows without a {header}, quoted rows) skips
// the rest of that section with a note.
#ifndef RINGID_DATASETS_TIR_H_
#define RINGID_DATASETS_TIR_H_

#include <optional>
#include <string>
#include <vector>

#include "datasets/dataset.h"

namespace ringid {

struct TirEntry {
  std::string section;     // as written, without brackets: "STRUCTURAL"
  std::string subsection;  // as written, without parentheses; usually empty
  std::string key;         // as written: "FREQ_LONG"
  std::optional<double> number;  // set for a number
  std::string text;              // a quoted string, without its quotes
  int line = 0;                  // 1-based

  // "[STRUCTURAL] FREQ_LONG (line 12)": how messages name the entry.
  std::string Where() const;
};

// A table of a section: column names and rows of numbers (e.g. [SHAPE]).
struct TirTable {
  std::string section;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  int line = 0;  // of its {header}
};

struct TirFile {
  std::string path;
  std::vector<std::string> sections;  // as written, in file order
  std::vector<TirEntry> entries;      // in file order
  std::vector<TirTable> tables;
  // What lenient reading skipped: "[SHAPE] (line 71): cannot read ...; the
  // rest of [SHAPE] is skipped (ringid does not read it)".
  std::vector<std::string> notes;

  // The entry KEY of [SECTION] (outside any sub-section), matched without
  // regard to case; nullptr when absent.
  const TirEntry* Find(const std::string& section, const std::string& key) const;
  bool HasSection(const std::string& section) const;
};

// Parses .tir text; `path` only names it in messages. On failure returns false
// with `error` set (field: "[SECTION] KEY (line N)" or "line N") and `file`
// unspecified. `strict_sections` (upper case): the sections read strictly,
// the others leniently; nullptr: every section strictly.
bool ParseTir(const std::string& text, const std::string& path, TirFile* file,
              LoadError* error, const std::vector<std::string>* strict_sections = nullptr);
// Reads (at most kMaxFileBytes) and parses a .tir file.
bool LoadTir(const std::string& path, TirFile* file, LoadError* error,
             const std::vector<std::string>* strict_sections = nullptr);

// The shortest decimal text that reads back as exactly `v` (at most 17
// significant digits), as .tir values are written.
std::string TirNumber(double v);
// `v` to six significant digits, as messages and notes give a value.
std::string ShortNumber(double v);

}  // namespace ringid

#endif  // RINGID_DATASETS_TIR_H_
