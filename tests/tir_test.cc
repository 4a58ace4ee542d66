// The .tir interchange (docs/tir.md): the parser reads what tools write and
// refuses the rest with one line naming file, line, section and key; the
// rigid-ring keys are the model's own belt modes and static stiffnesses;
// export then import gives back every parameter the format holds; the public
// TNO 205/60R15 belt reads as the model's stiffnesses.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "datasets/dataset.h"
#include "datasets/synthetic.h"
#include "datasets/tir.h"
#include "datasets/tir_parameters.h"
#include "model/rigid_ring_model.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using P = Param;
constexpr double kTwoPi = 2 * M_PI;

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

std::string Export(const Parameters& p) {
  std::string text;
  LoadError e;
  EXPECT_TRUE(ParametersToTir(p, "tire", "tire.json", &text, &e)) << e.OneLine();
  return text;
}

Parameters Import(const std::string& text) {
  Parameters p;
  LoadError e;
  EXPECT_TRUE(TirToParameters(Parse(text), &p, &e)) << e.OneLine();
  return p;
}

double Relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

int Count(const std::string& text, const std::string& word) {
  int n = 0;
  for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
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

// ---- the mapping ----------------------------------------------------------

// FREQ_* and DAMP_* against their closed forms, written out here.
TEST(TirMappingTest, FrequenciesAndDampingAreTheClosedFormsOfTheBeltElements) {
  const Parameters p = ExampleCarTire();
  const TirFile f = Parse(Export(p));
  const auto freq = [](double k, double m) { return std::sqrt(k / m) / (2 * M_PI); };
  const auto damp = [](double c, double k, double m) { return c / (2 * std::sqrt(k * m)); };
  EXPECT_NEAR(Value(f, "STRUCTURAL", "FREQ_LONG"), freq(p[P::k_bx], p[P::m_b]), 1e-12);
  EXPECT_NEAR(Value(f, "STRUCTURAL", "FREQ_LAT"), freq(p[P::k_by], p[P::m_b]), 1e-12);
  EXPECT_NEAR(Value(f, "STRUCTURAL", "FREQ_YAW"), freq(p[P::k_bpsi], p[P::I_bz]), 1e-12);
  EXPECT_NEAR(Value(f, "STRUCTURAL", "FREQ_WINDUP"), freq(p[P::k_btheta], p[P::I_by]), 1e-12);
  EXPECT_NEAR(Value(f, "STRUCTURAL", "DAMP_LONG"), damp(p[P::c_bx], p[P::k_bx], p[P::m_b]), 1e-15);
  EXPECT_NEAR(Value(f, "STRUCTURAL", "DAMP_LAT"), damp(p[P::c_by], p[P::k_by], p[P::m_b]), 1e-15);
  EXPECT_NEAR(Value(f, "STRUCTURAL", "DAMP_YAW"), damp(p[P::c_bpsi], p[P::k_bpsi], p[P::I_bz]), 1e-15);
  EXPECT_NEAR(Value(f, "STRUCTURAL", "DAMP_WINDUP"),
              damp(p[P::c_btheta], p[P::k_btheta], p[P::I_by]), 1e-15);
  // ExampleCarTire was built from the TNO belt frequencies and 5 % damping.
  EXPECT_NEAR(Value(f, "STRUCTURAL", "FREQ_LONG"), 76.63, 1e-12);
  EXPECT_NEAR(Value(f, "STRUCTURAL", "FREQ_LAT"), 41.47, 1e-12);
  EXPECT_NEAR(Value(f, "STRUCTURAL", "FREQ_YAW"), 53.46, 1e-12);
  EXPECT_NEAR(Value(f, "STRUCTURAL", "FREQ_WINDUP"), 67.73, 1e-12);
  for (const char* key : {"DAMP_LONG", "DAMP_LAT", "DAMP_YAW", "DAMP_WINDUP"}) {
    EXPECT_NEAR(Value(f, "STRUCTURAL", key), 0.05, 1e-15) << key;
  }
  EXPECT_EQ(f.Find("UNITS", "LENGTH")->text, "meter");
  EXPECT_EQ(f.Find("UNITS", "FORCE")->text, "newton");
  EXPECT_EQ(f.Find("UNITS", "ANGLE")->text, "radians");
  EXPECT_EQ(f.Find("UNITS", "MASS")->text, "kg");
  EXPECT_EQ(f.Find("UNITS", "TIME")->text, "second");
  EXPECT_EQ(Value(f, "INERTIA", "BELT_MASS"), p[P::m_b]);
  EXPECT_EQ(Value(f, "INERTIA", "BELT_IXX"), p[P::I_bx]);
  EXPECT_EQ(Value(f, "INERTIA", "BELT_IYY"), p[P::I_by]);
}

// The model is the truth: with the rim held (I_ay huge) and the road taken
// away (contact stiffnesses and load near 0), each belt mode is a one-degree
// oscillator whose |lambda| / 2 pi is a FREQ_* and whose damping ratio is the
// DAMP_* of the same key; x_b and z_b share FREQ_LONG, camber and yaw FREQ_YAW.
TEST(TirMappingTest, FrequenciesAndDampingAreTheModelsBeltModesOnAFixedRimWithoutRoad) {
  const Parameters car = ExampleCarTire();
  const TirFile f = Parse(Export(car));
  Parameters p = car;
  p[P::I_ay] = 1e12;
  for (Param q : {P::K_cx, P::k_cz, P::K_cy, P::F_cz0}) p[q] = 1e-9;
  const ModalSolution s = RigidRingModel().Solve(p);
  ASSERT_TRUE(s.ok) << s.error;
  const std::pair<const char*, const char*> keys[] = {
      {"FREQ_LONG", "DAMP_LONG"}, {"FREQ_LAT", "DAMP_LAT"},
      {"FREQ_YAW", "DAMP_YAW"}, {"FREQ_WINDUP", "DAMP_WINDUP"}};
  const std::map<std::string, int> expected_modes = {
      {"FREQ_LONG", 2}, {"FREQ_LAT", 1}, {"FREQ_YAW", 2}, {"FREQ_WINDUP", 1}};
  for (const auto& [freq_key, damp_key] : keys) {
    const double freq = Value(f, "STRUCTURAL", freq_key);
    const double damp = Value(f, "STRUCTURAL", damp_key);
    int found = 0;
    for (const Mode& m : s.modes) {
      const double undamped = m.frequency_hz / std::sqrt(1 - m.damping_ratio * m.damping_ratio);
      if (Relative(undamped, freq) > 1e-8) continue;
      ++found;
      EXPECT_NEAR(m.damping_ratio, damp, 1e-8) << damp_key << " at " << m.frequency_hz << " Hz";
    }
    EXPECT_EQ(found, expected_modes.at(freq_key)) << freq_key;
  }
}

// The model is the truth again: the overall stiffnesses are the static force
// on the hub per unit hub displacement from the model's own standing
// stiffness matrix (the sidewalls act on belt minus hub), the belt free, the
// rim's rotation held (wheel locked).
TEST(TirMappingTest, OverallStiffnessesAreTheStaticResponseOfTheModelsStandingStiffness) {
  for (const Parameters& p : {ExampleCarTire(), testing::PaperIdentified()}) {
    const TirFile f = Parse(Export(p));
    const Eigen::Matrix<double, kNumDofs, kNumDofs> K = RigidRingModel().Assemble(p).K();
    const std::vector<Dof> belt = {Dof::kXb, Dof::kZb, Dof::kThetaB,
                                   Dof::kYb, Dof::kGammaB, Dof::kPsiB};
    const auto stiffness = [&](Dof hub) {
      const int n = static_cast<int>(belt.size());
      Eigen::MatrixXd Kff(n, n);
      Eigen::VectorXd Kfa(n), Kaf(n);
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) Kff(i, j) = K(static_cast<int>(belt[i]), static_cast<int>(belt[j]));
        Kfa(i) = K(static_cast<int>(belt[i]), static_cast<int>(hub));
        Kaf(i) = K(static_cast<int>(hub), static_cast<int>(belt[i]));
      }
      const Eigen::VectorXd q = Kff.fullPivLu().solve(-Kfa);  // the belt, hub moved by 1
      return K(static_cast<int>(hub), static_cast<int>(hub)) + Kaf.dot(q);
    };
    EXPECT_LT(Relative(Value(f, "STRUCTURAL", "LONGITUDINAL_STIFFNESS"), stiffness(Dof::kXa)), 1e-10);
    EXPECT_LT(Relative(Value(f, "STRUCTURAL", "LATERAL_STIFFNESS"), stiffness(Dof::kYa)), 1e-10);
    EXPECT_LT(Relative(Value(f, "VERTICAL", "VERTICAL_STIFFNESS"), stiffness(Dof::kZa)), 1e-10);
  }
}

