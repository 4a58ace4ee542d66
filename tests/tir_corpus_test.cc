// Real .tir files (the public corpus, read in place: tests/test_support.h) and the contact values
// of a full MF-Tyre/MF-Swift file (docs/tir.md): every public file with a
// sound belt block reads to the values in its text; the rest are refused for
// the right reason; sections ringid does not read are read leniently; the
// derived contact values equal an independent evaluation of the formulas,
// and export and import agree on the relaxation lengths.
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "datasets/synthetic.h"
#include "datasets/tir.h"
#include "datasets/tir_contact.h"
#include "datasets/tir_parameters.h"
#include "model/rigid_ring_model.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using P = Param;
constexpr double kTwoPi = 2 * M_PI;

std::string Corpus(const std::string& name) { return testing::CorpusPath("tir/" + name + ".tir"); }

using TirCorpusTest = testing::CorpusTest;
using TirContactCorpusTest = testing::CorpusTest;

// KEY's number as the text gives it: the first line "KEY = number", read
// without the parser (comments after '$' or '!' ignored).
double TextValue(const std::string& text, const std::string& key) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line.compare(start, key.size(), key) != 0) continue;
    const size_t eq = line.find('=', start + key.size());
    if (eq == std::string::npos || line.find_first_not_of(" \t", start + key.size()) != eq) continue;
    return std::strtod(line.c_str() + eq + 1, nullptr);
  }
  ADD_FAILURE() << "no " << key;
  return NAN;
}

double Relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

bool Read(const std::string& text, TirFile* file, Parameters* belt, LoadError* e) {
  return ParseTir(text, "t.tir", file, e, &TirSectionsRead()) && TirToParameters(*file, belt, e);
}

std::string Joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& l : lines) out += l + "\n";
  return out;
}

const std::vector<std::string> kSoundBelts = {
    "opentire_sandbox__TNO_car205_60R15", "vhc_sem__TNO_car205_60R15",
    "opentire_sandbox__reference_tire_tvd3", "opentire_sandbox__MagicFormula61_Parameters",
    "opentire_sandbox__MagicFormula62_Parameters", "mfeval_julia__MagicFormula61_Parameters",
    "mfeval_julia__MagicFormula62_Parameters", "slip_angle_control__MagicFormula61_Parameters",
    "opentire_sandbox__FSAE_Defaults", "opentire_sandbox__PacejkaBook_Defaults",
    "tyredyn__Bus_270_70R22", "tyredyn__Truck_430_50R38", "tyredyn__car145_70R13",
    "tyredyn__fsae190_50R10"};

TEST_F(TirCorpusTest, EveryPublicFileWithASoundBeltBlockReadsToTheValuesInItsText) {
  for (const std::string& name : kSoundBelts) {
    SCOPED_TRACE(name);
    const std::string text = testing::ReadFile(Corpus(name));
    TirFile file;
    Parameters p;
    LoadError e;
    ASSERT_TRUE(Read(text, &file, &p, &e)) << e.OneLine();
    const double m = TextValue(text, "BELT_MASS"), ixx = TextValue(text, "BELT_IXX");
    const double iyy = TextValue(text, "BELT_IYY");
    EXPECT_LT(Relative(p[P::m_b], m), 1e-15);
    EXPECT_LT(Relative(p[P::I_bx], ixx), 1e-15);
    EXPECT_LT(Relative(p[P::I_by], iyy), 1e-15);
    const auto k = [](double f, double mass) { return mass * std::pow(kTwoPi * f, 2); };
    EXPECT_LT(Relative(p[P::k_bx], k(TextValue(text, "FREQ_LONG"), m)), 1e-13);
    EXPECT_LT(Relative(p[P::k_by], k(TextValue(text, "FREQ_LAT"), m)), 1e-13);
    EXPECT_LT(Relative(p[P::k_bpsi], k(TextValue(text, "FREQ_YAW"), ixx)), 1e-13);
    EXPECT_LT(Relative(p[P::k_btheta], k(TextValue(text, "FREQ_WINDUP"), iyy)), 1e-13);
    // And it round-trips: exported and read back, the belt is the same.
    std::string written;
    ASSERT_TRUE(ParametersToTir(p, name, name, &written, &e)) << e.OneLine();
    TirFile again;
    Parameters back;
    ASSERT_TRUE(Read(written, &again, &back, &e)) << e.OneLine();
    for (Param q : {P::m_b, P::I_bx, P::I_by, P::k_bx, P::k_by, P::k_bpsi, P::k_btheta, P::k_cz}) {
      EXPECT_LT(Relative(back[q], p[q]), 1e-11) << ParamName(q);
    }
  }
}

