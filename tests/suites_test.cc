// The quick selection of the benchmark suites, with assertions on accuracy
// and coverage (never on time).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "validation/suites.h"
#include "tests/round_trip.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

SuiteOptions Options() {
  SuiteOptions o;
  o.source_dir = RINGID_SOURCE_DIR;
  return o;
}

void ExpectSyntheticCoverage(Derivatives derivatives) {
  SuiteOptions o = Options();
  o.replicates = 60;  // 3 tires x 60 x 10 parameters = 1800 intervals
  o.derivatives = derivatives;
  SyntheticSuite r;
  const Status s = RunSyntheticSuite(o, &r);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_GT(r.coverage_95, 0.90);
  EXPECT_LT(r.coverage_95, 0.99);
  ASSERT_EQ(r.tires.size(), 3u);
  for (const TireCoverage& tire : r.tires) {
    EXPECT_EQ(tire.failed_fits, 0) << tire.tire;
    // |error| / std is half-normal when the std is right: median 0.674.
    EXPECT_NEAR(tire.median_error_over_std, 0.674, 0.15) << tire.tire;
  }
  testing::ExpectRoundTrip(BenchSyntheticReport{{}, r});
}

TEST(SuitesTest, SyntheticIntervalsCoverTheTruthAtTheirLevel) {
  ExpectSyntheticCoverage(Derivatives::kNumeric);
}

TEST(SuitesTest, SyntheticIntervalsCoverTheTruthWithAnalyticDerivatives) {
  ExpectSyntheticCoverage(Derivatives::kAnalytic);
}

TEST(SuitesTest, RollingTireIsIdentifiedStandingAndOnTheDrum) {
  SuiteOptions o = Options();
  o.replicates = 12;  // 12 x 14 = 168 intervals, about 4 s
  RollingSuite r;
  const Status s = RunRollingSuite(o, &r);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(r.failed_fits, 0);
  ASSERT_EQ(r.parameters.size(), 14u);
  for (Param p : {Param::K_cx, Param::sigma_cx}) {
    const RollingParameter* c = r.Find(p);
    ASSERT_NE(c, nullptr) << ToString(p);
    EXPECT_EQ(c->yes, o.replicates) << ToString(p);
  }
  for (const RollingParameter& p : r.parameters) EXPECT_EQ(p.no, 0) << ToString(p.param);
  EXPECT_TRUE(r.ContactClassedYes());
  EXPECT_TRUE(r.NeverNo());
  // A loose check for a small sample: 168 intervals at 95 % cover >= 80 %
  // unless the stds are badly wrong; the 90-99 % criterion is the full suite's
  // (200 replicates, ringid bench --suite=rolling).
  EXPECT_EQ(r.intervals, 12 * 14);
  EXPECT_GE(r.coverage_95, 0.8);
  testing::ExpectRoundTrip(BenchRollingReport{{}, r});
}

TEST(SuitesTest, RollingSuiteRefusesBadSpeeds) {
  SuiteOptions o = Options();
  o.replicates = 1;
  RollingSuite r;
  o.speeds = {};
  EXPECT_TRUE(RunRollingSuite(o, &r).invalid_input());
  o.speeds = {0, 6, 6};
  EXPECT_TRUE(RunRollingSuite(o, &r).invalid_input());
  o.speeds = {0, -1};
  EXPECT_TRUE(RunRollingSuite(o, &r).invalid_input());
}