// A parameter set that meets every assumption of the format: I_bz = I_bx,
// k_bz = k_bx, c_bz = c_bx, camber and yaw with one frequency and one ratio.
Parameters MeetsTheFormat(std::mt19937_64* rng) {
  std::uniform_real_distribution<double> decades(-3, 3);
  Parameters p = ExampleCarTire();
  for (int i = 0; i < kNumParams; ++i) {
    const Param q = ParamAt(i);
    if (IsBaseline(q) && p.IsSet(q)) p[q] *= std::pow(10.0, decades(*rng));
  }
  p[P::I_bz] = p[P::I_bx];
  p[P::k_bz] = p[P::k_bx];
  p[P::c_bz] = p[P::c_bx];
  p[P::k_bgamma] = p[P::k_bpsi];
  p[P::c_bgamma] = p[P::c_bpsi];
  return p;
}

TEST(TirMappingTest, ExportThenImportGivesBackEveryParameterTheFormatHolds) {
  std::vector<Parameters> sets = {ExampleCarTire()};
  std::mt19937_64 rng(14);
  for (int i = 0; i < 200; ++i) sets.push_back(MeetsTheFormat(&rng));
  const std::vector<Param> not_held = ParametersNotHeldByTir();
  for (const Parameters& p : sets) {
    const Parameters back = Import(Export(p));
    for (Param q : RigidRingModel().parameters()) {
      if (std::find(not_held.begin(), not_held.end(), q) != not_held.end()) {
        EXPECT_FALSE(back.IsSet(q)) << ParamName(q);
      } else {
        // 17 significant digits are written: what is lost is rounding, but
        // k_cz comes back from the series 1/(1/k_bz + 1/k_cz), which holds
        // it only to a relative (1 + k_cz/k_bz) times that.
        const double precision = 1e-12 * (q == P::k_cz ? 1 + p[P::k_cz] / p[P::k_bz] : 1);
        EXPECT_LT(Relative(back[q], p[q]), precision) << ParamName(q) << ": " << back[q] << " vs " << p[q];
      }
    }
  }
  EXPECT_EQ(not_held, (std::vector<Param>{P::I_ay, P::F_cz0, P::K_cx, P::sigma_cx, P::r_e0,
                                          P::K_cy, P::sigma_cy, P::r_l0, P::t_0}));
}