TEST_F(TirCorpusTest, FilesWithoutABeltBlockAreRefusedForThatBeforeAnythingElse) {
  for (const std::string name :
       {"chrono__HMMWV_Pac02Tire", "chrono__VW_microbus_mf_185_80R14",
        "chrono__feda_335_65R22_5_G275MSA_60psi", "opentire_sandbox__MagicFormula52_Parameters",
        "opentire_sandbox__harty_dunlop_F_100_90_19_D401"}) {
    Parameters p;
    LoadError e;
    EXPECT_FALSE(LoadParameters(Corpus(name), {{P::I_ay, 1.0}}, &p, &e)) << name;
    EXPECT_EQ(e.field, "[INERTIA] BELT_MASS") << name << ": " << e.OneLine();
    EXPECT_NE(e.message.find("no rigid-ring (MF-Swift belt) block"), std::string::npos) << e.OneLine();
  }
  Parameters p;
  LoadError e;
  EXPECT_FALSE(LoadParameters(Corpus("opentire_sandbox__Model_Unstable"), {}, &p, &e));
  EXPECT_EQ(e.field.rfind("[VERTICAL] VERTICAL_STIFFNESS", 0), 0u) << e.OneLine();
  EXPECT_NE(e.message.find("must be positive, not 0"), std::string::npos) << e.OneLine();
}

TEST_F(TirCorpusTest, SectionsRingidDoesNotReadAreSkippedWithANoteAndTheRestStaysStrict) {
  TirFile file;
  LoadError e;
  ASSERT_TRUE(LoadTir(Corpus("opentire_sandbox__harty_dunlop_F_100_90_19_D401"), &file, &e,
                      &TirSectionsRead())) << e.OneLine();
  EXPECT_NE(Joined(file.notes).find("[MDI_HEADER] (COMMENTS) (line 8)"), std::string::npos)
      << Joined(file.notes);
  ASSERT_TRUE(LoadTir(Corpus("chrono__feda_335_65R22_5_G275MSA_60psi"), &file, &e,
                      &TirSectionsRead())) << e.OneLine();
  EXPECT_NE(Joined(file.notes).find("[SHAPE] (line"), std::string::npos) << Joined(file.notes);
  EXPECT_NE(Joined(file.notes).find("[DEFLECTION_LOAD_CURVE]"), std::string::npos);
  EXPECT_NE(Joined(file.notes).find("appears twice"), std::string::npos);
  // Strictly, as before, these files are refused where they break the syntax.
  EXPECT_FALSE(LoadTir(Corpus("chrono__feda_335_65R22_5_G275MSA_60psi"), &file, &e));

  const std::string tno = testing::ReadFile(Corpus("vhc_sem__TNO_car205_60R15"));
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string t = tno;
    const size_t at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return t.replace(at, from.size(), to);
  };
  Parameters p;
  // Other spellings of SI units are SI.
  EXPECT_TRUE(Read(with("'radians'", "'radian'"), &file, &p, &e)) << e.OneLine();
  EXPECT_TRUE(Read(with("'second'", "'sec'"), &file, &p, &e)) << e.OneLine();
  EXPECT_FALSE(Read(with("'meter'", "'mm'"), &file, &p, &e));
  EXPECT_EQ(e.field.rfind("[UNITS] LENGTH", 0), 0u) << e.OneLine();
  // In a section the mapping reads, a section twice or a bad line is refused.
  EXPECT_FALSE(Read(tno + "\n[STRUCTURAL]\nFREQ_LONG = 80\n", &file, &p, &e));
  EXPECT_NE(e.message.find("section appears twice"), std::string::npos) << e.OneLine();
  EXPECT_FALSE(Read(with("[STRUCTURAL]", "[STRUCTURAL]\n1.0 2.0"), &file, &p, &e));
  EXPECT_EQ(e.field.rfind("[STRUCTURAL]", 0), 0u) << e.OneLine();
  // Elsewhere it is skipped with a note.
  ASSERT_TRUE(Read(with("[VERTICAL_FORCE_RANGE]", "[VERTICAL_FORCE_RANGE]\n1.0 2.0 $ no header"),
                   &file, &p, &e)) << e.OneLine();
  EXPECT_NE(Joined(file.notes).find("[VERTICAL_FORCE_RANGE]"), std::string::npos);
}

