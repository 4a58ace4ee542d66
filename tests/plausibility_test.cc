// The plausibility rules of model/plausibility.h: each fires outside its range
// and not inside, only when its parameters are used and set, and the table in
// docs/plausibility.md is the one the code holds.
#include "model/plausibility.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "datasets/dataset.h"
#include "model/rigid_ring_model.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using testing::ReadFile;
using testing::SourcePath;

std::vector<Param> AllParams() {
  std::vector<Param> all;
  for (int i = 0; i < kNumParams; ++i) all.push_back(ParamAt(i));
  return all;
}

std::vector<std::string> Ids(const std::vector<PlausibilityFlag>& flags) {
  std::vector<std::string> ids;
  for (const PlausibilityFlag& f : flags) ids.push_back(f.rule);
  return ids;
}

const PlausibilityFlag* FindFlag(const std::vector<PlausibilityFlag>& flags,
                                 const std::string& rule) {
  for (const PlausibilityFlag& f : flags) {
    if (f.rule == rule) return &f;
  }
  return nullptr;
}

// A typical passenger-car tire (205/60 R15 class) with every sidewall mode at
// a damping ratio of 0.05: well inside every range.
Parameters CarTire() {
  Parameters p;
  p[Param::m_b] = 7;
  p[Param::I_ay] = 1.0;
  p[Param::I_by] = 0.5;  // 0.79 m_b r_e0^2
  p[Param::I_bx] = 0.3;  // 0.48 m_b r_e0^2
  p[Param::I_bz] = 0.3;
  p[Param::F_cz0] = 4000;
  p[Param::k_bx] = 4e5;
  p[Param::k_bz] = 4e5;
  p[Param::k_btheta] = 5e4;
  p[Param::K_cx] = 8e4;  // 20 F_cz0
  p[Param::sigma_cx] = 0.1;
  p[Param::r_e0] = 0.3;
  p[Param::a_e] = 0.45;  // the tandem cam: 1.5 and 1 r_e0, l_s near 0.8 of a contact length
  p[Param::b_e] = 0.3;
  p[Param::c_e] = 1.6;
  p[Param::l_s] = 0.11;
  p[Param::k_cz] = 2e5;
  p[Param::k_by] = 2e5;
  p[Param::k_bgamma] = 5e3;
  p[Param::k_bpsi] = 5e3;
  p[Param::K_cy] = 6e4;  // 15 F_cz0
  p[Param::sigma_cy] = 0.15;
  p[Param::r_l0] = 0.28;
  p[Param::t_0] = 0.03;
  const auto damp = [&](Param c, Param k, Param m) {
    p[c] = 0.05 * 2 * std::sqrt(p[k] * p[m]);
  };
  damp(Param::c_bx, Param::k_bx, Param::m_b);
  damp(Param::c_bz, Param::k_bz, Param::m_b);
  damp(Param::c_btheta, Param::k_btheta, Param::I_by);
  damp(Param::c_by, Param::k_by, Param::m_b);
  damp(Param::c_bgamma, Param::k_bgamma, Param::I_bx);
  damp(Param::c_bpsi, Param::k_bpsi, Param::I_bz);
  return p;
}

Parameters PaperSet() {
  Parameters p;
  LoadError error;
  EXPECT_TRUE(LoadParameterSet(SourcePath("datasets/paper/parameters.json"), &p, &error))
      << error.OneLine();
  return p;
}

TEST(PlausibilityTest, ATypicalCarTireRaisesNoFlag) {
  const std::vector<PlausibilityFlag> flags =
      CheckPlausibility(CarTire(), AllParams());
  for (const PlausibilityFlag& f : flags) ADD_FAILURE() << f.rule << ": " << f.reason;
}