// The criteria, checked from the counts; a report whose checks disagree with
// its counts does not read.
TEST(SuitesTest, RollingCriteriaFollowTheCounts) {
  RollingSuite r;
  r.replicates = 200;
  r.coverage_95 = 0.95;
  r.parameters = {{Param::K_cx, 8e4, 190, 10, 0, 200, 0.95, 0, 1},
                  {Param::sigma_cx, 0.1, 200, 0, 0, 200, 0.89, 0, 1}};
  EXPECT_TRUE(r.ContactClassedYes());  // 190 of 200 is 95 %
  EXPECT_TRUE(r.NeverNo());
  EXPECT_TRUE(r.CoverageInRange());
  EXPECT_EQ(r.OutsideCoverageRange(), std::vector<Param>{Param::sigma_cx});
  EXPECT_TRUE(r.Pass());
  testing::ExpectRoundTrip(BenchRollingReport{{}, r});
  Json tampered = Json::parse(ReportText(BenchRollingReport{{}, r}));
  r.parameters[0].yes = 189;
  EXPECT_FALSE(r.ContactClassedYes());
  EXPECT_FALSE(r.Pass());
  r.parameters[0].yes = 190;
  r.parameters[1].no = 1;
  EXPECT_FALSE(r.NeverNo());
  r.parameters[1].no = 0;
  r.coverage_95 = 0.991;
  EXPECT_FALSE(r.CoverageInRange());
  tampered["parameters"]["K_cx"]["yes"] = 100;  // "pass" still says true
  BenchRollingReport read;
  std::string error;
  EXPECT_FALSE(ReadReport(tampered, &read, &error));
  EXPECT_NE(error.find("checks.contact_classed_yes"), std::string::npos) << error;
}

TEST(SuitesTest, ConditioningShowsWhatEachKindOfDataDetermines) {
  ConditioningSuite r;
  const Status s = RunConditioningSuite(Options(), &r);
  ASSERT_TRUE(s.ok()) << s.message;
  const auto& v = r.variants;
  ASSERT_EQ(v.size(), 4u);
  EXPECT_EQ(v[0].rank, 7);  // 7 frequencies
  // With shapes and damping only the contact ratios stay undetermined (eq. 9).
  EXPECT_EQ(v[3].rank, 14);
  EXPECT_EQ(v[3].classes.at(Param::K_cx), Identifiability::kNo);
  EXPECT_EQ(v[3].classes.at(Param::sigma_cy), Identifiability::kNo);
  EXPECT_EQ(v[3].classes.at(Param::k_bx), Identifiability::kYes);
  testing::ExpectRoundTrip(BenchConditioningReport{{}, r});
}

TEST(SuitesTest, PaperSuiteReproducesTable3AndFitsTable1) {
  PaperSuite r;
  const Status s = RunPaperSuite(Options(), &r);
  ASSERT_TRUE(s.ok()) << s.message;
  ASSERT_EQ(r.table3.size(), 7u);
  for (const Table3Row& row : r.table3) {
    const bool in_plane = LabelPlane(row.label) == Plane::kInPlane;
    EXPECT_NEAR(row.model_hz, row.paper_hz, in_plane ? 0.1 : 0.3) << LabelName(row.label);
  }
  ASSERT_EQ(r.identify[0].method, Method::kLevenbergMarquardt);
  EXPECT_LT(r.identify[0].relative_error_in_plane_eq19, 1e-8);
  EXPECT_LT(r.identify[0].relative_error_out_of_plane_eq20, 1e-8);
  testing::ExpectRoundTrip(BenchPaperReport{{}, r});
}

TEST(SuitesTest, ScaledTiresKeepTheirDampingRatios) {
  const Parameters paper = testing::PaperIdentified();
  const ModalSolution a = RigidRingModel().Solve(paper);
  const ModalSolution b = RigidRingModel().Solve(ScaledTire(paper, 1.5));
  ASSERT_TRUE(a.ok && b.ok);
  for (const Mode& m : a.modes) {
    const Mode* n = b.Find(m.label);
    ASSERT_NE(n, nullptr);
    EXPECT_NEAR(n->damping_ratio, m.damping_ratio, 1e-9) << LabelName(m.label);
    // Frequencies scale as sqrt(k / m) = s^(-1/2).
    EXPECT_NEAR(n->frequency_hz, m.frequency_hz / std::sqrt(1.5), 1e-9 * m.frequency_hz);
  }
}

}  // namespace
}  // namespace ringid