// The TNO 205/60R15 file (MF 6.2), its coefficients typed from its text.
struct Tno {
  double fnomin = 4000, r0 = 0.3135, cz0 = 209651.5, q_fz2 = 15.416, pfz1 = 0.7097;
  double q_re0 = 0.9974, breff = 8.39, dreff = 0.2587, freff = 0.07355;
  double pkx1 = 21.69, pkx2 = 13.774, pkx3 = -0.4119, ppx1 = -0.3489, ppx2 = 0.382;
  double pky1 = -15.314, pky2 = 1.7044, pky4 = 1.9896, ppy1 = -0.6249, ppy2 = -0.06535;
  double qdz1 = 0.08993, qdz2 = -0.005979, ppz1 = -0.4402;
  double cx0 = 381913.4, cy0 = 157632.5, pcfx1 = 0.18677, pcfy1 = 0.16365, pcfy3 = 0.24993;
  double nompres = 220000;
  double lfzo = 1, pcfx2 = 0, pcfx3 = 0, pcfy2 = 0;  // as the file; a case changes them
};

// The contact values at load f and inflation pressure p, evaluated here from
// the formulas of Pacejka (2012) written out again: the deflection by
// bisection, the tangent stiffness from its polynomial.
// The nominal load scaled by LFZO enters df_z (4.E2a), K_cy (4.E25) and the
// trail (4.E42); the vertical law and the effective radius take FNOMIN itself
// (A3.3-A3.6), as TyreDyn's radius and stiffness modules do.
std::map<Param, double> Independent(const Tno& t, const Parameters& belt, double f, double p) {
  const double fz0s = t.fnomin * t.lfzo;
  const double dfz = f / fz0s - 1, dpi = p / t.nompres - 1;
  const double q1 = std::sqrt(std::pow(t.cz0 * t.r0 / t.fnomin, 2) - 4 * t.q_fz2);
  const double scale = t.fnomin * (1 + t.pfz1 * dpi);
  double lo = 0, hi = t.r0;  // F(rho) = scale (q1 rho/R0 + q2 (rho/R0)^2), increasing
  for (int i = 0; i < 200; ++i) {
    const double mid = (lo + hi) / 2, x = mid / t.r0;
    (scale * (q1 * x + t.q_fz2 * x * x) < f ? lo : hi) = mid;
  }
  const double rho = (lo + hi) / 2;
  const double cz = scale / t.r0 * (q1 + 2 * t.q_fz2 * rho / t.r0);
  std::map<Param, double> v;
  v[P::F_cz0] = f;
  v[P::k_cz] = cz * belt[P::k_bz] / (belt[P::k_bz] - cz);
  v[P::r_l0] = t.r0 * t.q_re0 - rho;
  const double cz_pressure = t.cz0 * (1 + t.pfz1 * dpi);
  v[P::r_e0] = t.r0 * t.q_re0 - t.fnomin / cz_pressure *
                                    (t.freff * f / t.fnomin + t.dreff * std::atan(t.breff * f / t.fnomin));
  v[P::K_cx] = f * (t.pkx1 + t.pkx2 * dfz) * std::exp(t.pkx3 * dfz) * (1 + t.ppx1 * dpi + t.ppx2 * dpi * dpi);
  v[P::K_cy] = -t.pky1 * fz0s * (1 + t.ppy1 * dpi) *
               std::sin(t.pky4 * std::atan(f / (t.pky2 * (1 + t.ppy2 * dpi) * fz0s)));
  v[P::t_0] = f * t.r0 / fz0s * (t.qdz1 + t.qdz2 * dfz) * (1 - t.ppz1 * dpi);
  const double cx = t.cx0 * (1 + t.pcfx1 * dfz + t.pcfx2 * dfz * dfz) * (1 + t.pcfx3 * dpi);
  const double cy = t.cy0 * (1 + t.pcfy1 * dfz + t.pcfy2 * dfz * dfz) * (1 + t.pcfy3 * dpi);
  v[P::sigma_cx] = v[P::K_cx] * (1 / cx - 1 / belt[P::k_bx] -
                                 v[P::r_e0] * v[P::r_e0] / belt[P::k_btheta]);
  v[P::sigma_cy] = v[P::K_cy] * (1 / cy - 1 / belt[P::k_by] -
                                 v[P::r_l0] * v[P::r_l0] / (belt[P::k_bgamma] + v[P::r_l0] * f));
  return v;
}