// The paper's set (Table 2 plus the recovered inertias and load) trips these
// rules; each is a real oddity of that set, not a range set too tight:
// * r_l0 = 2.58 mm and sigma_cy = 1.17 mm are millimetres, not a radius and a
//   contact relaxation length (datasets/paper/table1_r_l0_physical.json makes
//   the same point about r_l0);
// * every sidewall damper gives a one-DOF damping ratio of 0.66-0.97
//   (docs/model.md section 9: "heavy damping, zeta up to about 0.9 here"),
//   where tires show a few per cent;
// * the recovered belt inertias have a radius of gyration of about 0.1 m,
//   a third of r_e0, and I_bz = 2.2 I_bx although a ring has I_bx = I_bz;
// * K_cx and K_cy are 0.1 and 0.006 times the recovered load F_cz0 = 107 kN,
//   where a tire's slip stiffness is several times its load.
TEST(PlausibilityTest, ThePapersSetTripsOnlyTheRulesItReallyBreaks) {
  const std::vector<PlausibilityFlag> flags =
      CheckPlausibility(PaperSet(), RigidRingModel().parameters());
  const std::vector<std::string> expected = {
      "loaded_radius_range",
      "loaded_radius_vs_rolling_radius",
      "lateral_relaxation_length_range",
      "damping_ratio_x",
      "damping_ratio_z",
      "damping_ratio_theta",
      "damping_ratio_y",
      "damping_ratio_gamma",
      "damping_ratio_psi",
      "belt_inertia_y_vs_ring",
      "belt_inertia_x_vs_ring",
      "belt_inertia_z_vs_ring",
      "belt_inertia_x_vs_z",
      "longitudinal_slip_stiffness_vs_load",
      "lateral_slip_stiffness_vs_load",
  };
  EXPECT_EQ(Ids(flags), expected);
  for (const PlausibilityFlag& f : flags) std::printf("  %s: %s\n", f.rule.c_str(), f.reason.c_str());

  const PlausibilityFlag* radius = FindFlag(flags, "loaded_radius_vs_rolling_radius");
  ASSERT_NE(radius, nullptr);
  EXPECT_EQ(radius->reason,
            "r_l0 = 0.00258 m is 99.2 % below r_e0 = 0.319 m; a loaded radius is at most 15 % "
            "below the rolling radius and not above it");
  const PlausibilityFlag* damping = FindFlag(flags, "damping_ratio_x");
  ASSERT_NE(damping, nullptr);
  EXPECT_EQ(damping->reason,
            "c_bx / (2 sqrt(k_bx m_b)) = 0.723 (c_bx = 1380 N s/m, k_bx = 3.84e5 N/m, "
            "m_b = 2.37 kg) is above 0.5; the sidewall modes of a tire are lightly damped");
}

struct Case {
  std::string rule;
  Param param;
  double value;
  bool fires;
};