// The paper's tire breaks two assumptions (I_bz != I_bx, so camber and yaw
// differ); a variant breaks k_bz = k_bx. The header says what is held and
// gives the rest; what is read back keeps BELT_IXX = I_bx and the overall
// vertical stiffness.
TEST(TirMappingTest, WhereTheParametersBreakAnAssumptionTheHeaderSaysWhatIsHeld) {
  Parameters p = testing::PaperIdentified();
  p[P::k_bz] = 1.2 * p[P::k_bx];
  const std::string text = Export(p);
  std::vector<std::string> header;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("$ ", 0) == 0) header.push_back(line);
  }
  const auto says = [&](const std::string& words) {
    return std::any_of(header.begin(), header.end(),
                       [&](const std::string& l) { return l.find(words) != std::string::npos; });
  };
  EXPECT_TRUE(says("BELT_IXX holds I_bx; I_bz = " + TirNumber(p[P::I_bz])));
  EXPECT_TRUE(says("FREQ_LONG holds k_bx; k_bz = " + TirNumber(p[P::k_bz])));
  EXPECT_TRUE(says("the camber frequency " +
                   TirNumber(std::sqrt(p[P::k_bgamma] / p[P::I_bx]) / kTwoPi) + " Hz"));
  EXPECT_TRUE(says("the vertical ratio"));  // c_bz = c_bx on a stiffer k_bz
  EXPECT_TRUE(says("K_cx = 10300 N"));      // not held, with its value
  EXPECT_TRUE(says("t_0 = 0.00135 m"));
  EXPECT_TRUE(says("F_cz0 = " + TirNumber(p[P::F_cz0]) + " N"));
  const Parameters back = Import(text);
  EXPECT_EQ(back[P::I_bx], p[P::I_bx]);
  EXPECT_EQ(back[P::I_bz], p[P::I_bx]);
  EXPECT_LT(Relative(back[P::k_bz], p[P::k_bx]), 1e-12);
  const auto series = [](double a, double b) { return 1 / (1 / a + 1 / b); };
  EXPECT_LT(Relative(series(back[P::k_bz], back[P::k_cz]), series(p[P::k_bz], p[P::k_cz])), 1e-12);
  // Nothing to say where every assumption holds.
  const std::string clean = Export(ExampleCarTire());
  for (const char* words : {"holds I_bx", "holds k_bx", "camber frequency", "vertical ratio",
                            "camber ratio", "effect parameters"}) {
    EXPECT_EQ(clean.find(words), std::string::npos) << words;
  }
}