TEST_F(TirContactCorpusTest, TheContactValuesOfTheTnoTireEqualAnIndependentEvaluationOfTheFormulas) {
  const std::string tno = testing::ReadFile(Corpus("opentire_sandbox__TNO_car205_60R15"));
  // The text with KEY's line (its value `from`) giving `to` instead.
  const auto with = [](std::string text, const std::string& key, const std::string& from,
                       const std::string& to) {
    const std::string line = key + std::string(25 - key.size(), ' ') + "= " + from;
    const size_t at = text.find(line);
    EXPECT_NE(at, std::string::npos) << line;
    return at == std::string::npos ? text : text.replace(at, line.size(), key + " = " + to);
  };
  struct Case {
    double load, pressure;
    bool scaled;  // LFZO 0.9 and the quadratic and pressure terms of C_x, C_y set
  };
  for (const Case& k : std::vector<Case>{{4000, 220000, false}, {3000, 220000, false},
                                          {5200, 250000, false}, {3500, 250000, true}}) {
    SCOPED_TRACE("F_cz0 " + std::to_string(k.load) + " N, " + std::to_string(k.pressure) + " Pa" +
                 (k.scaled ? ", scaled" : ""));
    Tno t;
    std::string text = with(tno, "INFLPRES", "220000", std::to_string(static_cast<int>(k.pressure)));
    if (k.scaled) {
      t.lfzo = 0.9, t.pcfx2 = 0.1, t.pcfx3 = 0.2, t.pcfy2 = 0.05;
      text = with(text, "LFZO", "1", "0.9");
      text = with(text, "PCFX2", "0", "0.1");
      text = with(text, "PCFX3", "0", "0.2");
      text = with(text, "PCFY2", "0", "0.05");
    }
    TirFile file;
    Parameters belt;
    LoadError e;
    ASSERT_TRUE(Read(text, &file, &belt, &e)) << e.OneLine();
    std::map<Param, double> given;
    if (k.load != t.fnomin) given[P::F_cz0] = k.load;
    TirContact c;
    ASSERT_TRUE(DeriveTirContact(file, belt, given, &c, &e)) << e.OneLine();
    EXPECT_EQ(c.version, "6.2");
    EXPECT_EQ(c.load, k.load);
    const std::map<Param, double> expected = Independent(t, belt, k.load, k.pressure);
    EXPECT_EQ(c.derived.size(), expected.size() - given.size()) << Joined(c.notes);
    for (const TirDerived& d : c.derived) {
      ASSERT_TRUE(expected.count(d.parameter)) << ParamName(d.parameter);
      EXPECT_LT(Relative(d.value, expected.at(d.parameter)), 1e-9)
          << ParamName(d.parameter) << ": " << d.value << " vs " << expected.at(d.parameter);
    }
  }
}