// Each rule, moved outside its range (on every side it has) and to a value
// just inside, from the car tire.
const std::vector<Case> kCases = {
    {"belt_mass_range", Param::m_b, 0.5, true},
    {"belt_mass_range", Param::m_b, 150, true},
    {"belt_mass_range", Param::m_b, 1.5, false},
    {"belt_mass_range", Param::m_b, 90, false},
    {"rolling_radius_range", Param::r_e0, 0.1, true},
    {"rolling_radius_range", Param::r_e0, 1.5, true},
    {"rolling_radius_range", Param::r_e0, 1.1, false},
    {"loaded_radius_range", Param::r_l0, 0.00258, true},
    {"loaded_radius_range", Param::r_l0, 1.3, true},
    {"loaded_radius_range", Param::r_l0, 0.2, false},
    {"loaded_radius_vs_rolling_radius", Param::r_l0, 0.24, true},   // 0.80 r_e0
    {"loaded_radius_vs_rolling_radius", Param::r_l0, 0.31, true},   // 1.033 r_e0
    {"loaded_radius_vs_rolling_radius", Param::r_l0, 0.26, false},  // 0.867 r_e0
    {"loaded_radius_vs_rolling_radius", Param::r_l0, 0.305, false}, // 1.017 r_e0
    {"loaded_radius_vs_rolling_radius", Param::r_e0, 0.35, true},   // r_l0 = 0.8 r_e0
    {"longitudinal_relaxation_length_range", Param::sigma_cx, 0.005, true},
    {"longitudinal_relaxation_length_range", Param::sigma_cx, 3, true},
    {"longitudinal_relaxation_length_range", Param::sigma_cx, 0.03, false},
    {"lateral_relaxation_length_range", Param::sigma_cy, 0.00117, true},
    {"lateral_relaxation_length_range", Param::sigma_cy, 2.5, true},
    {"lateral_relaxation_length_range", Param::sigma_cy, 1.5, false},
    {"pneumatic_trail_range", Param::t_0, 0.15, true},
    {"pneumatic_trail_range", Param::t_0, -0.01, true},
    {"pneumatic_trail_range", Param::t_0, 0.08, false},
    // 2 sqrt(k m) is 3347 for x and z, 316 for theta, 2366 for y, 77.5 for
    // gamma and psi.
    {"damping_ratio_x", Param::c_bx, 2000, true},
    {"damping_ratio_x", Param::c_bx, 1500, false},
    {"damping_ratio_x", Param::k_bx, 1e3, true},  // a softer spring, same damper
    {"damping_ratio_z", Param::c_bz, 2000, true},
    {"damping_ratio_z", Param::c_bz, 1500, false},
    {"damping_ratio_theta", Param::c_btheta, 200, true},
    {"damping_ratio_theta", Param::c_btheta, 140, false},
    {"damping_ratio_theta", Param::I_by, 0.002, true},
    {"damping_ratio_y", Param::c_by, 1500, true},
    {"damping_ratio_y", Param::c_by, 1000, false},
    {"damping_ratio_gamma", Param::c_bgamma, 50, true},
    {"damping_ratio_gamma", Param::c_bgamma, 30, false},
    {"damping_ratio_psi", Param::c_bpsi, 50, true},
    {"damping_ratio_psi", Param::c_bpsi, 30, false},
    // m_b r_e0^2 = 0.63 kg m^2.
    {"belt_inertia_y_vs_ring", Param::I_by, 0.2, true},
    {"belt_inertia_y_vs_ring", Param::I_by, 1.0, true},
    {"belt_inertia_y_vs_ring", Param::I_by, 0.35, false},
    {"belt_inertia_y_vs_ring", Param::I_by, 0.9, false},
    {"belt_inertia_y_vs_ring", Param::r_e0, 0.5, true},
    {"belt_inertia_x_vs_ring", Param::I_bx, 0.1, true},
    {"belt_inertia_x_vs_ring", Param::I_bx, 0.5, true},
    {"belt_inertia_x_vs_ring", Param::I_bx, 0.2, false},
    {"belt_inertia_x_vs_ring", Param::m_b, 2, true},
    {"belt_inertia_z_vs_ring", Param::I_bz, 0.1, true},
    {"belt_inertia_z_vs_ring", Param::I_bz, 0.5, true},
    {"belt_inertia_z_vs_ring", Param::I_bz, 0.2, false},
    {"belt_inertia_x_vs_z", Param::I_bz, 0.46, true},  // 1.53 I_bx
    {"belt_inertia_x_vs_z", Param::I_bx, 0.46, true},
    {"belt_inertia_x_vs_z", Param::I_bz, 0.44, false},  // 1.47 I_bx
    {"belt_inertia_x_vs_z", Param::I_bx, 0.21, false},  // I_bz = 1.43 I_bx
    // F_cz0 = 4000 N.
    {"longitudinal_slip_stiffness_vs_load", Param::K_cx, 4000, true},
    {"longitudinal_slip_stiffness_vs_load", Param::K_cx, 3e5, true},
    {"longitudinal_slip_stiffness_vs_load", Param::K_cx, 1e4, false},
    {"longitudinal_slip_stiffness_vs_load", Param::F_cz0, 1e5, true},
    {"lateral_slip_stiffness_vs_load", Param::K_cy, 637, true},
    {"lateral_slip_stiffness_vs_load", Param::K_cy, 2.1e5, true},
    {"lateral_slip_stiffness_vs_load", Param::K_cy, 1.9e5, false},
    {"lateral_slip_stiffness_vs_load", Param::F_cz0, 1e5, true},
    // r_e0 = 0.3 m: the cam's lengths 0.5-3, 0.3-2 and 0.05-1 of it.
    {"cam_length_vs_radius", Param::a_e, 0.1, true},
    {"cam_length_vs_radius", Param::a_e, 1.0, true},
    {"cam_length_vs_radius", Param::a_e, 0.2, false},
    {"cam_height_vs_radius", Param::b_e, 0.05, true},
    {"cam_height_vs_radius", Param::b_e, 0.7, true},
    {"cam_height_vs_radius", Param::b_e, 0.1, false},
    {"cam_order_range", Param::c_e, 1.1, true},
    {"cam_order_range", Param::c_e, 3.5, true},
    {"cam_order_range", Param::c_e, 2.0, false},
    {"cam_distance_vs_radius", Param::l_s, 0.01, true},
    {"cam_distance_vs_radius", Param::l_s, 0.4, true},
    {"cam_distance_vs_radius", Param::l_s, 0.05, false},
};

TEST(PlausibilityTest, EachRuleFiresOutsideItsRangeNamingTheParameterAndNotInside) {
  for (const Case& c : kCases) {
    SCOPED_TRACE(c.rule + ": " + ParamName(c.param) + " = " + std::to_string(c.value));
    Parameters p = CarTire();
    p[c.param] = c.value;
    const std::vector<PlausibilityFlag> flags = CheckPlausibility(p, AllParams());
    const PlausibilityFlag* f = FindFlag(flags, c.rule);
    if (!c.fires) {
      EXPECT_EQ(f, nullptr) << f->reason;
      continue;
    }
    ASSERT_NE(f, nullptr);
    EXPECT_NE(std::find(f->parameters.begin(), f->parameters.end(), c.param),
              f->parameters.end());
    EXPECT_NE(f->reason.find(ParamName(c.param)), std::string::npos) << f->reason;
    EXPECT_NE(f->reason.find(FormatSignificant3(c.value)), std::string::npos) << f->reason;
  }
}

TEST(PlausibilityTest, EveryRuleOfTheTableHasAFiringAndAQuietCase) {
  std::set<std::string> fired, quiet;
  for (const Case& c : kCases) (c.fires ? fired : quiet).insert(c.rule);
  for (const PlausibilityRule& rule : PlausibilityRules()) {
    EXPECT_TRUE(fired.count(rule.id)) << rule.id << " has no case that fires";
    EXPECT_TRUE(quiet.count(rule.id)) << rule.id << " has no case inside its range";
  }
}