// The public TNO MF-Swift 205/60R15 example's belt, as shipped in
// datasets/examples: k = m (2 pi f)^2 with the mass or inertia of its
// element, the numbers of the example car tire (typed in independently) and
// these, worked out by hand to 5 digits.
TEST(TirMappingTest, TheTnoExampleBeltReadsAsTheModelsStiffnesses) {
  Parameters p;
  LoadError e;
  ASSERT_TRUE(LoadParameters(testing::SourcePath("datasets/examples/tno_205_60R15_belt.tir"), {}, &p, &e))
      << e.OneLine();
  const auto k = [](double m, double f) { return m * std::pow(2 * M_PI * f, 2); };
  EXPECT_EQ(p[P::m_b], 7.698);
  EXPECT_EQ(p[P::I_bx], 0.3519);
  EXPECT_EQ(p[P::I_bz], 0.3519);
  EXPECT_EQ(p[P::I_by], 0.4889);
  EXPECT_LT(Relative(p[P::k_bx], k(7.698, 76.63)), 1e-14);
  EXPECT_LT(Relative(p[P::k_bz], k(7.698, 76.63)), 1e-14);
  EXPECT_LT(Relative(p[P::k_by], k(7.698, 41.47)), 1e-14);
  EXPECT_LT(Relative(p[P::k_bpsi], k(0.3519, 53.46)), 1e-14);
  EXPECT_LT(Relative(p[P::k_bgamma], k(0.3519, 53.46)), 1e-14);
  EXPECT_LT(Relative(p[P::k_btheta], k(0.4889, 67.73)), 1e-14);
  EXPECT_NEAR(p[P::k_bx], 1.7846e6, 50);
  EXPECT_NEAR(p[P::k_by], 5.2264e5, 5);
  EXPECT_NEAR(p[P::k_bpsi], 3.9704e4, 0.5);
  EXPECT_NEAR(p[P::k_btheta], 8.8540e4, 0.5);
  Parameters car;
  ASSERT_TRUE(LoadParameterSet(testing::SourcePath("datasets/examples/car_tire.json"), &car, &e))
      << e.OneLine();
  for (Param q : {P::m_b, P::I_bx, P::I_bz, P::I_by, P::k_bx, P::k_bz, P::k_by, P::k_bgamma,
                  P::k_bpsi, P::k_btheta}) {
    EXPECT_LT(Relative(p[q], car[q]), 1e-14) << ParamName(q);
  }
  // It holds no damping and no vertical stiffness: those stay unset.
  for (Param q : {P::c_bx, P::c_bz, P::c_by, P::c_bgamma, P::c_bpsi, P::c_btheta, P::k_cz}) {
    EXPECT_FALSE(p.IsSet(q)) << ParamName(q);
  }
}