// A full set exported, with Magic Formula keys that give its contact values
// added, reads back to the same set: export's series relation is import's.
TEST(TirContactTest, ExportAndImportAgreeOnTheContactValuesAndRelaxationLengths) {
  const Parameters p = ExampleCarTire();
  std::string text;
  LoadError e;
  ASSERT_TRUE(ParametersToTir(p, "car", "car.json", &text, &e)) << e.OneLine();
  const double f = p[P::F_cz0];
  const double cz = 1 / (1 / p[P::k_bz] + 1 / p[P::k_cz]);
  const double r0 = p[P::r_l0] + f / cz;  // Q_FZ2 = 0: a linear vertical law
  const auto number = [](double v) { return TirNumber(v); };
  const auto insert = [&](const std::string& section, const std::string& lines) {
    const size_t at = text.find("[" + section + "]\n");
    ASSERT_NE(at, std::string::npos) << section;
    text.insert(at + section.size() + 3, lines);
  };
  insert("VERTICAL", "FNOMIN = " + number(f) + "\nQ_RE0 = 1\nQ_FZ2 = 0\nBREFF = 0\nDREFF = 0\n" +
                         "FREFF = " + number((r0 - p[P::r_e0]) * cz / f) + "\n");
  text += "[MODEL]\nFITTYP = 61\n[DIMENSION]\nUNLOADED_RADIUS = " + number(r0) + "\n" +
          "[LONGITUDINAL_COEFFICIENTS]\nPKX1 = " + number(p[P::K_cx] / f) + "\n" +
          "[LATERAL_COEFFICIENTS]\nPKY1 = " + number(-p[P::K_cy] / f) + "\nPKY2 = 1\nPKY4 = 2\n" +
          "[ALIGNING_COEFFICIENTS]\nQDZ1 = " + number(p[P::t_0] / r0) + "\n";
  TirFile file;
  Parameters belt;
  ASSERT_TRUE(Read(text, &file, &belt, &e)) << e.OneLine();
  TirContact c;
  ASSERT_TRUE(DeriveTirContact(file, belt, {}, &c, &e)) << e.OneLine();
  EXPECT_EQ(c.derived.size(), 9u) << Joined(c.notes);
  for (const TirDerived& d : c.derived) {
    EXPECT_LT(Relative(d.value, p[d.parameter]), 1e-9)
        << ParamName(d.parameter) << ": " << d.value << " vs " << p[d.parameter];
  }
}

TEST_F(TirContactCorpusTest, AConsistentFullFileGivesACompleteSetWithOnlyTheRimsInertiaGiven) {
  for (const std::string name :
       {"opentire_sandbox__TNO_car205_60R15", "vhc_sem__TNO_car205_60R15",
        "opentire_sandbox__reference_tire_tvd3", "opentire_sandbox__FSAE_Defaults",
        "opentire_sandbox__PacejkaBook_Defaults", "tyredyn__Bus_270_70R22",
        "tyredyn__car145_70R13", "tyredyn__fsae190_50R10"}) {
    SCOPED_TRACE(name);
    const std::string text = testing::ReadFile(Corpus(name));
    Parameters p;
    LoadError e;
    std::vector<std::string> notes;
    ASSERT_TRUE(LoadParameters(Corpus(name), {{P::I_ay, 0.3}}, &p, &e, &notes)) << e.OneLine();
    for (Param q : RigidRingModel().parameters()) EXPECT_TRUE(p.IsSet(q)) << ParamName(q);
    EXPECT_NEAR(p[P::I_ay], 0.3 + TextValue(text, "IYY") - TextValue(text, "BELT_IYY"), 1e-12);
    EXPECT_NE(Joined(notes).find("a .tir describes the tire, not the wheel"), std::string::npos);
    EXPECT_TRUE(RigidRingModel().Solve(p).ok);
  }
  // The reference tire of the book's appendix changes its belt with load and
  // speed: the values hold at FNOMIN and standstill, and that is said.
  Parameters p;
  LoadError e;
  std::vector<std::string> notes;
  ASSERT_TRUE(LoadParameters(Corpus("opentire_sandbox__reference_tire_tvd3"), {}, &p, &e, &notes));
  EXPECT_NE(Joined(notes).find("Q_BVX = 0.364"), std::string::npos) << Joined(notes);
  EXPECT_NE(Joined(notes).find("Q_BVT = 0.065"), std::string::npos);
}

