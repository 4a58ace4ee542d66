// The identifiability analysis against structure known from the equations.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "datasets/synthetic.h"
#include "estimation/identifiability.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using testing::PaperIdentified;

const ParameterIdentifiability& Find(const IdentifiabilityReport& r, Param p) {
  for (const auto& q : r.parameters) {
    if (q.param() == p) return q;
  }
  ADD_FAILURE() << "no " << ParamName(p);
  return r.parameters.front();
}

bool HasMeaning(const IdentifiabilityReport& r, const std::string& text) {
  for (const Combination& c : r.combinations) {
    if (c.meaning.find(text) != std::string::npos) return true;
  }
  return false;
}

TEST(IdentifiabilityTest, Table1DeterminesOnlyRatiosOfContactStiffnessAndRelaxation) {
  Dataset d;
  LoadError e;
  ASSERT_TRUE(LoadDataset(testing::SourcePath("datasets/paper/table1.json"), &d, &e));
  IdentifiabilityOptions o;
  o.profile_steps = 0;  // the structure, not the intervals, is tested here
  IdentifiabilityReport r;
  AnalyzeIdentifiability(RigidRingModel(), d, o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.rank, 7);
  EXPECT_NE(r.rank_explanation.find("7 observations cannot determine 16"), std::string::npos)
      << r.rank_explanation;
  // Eq. (9)-(10): K_cx and sigma_cx (K_cy, sigma_cy) enter only as K / sigma.
  for (Param p : {Param::K_cx, Param::sigma_cx, Param::K_cy, Param::sigma_cy}) {
    EXPECT_EQ(Find(r, p).identifiable, Identifiability::kNo) << ParamName(p);
  }
  EXPECT_TRUE(HasMeaning(r, "only K_cx / sigma_cx is determined"));
  EXPECT_TRUE(HasMeaning(r, "only K_cy / sigma_cy is determined"));
  EXPECT_EQ(static_cast<int>(r.identifiable_subset.size()), 7);
}

// Full modal data, ten free parameters (as estimation_test's well-posed case).
Dataset WellPosed(const Parameters& truth, std::mt19937_64* rng,
                  std::vector<Param> free, bool full_data) {
  Dataset d = testing::SyntheticDataset(RigidRingModel(), truth, 0.0025, 0.10, 0.02, rng);
  if (!full_data) {
    for (MeasuredMode& m : d.modes) {
      m.damping_ratio.reset();
      m.damping_sigma.reset();
      m.shape.clear();
      m.shape_sigma.reset();
    }
  }
  for (int i = 0; i < kNumParams; ++i) {
    if (Info(ParamAt(i)).group != Group::kEffect) d.known[ParamAt(i)] = truth[ParamAt(i)];
  }
  for (Param p : free) {
    d.known.erase(p);
    d.initial[p] = truth[p] * (ParamName(p)[0] == 'c' ? 0.8 : 1.25);
  }
  return d;
}

TEST(IdentifiabilityTest, ProfileAndWaldIntervalsAgreeOnAWellPosedProblem) {
  std::mt19937_64 rng(3);
  const Parameters truth = PaperIdentified();
  const Dataset d = WellPosed(truth, &rng,
                              {Param::k_bx, Param::k_btheta, Param::K_cx, Param::k_by,
                               Param::k_bgamma, Param::c_by},
                              true);
  IdentifiabilityReport r;
  AnalyzeIdentifiability(RigidRingModel(), d, IdentifiabilityOptions{}, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.rank, 6);
  EXPECT_TRUE(r.advice.empty());
  for (const auto& p : r.parameters) {
    EXPECT_EQ(p.identifiable, Identifiability::kYes) << p.key.Text();
    ASSERT_TRUE(p.wald_95 && p.profile_95.lower && p.profile_95.upper) << p.key.Text();
    // Near-linear problem: the two intervals agree to a fraction of a width.
    const double width = p.wald_95->second - p.wald_95->first;
    EXPECT_NEAR(*p.profile_95.lower, p.wald_95->first, 0.15 * width) << p.key.Text();
    EXPECT_NEAR(*p.profile_95.upper, p.wald_95->second, 0.15 * width) << p.key.Text();
  }
}