// The rigid-ring part of a fuller file: sections and keys it does not use,
// tables and sub-sections are ignored.
const char kGoodBlock[] =
    "[MDI_HEADER]\nFILE_TYPE = 'tir'\n"
    "[UNITS]\nLENGTH = 'meter'\nFORCE = 'newton'\nANGLE = 'radians'\nMASS = 'kg'\nTIME = 'second'\n"
    "[MODEL]\nFITTYP = 61\nTYRESIDE = 'LEFT'\n"
    "[INERTIA]\nMASS = 9.3\nBELT_MASS = 7.698\nBELT_IXX = 0.3519\nBELT_IYY = 0.4889\n"
    "[VERTICAL]\nFNOMIN = 4000\nVERTICAL_STIFFNESS = 209651\n"
    "[STRUCTURAL]\nLONGITUDINAL_STIFFNESS = 358066\nFREQ_LONG = 76.63\nFREQ_LAT = 41.47\n"
    "FREQ_YAW = 53.46\nFREQ_WINDUP = 67.73\nDAMP_LONG = 0.05\nDAMP_LAT = 0.04\n"
    "DAMP_YAW = 0.1\nDAMP_WINDUP = 0.05\nDAMP_RESIDUAL = 0.002\n"
    "[SHAPE]\n{radial width}\n1.0 0.0\n0.9 1.0\n"
    "[LONGITUDINAL_COEFFICIENTS]\nPCX1 = 1.579\n";

TEST(TirMappingTest, AFullerFileReadsTheRigidRingPartAndIgnoresTheRest) {
  const Parameters p = Import(kGoodBlock);
  const double k_bx = 7.698 * std::pow(2 * M_PI * 76.63, 2);
  EXPECT_LT(Relative(p[P::k_cz], 1 / (1 / 209651.0 - 1 / k_bx)), 1e-14);
  EXPECT_LT(Relative(p[P::c_bx], 2 * 0.05 * std::sqrt(k_bx * 7.698)), 1e-14);
  EXPECT_LT(Relative(p[P::c_bz], p[P::c_bx]), 1e-15);
  const double k_by = 7.698 * std::pow(2 * M_PI * 41.47, 2);
  EXPECT_LT(Relative(p[P::c_by], 2 * 0.04 * std::sqrt(k_by * 7.698)), 1e-14);
  const double k_bpsi = 0.3519 * std::pow(2 * M_PI * 53.46, 2);
  EXPECT_LT(Relative(p[P::c_bpsi], 2 * 0.1 * std::sqrt(k_bpsi * 0.3519)), 1e-14);
  EXPECT_LT(Relative(p[P::c_bgamma], p[P::c_bpsi]), 1e-15);
  const double k_btheta = 0.4889 * std::pow(2 * M_PI * 67.73, 2);
  EXPECT_LT(Relative(p[P::c_btheta], 2 * 0.05 * std::sqrt(k_btheta * 0.4889)), 1e-14);
  for (Param q : ParametersNotHeldByTir()) EXPECT_FALSE(p.IsSet(q)) << ParamName(q);
}

// `kGoodBlock` with `line` (a whole "KEY = value" line, or a section header)
// replaced by `by`; the replaced line must be there.
std::string Broken(const std::string& line, const std::string& by) {
  std::string text = kGoodBlock;
  const size_t at = text.find(line + "\n");
  EXPECT_NE(at, std::string::npos) << line;
  if (at != std::string::npos) text.replace(at, line.size() + 1, by);
  return text;
}

