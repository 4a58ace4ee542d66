// The .tir syntax: the parser reads what tools write and refuses the rest with
// one line naming file, line, section and key.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "datasets/dataset.h"
#include "datasets/tir.h"

namespace ringid {
namespace {

TirFile Parse(const std::string& text) {
  TirFile f;
  LoadError e;
  EXPECT_TRUE(ParseTir(text, "t.tir", &f, &e)) << e.OneLine();
  return f;
}

double Value(const TirFile& f, const char* section, const char* key) {
  const TirEntry* e = f.Find(section, key);
  EXPECT_TRUE(e && e->number) << section << " " << key;
  return e && e->number ? *e->number : NAN;
}

// ---- the syntax -----------------------------------------------------------

TEST(TirParserTest, ReadsSectionsKeysNumbersStringsCommentsAndTablesAsToolsWriteThem) {
  const std::string text =
      "\xEF\xBB\xBF[MDI_HEADER]\r\n"
      "FILE_TYPE                ='tir'\r\n"
      "FILE_VERSION             =3.0\r\n"
      "! : TIRE_VERSION :      MF-Swift 6.2\n"
      "$------------------------------------------------------------------units\n"
      "[UNITS]\n"
      "LENGTH                   = 'meter'\n"
      "\tFORCE = \"newton\"   ! trailing comment\n"
      "[MODEL]\n"
      "PROPERTY_FILE_FORMAT     ='MF_SWIFT'\n"
      "COMMENT                  = 'costs $5 ! not a comment'  $ but this is\n"
      "[INERTIA]\n"
      "belt_mass                = 7.698 $Belt mass\n"
      "BELT_IXX                 = .3519\n"
      "BELT_IYY=+4.889E-1\n"
      "GRAVITY                  = -9.81\n"
      "[SHAPE]\n"
      "{radial width}\n"
      " 1.0    0.0\n"
      " 0.9\t1.0   $ a row\n"
      "[VERTICAL_FORCE_RANGE]\n"
      "(XY_DATA)\n"
      "FZMIN = 100\n";
  const TirFile f = Parse(text);
  EXPECT_EQ(f.sections, (std::vector<std::string>{"MDI_HEADER", "UNITS", "MODEL", "INERTIA",
                                                  "SHAPE", "VERTICAL_FORCE_RANGE"}));
  ASSERT_TRUE(f.Find("mdi_header", "file_type"));
  EXPECT_EQ(f.Find("MDI_HEADER", "FILE_TYPE")->text, "tir");
  EXPECT_EQ(Value(f, "MDI_HEADER", "FILE_VERSION"), 3.0);
  EXPECT_EQ(f.Find("UNITS", "FORCE")->text, "newton");
  EXPECT_EQ(f.Find("MODEL", "COMMENT")->text, "costs $5 ! not a comment");
  EXPECT_EQ(Value(f, "INERTIA", "BELT_MASS"), 7.698);
  EXPECT_EQ(f.Find("INERTIA", "BELT_MASS")->key, "belt_mass");  // as written
  EXPECT_EQ(f.Find("INERTIA", "BELT_MASS")->line, 13);
  EXPECT_EQ(Value(f, "INERTIA", "BELT_IXX"), 0.3519);
  EXPECT_EQ(Value(f, "INERTIA", "BELT_IYY"), 0.4889);
  EXPECT_EQ(Value(f, "INERTIA", "GRAVITY"), -9.81);
  ASSERT_EQ(f.tables.size(), 1u);
  EXPECT_EQ(f.tables[0].section, "SHAPE");
  EXPECT_EQ(f.tables[0].columns, (std::vector<std::string>{"radial", "width"}));
  EXPECT_EQ(f.tables[0].rows, (std::vector<std::vector<double>>{{1.0, 0.0}, {0.9, 1.0}}));
  EXPECT_EQ(f.Find("VERTICAL_FORCE_RANGE", "FZMIN"), nullptr);  // inside a sub-section
  EXPECT_EQ(f.entries.back().subsection, "XY_DATA");
  EXPECT_EQ(f.Find("INERTIA", "FREQ_LONG"), nullptr);
}

// Every defect: ParseTir refuses it, and the one line names the file and
// where: the line, and the section and key where it has them.
TEST(TirParserTest, RefusesWhatItCannotReadWithOneLineNamingLineSectionAndKey) {
  struct Case {
    std::string what, text, field, words;
  };
  const Case cases[] = {
      {"unterminated string", "[UNITS]\nLENGTH = 'meter\n", "[UNITS] LENGTH (line 2)", "unterminated"},
      {"key before any section", "FREQ_LONG = 76.63\n", "FREQ_LONG (line 1)", "before any [SECTION]"},
      {"section not closed", "[UNITS\n", "line 1", "not closed"},
      {"bad section name", "[UN ITS]\n", "line 1", "letters, digits"},
      {"empty section name", "[]\n", "line 1", "letters, digits"},
      {"section twice", "[A]\nX = 1\n[a]\n", "[a] (line 3)", "appears twice (first on line 1)"},
      {"key twice, other case", "[A]\nX = 1\nx = 2\n", "[A] x (line 3)", "appears twice in its section (first on line 2)"},
      {"missing value", "[A]\nX =\n", "[A] X (line 2)", "missing value"},
      {"missing value before comment", "[A]\nX = $ 5\n", "[A] X (line 2)", "missing value"},
      {"number with a unit", "[A]\nX = 7.7kg\n", "[A] X (line 2)", "not a number"},
      {"two numbers", "[A]\nX = 1 2\n", "[A] X (line 2)", "not a number"},
      {"bare word", "[A]\nX = meter\n", "[A] X (line 2)", "not a number or a quoted string"},
      {"hexadecimal", "[A]\nX = 0x10\n", "[A] X (line 2)", "not a number"},
      {"nan", "[A]\nX = nan\n", "[A] X (line 2)", "not a number"},
      {"infinity", "[A]\nX = inf\n", "[A] X (line 2)", "not a number"},
      {"out of range", "[A]\nX = 1e999\n", "[A] X (line 2)", "out of range"},
      {"two points", "[A]\nX = 1.2.3\n", "[A] X (line 2)", "not a number"},
      {"lone sign", "[A]\nX = -\n", "[A] X (line 2)", "not a number"},
      {"exponent without digits", "[A]\nX = 1e\n", "[A] X (line 2)", "not a number"},
      {"text after a string", "[A]\nX = 'a' 'b'\n", "[A] X (line 2)", "unexpected text"},
      {"key with a blank", "[A]\nFREQ LONG = 3\n", "[A] (line 2)", "key 'FREQ LONG'"},
      {"empty key", "[A]\n= 3\n", "[A] (line 2)", "key ''"},
      {"a line of nothing known", "[A]\nhello world\n", "[A] (line 2)", "cannot read 'hello world'"},
      {"table row too short", "[SHAPE]\n{radial width}\n1.0\n", "[SHAPE] (line 3)",
       "1 numbers for 2 columns"},
      {"table row not numbers", "[SHAPE]\n{radial width}\n1.0 wide\n", "[SHAPE] (line 3)",
       "not a number"},
      {"table header not closed", "[SHAPE]\n{radial width\n", "[SHAPE] (line 2)", "not closed"},
      {"table without columns", "[SHAPE]\n{ }\n", "[SHAPE] (line 2)", "names no column"},
      {"table before any section", "{a b}\n", "line 1", "before any [SECTION]"},
      {"sub-section before any section", "(XY)\n", "line 1", "before any [SECTION]"},
      {"sub-section twice", "[A]\n(XY)\n(xy)\n", "[A] (xy) (line 3)", "appears twice"},
      {"NUL byte", std::string("[A]\nX = 1\0\n", 10), "line 2", "NUL byte"},
      {"control character", "[A]\nX = 1\x01\n", "line 2", "control character"},
      {"binary", "\x7f" "ELF\x02\x01\x01", "line 1", "control character"},
  };
  for (const Case& c : cases) {
    TirFile f;
    LoadError e;
    EXPECT_FALSE(ParseTir(c.text, "bad.tir", &f, &e)) << c.what;
    const std::string line = e.OneLine();
    EXPECT_EQ(line.rfind("bad.tir: " + c.field + ": ", 0), 0u) << c.what << ": " << line;
    EXPECT_NE(line.find(c.words), std::string::npos) << c.what << ": " << line;
    EXPECT_EQ(line.find('\n'), std::string::npos) << c.what;
  }
}

TEST(TirParserTest, NumbersAreWrittenAsTheShortestTextThatReadsBackExactly) {
  EXPECT_EQ(TirNumber(76.63), "76.63");
  EXPECT_EQ(TirNumber(4000), "4000");
  EXPECT_EQ(TirNumber(0.1), "0.1");
  EXPECT_EQ(TirNumber(1e-5), "1e-05");
  EXPECT_EQ(TirNumber(1784577.013066446), "1784577.013066446");
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> exponent(-300, 300), mantissa(1, 10);
  for (int i = 0; i < 2000; ++i) {
    const double v = mantissa(rng) * std::pow(10.0, exponent(rng));
    const std::string text = TirNumber(v);
    const TirFile f = Parse("[A]\nX = " + text + "\n");
    EXPECT_EQ(Value(f, "A", "X"), v) << text;
  }
}

}  // namespace
}  // namespace ringid