TEST(IdentifiabilityTest, VerticalStiffnessesFromOneFrequencyAreOneCombination) {
  // The vertical mode sees only k_bz + k_cz (its 1-DOF closed form).
  std::mt19937_64 rng(4);
  const Dataset d = WellPosed(PaperIdentified(), &rng,
                              {Param::k_bz, Param::k_cz, Param::k_btheta}, false);
  IdentifiabilityOptions o;
  o.profile_steps = 0;
  IdentifiabilityReport r;
  AnalyzeIdentifiability(RigidRingModel(), d, o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.rank, 2);
  EXPECT_EQ(Find(r, Param::k_bz).identifiable, Identifiability::kNo);
  EXPECT_EQ(Find(r, Param::k_cz).identifiable, Identifiability::kNo);
  EXPECT_EQ(Find(r, Param::k_btheta).identifiable, Identifiability::kYes);
  EXPECT_TRUE(HasMeaning(r, "only one combination of k_bz and k_cz is determined"));
  // A known k_cz determines k_bz; the advice must say so.
  bool advised = false;
  for (const Advice& a : r.advice) {
    if (a.parameter == "k_bz" && a.observation.find("known value of k_cz") != std::string::npos) {
      advised = a.makes_identifiable;
    }
  }
  EXPECT_TRUE(advised);
}

// A standing test of the example car tire with the contact free; `speeds`
// adds drum conditions.
Dataset CarTireTest(const std::vector<double>& speeds, unsigned seed) {
  const Parameters truth = ExampleCarTire();
  Dataset d;
  d.name = "car";
  d.format = 2;
  d.conditions.clear();
  for (double v : speeds) {
    Condition c;
    c.name = "at_" + std::to_string(static_cast<int>(v));
    c.speed_m_s = v;
    d.conditions.push_back(c);
  }
  std::mt19937_64 rng(seed);
  std::string error;
  EXPECT_TRUE(Simulate(RigidRingModel(), truth, SimulateOptions(), &rng, &d, &error)) << error;
  for (int i = 0; i < kNumParams; ++i) {
    if (Info(ParamAt(i)).group != Group::kEffect) d.known[ParamAt(i)] = truth[ParamAt(i)];
  }
  for (Param p : {Param::k_bx, Param::c_bx, Param::K_cx, Param::sigma_cx, Param::k_by,
                  Param::K_cy, Param::sigma_cy}) {
    d.known.erase(p);
    d.initial[p] = truth[p] * 1.2;
  }
  return d;
}

// The advice is checked by doing what it says: the drum test it proposes,
// simulated and added, makes sigma_cx identifiable.
TEST(IdentifiabilityTest, AdvisedDrumTestMakesTheRelaxationLengthIdentifiable) {
  IdentifiabilityOptions o;
  o.profile_steps = 0;
  o.fit.starts = 1;
  IdentifiabilityReport standing;
  AnalyzeIdentifiability(RigidRingModel(), CarTireTest({0}, 5), o, &standing);
  ASSERT_TRUE(standing.status.ok()) << standing.status.message;
  // Standing, only K_cx / sigma_cx enters.
  EXPECT_NE(Find(standing, Param::sigma_cx).identifiable, Identifiability::kYes);
  EXPECT_NE(Find(standing, Param::K_cx).identifiable, Identifiability::kYes);
  double advised = 0;
  for (const Advice& a : standing.advice) {
    double speed = 0;
    if (a.parameter == "sigma_cx" && a.makes_identifiable &&
        std::sscanf(a.observation.c_str(), "a drum test at %lf m/s", &speed) == 1 && advised == 0) {
      advised = speed;
    }
  }
  ASSERT_GT(advised, 0) << "no drum test advised for sigma_cx";
  IdentifiabilityReport rolling;
  AnalyzeIdentifiability(RigidRingModel(), CarTireTest({0, advised}, 5), o, &rolling);
  ASSERT_TRUE(rolling.status.ok()) << rolling.status.message;
  EXPECT_EQ(Find(rolling, Param::sigma_cx).identifiable, Identifiability::kYes) << advised;
  EXPECT_EQ(Find(rolling, Param::K_cx).identifiable, Identifiability::kYes) << advised;
}

}  // namespace
}  // namespace ringid