TEST(PlausibilityTest, ARuleWhoseParametersAreNotAllUsedDoesNotFire) {
  const Parameters p = PaperSet();
  std::vector<Param> used = RigidRingModel().parameters();
  used.erase(std::remove(used.begin(), used.end(), Param::r_e0), used.end());
  const std::vector<PlausibilityFlag> flags = CheckPlausibility(p, used);
  for (const char* rule : {"loaded_radius_vs_rolling_radius", "belt_inertia_y_vs_ring",
                           "belt_inertia_x_vs_ring", "belt_inertia_z_vs_ring"}) {
    EXPECT_EQ(FindFlag(flags, rule), nullptr) << rule;
  }
  EXPECT_NE(FindFlag(flags, "loaded_radius_range"), nullptr);  // needs r_l0 only
  EXPECT_TRUE(CheckPlausibility(p, {}).empty());
}

TEST(PlausibilityTest, ARuleWhoseParametersAreNotAllSetDoesNotFire) {
  Parameters p = PaperSet();
  p[Param::F_cz0] = std::nan("");
  p[Param::m_b] = std::nan("");
  const std::vector<PlausibilityFlag> flags = CheckPlausibility(p, AllParams());
  for (const PlausibilityFlag& f : flags) {
    for (Param q : f.parameters) {
      EXPECT_NE(q, Param::F_cz0) << f.rule;
      EXPECT_NE(q, Param::m_b) << f.rule;
    }
  }
  // Those that need neither still fire.
  EXPECT_NE(FindFlag(flags, "damping_ratio_theta"), nullptr);
  EXPECT_NE(FindFlag(flags, "belt_inertia_x_vs_z"), nullptr);
  EXPECT_TRUE(CheckPlausibility(Parameters(), AllParams()).empty());
}

TEST(PlausibilityTest, RuleIdsAreUniqueAndTheTableTextIsMarkdownSafe) {
  std::set<std::string> ids;
  for (const PlausibilityRule& rule : PlausibilityRules()) {
    EXPECT_TRUE(ids.insert(rule.id).second) << rule.id;
    EXPECT_FALSE(rule.parameters.empty()) << rule.id;
    EXPECT_FALSE(rule.range.empty()) << rule.id;
    EXPECT_FALSE(rule.why.empty()) << rule.id;
    for (const std::string& text : {rule.id, rule.range, rule.why}) {
      EXPECT_EQ(text.find_first_of("|\n"), std::string::npos) << rule.id << ": " << text;
    }
  }
  const std::string md = PlausibilityTableMarkdown();
  EXPECT_EQ(std::count(md.begin(), md.end(), '\n'),
            static_cast<long>(PlausibilityRules().size()) + 2);
}

TEST(PlausibilityTest, TheDocHoldsExactlyTheTableTheCodeProduces) {
  const std::string doc = ReadFile(SourcePath("docs/plausibility.md"));
  const std::string table = PlausibilityTableMarkdown();
  const size_t at = doc.find(table);
  ASSERT_NE(at, std::string::npos)
      << "docs/plausibility.md is out of date; paste this table into it:\n" << table;
  EXPECT_EQ(doc.find(table, at + 1), std::string::npos) << "the table appears twice";
  // No other table rows: every line starting with '|' is part of the table.
  size_t rows = 0;
  for (size_t pos = 0; pos < doc.size(); pos = doc.find('\n', pos) + 1) {
    if (doc[pos] == '|') ++rows;
    if (doc.find('\n', pos) == std::string::npos) break;
  }
  EXPECT_EQ(rows, PlausibilityRules().size() + 2);
}

TEST(PlausibilityTest, NumbersAreFormattedToThreeSignificantDigits) {
  EXPECT_EQ(FormatSignificant3(0.00258), "0.00258");
  EXPECT_EQ(FormatSignificant3(0.319), "0.319");
  EXPECT_EQ(FormatSignificant3(0.5), "0.5");
  EXPECT_EQ(FormatSignificant3(2.3723885), "2.37");
  EXPECT_EQ(FormatSignificant3(9.996), "10");
  EXPECT_EQ(FormatSignificant3(1380), "1380");
  EXPECT_EQ(FormatSignificant3(12345), "12300");
  EXPECT_EQ(FormatSignificant3(106675.49), "1.07e5");
  EXPECT_EQ(FormatSignificant3(-2.5e-4), "-2.5e-4");
  EXPECT_EQ(FormatSignificant3(0), "0");
  EXPECT_EQ(FormatSignificant3(1), "1");
}

}  // namespace
}  // namespace ringid