TEST_F(TirContactCorpusTest, WhereCarcassAndBeltDisagreeTheRelaxationLengthIsLeftToTheUserAndSaid) {
  for (const std::string name :
       {"opentire_sandbox__MagicFormula61_Parameters", "mfeval_julia__MagicFormula62_Parameters",
        "tyredyn__Truck_430_50R38"}) {
    Parameters p;
    LoadError e;
    std::vector<std::string> notes;
    ASSERT_TRUE(LoadParameters(Corpus(name), {}, &p, &e, &notes)) << e.OneLine();
    EXPECT_FALSE(p.IsSet(P::sigma_cy)) << name;
    EXPECT_NE(Joined(notes).find("sigma_cy not derived: [STRUCTURAL] LATERAL_STIFFNESS"),
              std::string::npos) << Joined(notes);
    EXPECT_NE(Joined(notes).find("is stiffer than the belt allows"), std::string::npos);
    // Given by hand, it is used.
    ASSERT_TRUE(LoadParameters(Corpus(name), {{P::sigma_cy, 0.2}, {P::sigma_cx, 0.1}}, &p, &e,
                               &notes)) << e.OneLine();
    EXPECT_EQ(p[P::sigma_cy], 0.2);
  }
}

TEST_F(TirContactCorpusTest, BadMagicFormulaKeysAreRefusedNamingTheKey) {
  const std::string tno = testing::ReadFile(Corpus("vhc_sem__TNO_car205_60R15"));
  const auto refused = [&](const std::string& from, const std::string& to) {
    std::string text = tno;
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    TirFile file;
    Parameters belt;
    LoadError e;
    EXPECT_TRUE(Read(text, &file, &belt, &e)) << e.OneLine();
    TirContact c;
    EXPECT_FALSE(DeriveTirContact(file, belt, {}, &c, &e)) << from;
    return e;
  };
  LoadError e = refused("FNOMIN                   = 4000", "FNOMIN = 'heavy'");
  EXPECT_EQ(e.field.rfind("[VERTICAL] FNOMIN", 0), 0u) << e.OneLine();
  EXPECT_EQ(e.message, "must be a number, not a quoted string");
  e = refused("FNOMIN                   = 4000", "FNOMIN = -4000");
  EXPECT_EQ(e.field.rfind("[VERTICAL] FNOMIN", 0), 0u) << e.OneLine();
  e = refused("PKX1                     = 21.69", "PKX1 = 'x'");
  EXPECT_EQ(e.field.rfind("[LONGITUDINAL_COEFFICIENTS] PKX1", 0), 0u) << e.OneLine();
  e = refused("Q_FZ2                    = 15.416", "Q_FZ2 = 1e9");
  EXPECT_EQ(e.field.rfind("[VERTICAL] Q_FZ2", 0), 0u) << e.OneLine();
  EXPECT_NE(e.message.find("no solution"), std::string::npos) << e.OneLine();
  e = refused("INFLPRES                 = 220000", "INFLPRES = -220000");
  EXPECT_EQ(e.field.rfind("[OPERATING_CONDITIONS] INFLPRES", 0), 0u) << e.OneLine();
  e = refused("LFZO                     = 1", "LFZO = 0");
  EXPECT_EQ(e.field.rfind("[SCALING_COEFFICIENTS] LFZO", 0), 0u) << e.OneLine();
  e = refused("PKY2                     = 1.7044", "PKY2 = 0");
  EXPECT_EQ(e.field.rfind("[LATERAL_COEFFICIENTS] PKY2", 0), 0u) << e.OneLine();
}

}  // namespace
}  // namespace ringid