TEST(TirMappingTest, BadRigidRingBlocksAreRefusedNamingTheKey) {
  struct Case {
    std::string what, text, field, words;
  };
  const Case cases[] = {
      {"no units", Broken("[UNITS]", "[UNITZ]\n"), "[UNITS]", "missing"},
      {"millimetres", Broken("LENGTH = 'meter'", "LENGTH = 'mm'\n"), "[UNITS] LENGTH (line 4)",
       "must be 'meter'"},
      {"degrees", Broken("ANGLE = 'radians'", "ANGLE = 'degrees'\n"), "[UNITS] ANGLE (line 6)",
       "must be 'radians'"},
      {"a unit as a number", Broken("TIME = 'second'", "TIME = 1\n"), "[UNITS] TIME (line 8)",
       "must be 'second'"},
      {"no force unit", Broken("FORCE = 'newton'", ""), "[UNITS] FORCE", "missing"},
      {"no belt mass", Broken("BELT_MASS = 7.698", ""), "[INERTIA] BELT_MASS", "missing (ringid reads m_b from it)"},
      {"no lateral frequency", Broken("FREQ_LAT = 41.47", ""), "[STRUCTURAL] FREQ_LAT",
       "missing (ringid reads k_by from it)"},
      {"no structural section", Broken("[STRUCTURAL]", "[STRUCTURAL_X]\n"), "[STRUCTURAL] FREQ_LONG",
       "missing"},
      {"a string for a number", Broken("BELT_MASS = 7.698", "BELT_MASS = 'heavy'\n"),
       "[INERTIA] BELT_MASS (line 14)", "must be a number"},
      {"zero mass", Broken("BELT_MASS = 7.698", "BELT_MASS = 0\n"), "[INERTIA] BELT_MASS (line 14)",
       "must be positive"},
      {"negative frequency", Broken("FREQ_LONG = 76.63", "FREQ_LONG = -76.63\n"),
       "[STRUCTURAL] FREQ_LONG (line 22)", "must be positive"},
      {"zero damping", Broken("DAMP_LAT = 0.04", "DAMP_LAT = 0\n"), "[STRUCTURAL] DAMP_LAT (line 27)",
       "must be positive"},
      {"a frequency whose stiffness overflows", Broken("FREQ_LONG = 76.63", "FREQ_LONG = 1e200\n"),
       "[STRUCTURAL] FREQ_LONG (line 22)", "gives k_bx = inf"},
      {"a vertical stiffness above the sidewall's", Broken("VERTICAL_STIFFNESS = 209651",
                                                           "VERTICAL_STIFFNESS = 2e6\n"),
       "[VERTICAL] VERTICAL_STIFFNESS (line 19)", "gives k_cz = -"},
      {"a vertical stiffness equal to the sidewall's",
       Broken("VERTICAL_STIFFNESS = 209651",
              "VERTICAL_STIFFNESS = " + TirNumber(7.698 * std::pow(2 * M_PI * 76.63, 2)) + "\n"),
       "[VERTICAL] VERTICAL_STIFFNESS (line 19)", "gives k_cz = "},
      {"a syntax error in a section not used", Broken("PCX1 = 1.579", "PCX1 = 1.579 N\n"),
       "[LONGITUDINAL_COEFFICIENTS] PCX1 (line 36)", "not a number"},
  };
  for (const Case& c : cases) {
    TirFile f;
    Parameters p;
    LoadError e;
    const bool ok = ParseTir(c.text, "bad.tir", &f, &e) && TirToParameters(f, &p, &e);
    EXPECT_FALSE(ok) << c.what;
    const std::string line = e.OneLine();
    EXPECT_EQ(line.rfind("bad.tir: " + c.field + ": ", 0), 0u) << c.what << ": " << line;
    EXPECT_NE(line.find(c.words), std::string::npos) << c.what << ": " << line;
    EXPECT_EQ(line.find('\n'), std::string::npos) << c.what;
  }
}

TEST(TirMappingTest, ExportRefusesASetWithoutWhatARequiredKeyNeedsAndLeavesOutTheRest) {
  Parameters p = ExampleCarTire();
  p[P::k_by] = NAN;
  std::string text;
  LoadError e;
  EXPECT_FALSE(ParametersToTir(p, "tire", "tire.json", &text, &e));
  EXPECT_EQ(e.OneLine(), "tire.json: parameters.k_by: missing (the .tir's [STRUCTURAL] FREQ_LAT needs it)");
  p = ExampleCarTire();
  p[P::I_by] = -1;
  EXPECT_FALSE(ParametersToTir(p, "tire", "tire.json", &text, &e));
  EXPECT_NE(e.OneLine().find("parameters.I_by: must be a positive number"), std::string::npos);
  // Optional keys are left out and named.
  p = ExampleCarTire();
  p[P::c_by] = NAN;
  p[P::k_cz] = NAN;
  ASSERT_TRUE(ParametersToTir(p, "tire", "tire.json", &text, &e)) << e.OneLine();
  const TirFile f = Parse(text);
  EXPECT_EQ(f.Find("STRUCTURAL", "DAMP_LAT"), nullptr);
  EXPECT_EQ(f.Find("VERTICAL", "VERTICAL_STIFFNESS"), nullptr);
  EXPECT_NE(text.find("DAMP_LAT (c_by)"), std::string::npos);
  EXPECT_NE(text.find("VERTICAL_STIFFNESS (k_cz)"), std::string::npos);
}

// A value the data left undetermined is marked in the header, with the keys
// written from it; the others are not, and the keys' values are unchanged.
TEST(TirMappingTest, ExportMarksTheValuesTheDataLeftUndeterminedInItsHeader) {
  const Parameters p = ExampleCarTire();
  std::string text;
  LoadError e;
  const Undetermined undetermined = {
      {P::K_cx, "given sigma_cx = 0.1 m (known): the data measure K_cx/sigma_cx"},
      {P::c_bgamma, "classed no by ringid identify"}};
  ASSERT_TRUE(ParametersToTir(p, "tire", "tire.json", &text, &e, undetermined)) << e.OneLine();
  EXPECT_NE(text.find("$ UNDETERMINED by the data: K_cx = " + TirNumber(p[P::K_cx]) +
                      " N in LONGITUDINAL_STIFFNESS: given sigma_cx = 0.1 m (known): the "
                      "data measure K_cx/sigma_cx\n"),
            std::string::npos) << text;
  EXPECT_NE(text.find("$ UNDETERMINED by the data: c_bgamma = " + TirNumber(p[P::c_bgamma])),
            std::string::npos) << text;
  EXPECT_EQ(text.find("UNDETERMINED by the data: k_bx"), std::string::npos);
  EXPECT_EQ(Count(text, "UNDETERMINED"), 2);
  // Only comments differ from the unmarked file.
  const TirFile marked = Parse(text), plain = Parse(Export(p));
  ASSERT_EQ(marked.entries.size(), plain.entries.size());
  for (size_t i = 0; i < plain.entries.size(); ++i) {
    EXPECT_EQ(marked.entries[i].number, plain.entries[i].number) << plain.entries[i].key;
  }
}

// docs/tir.md's tables are TirMappingMarkdown(), between its markers.
TEST(TirMappingTest, DocsTirMdHoldsTheMappingTableOfTheCode) {
  std::ifstream in(testing::SourcePath("docs/tir.md"));
  std::stringstream doc;
  doc << in.rdbuf();
  const std::string text = doc.str();
  const std::string begin = "<!-- generated: TirMappingMarkdown() -->\n";
  const std::string end = "<!-- end generated -->";
  const size_t b = text.find(begin), e = text.find(end);
  ASSERT_NE(b, std::string::npos) << "docs/tir.md has no " << begin;
  ASSERT_NE(e, std::string::npos);
  const std::string generated = "\n" + TirMappingMarkdown() + "\n";
  if (std::getenv("RINGID_REGENERATE")) {
    std::ofstream(testing::SourcePath("docs/tir.md"))
        << text.substr(0, b + begin.size()) + generated + text.substr(e);
  }
  EXPECT_EQ(text.substr(b + begin.size(), e - b - begin.size()), generated)
      << "RINGID_REGENERATE=1 build/tests/data_tests --gtest_filter=*DocsTirMd*";
}

TEST(TirMappingTest, TirPathsAreKnownByTheirExtension) {
  EXPECT_TRUE(IsTirPath("a/b/tire.tir"));
  EXPECT_TRUE(IsTirPath("TIRE.TIR"));
  EXPECT_FALSE(IsTirPath("tire.json"));
  EXPECT_FALSE(IsTirPath("tir"));
  EXPECT_FALSE(IsTirPath("tire.tir.json"));
}

}  // namespace
}  // namespace ringid
