// The quick selection of the benchmark suites, with assertions on accuracy
// and coverage (never on time).
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "datasets/synthetic.h"
#include "model/rigid_ring_model.h"
#include "validation/speed_cases.h"
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

// The static suite on 12 tires (the full one is 200, ringid bench
// --suite=static): standing modes and static stiffnesses identify every free
// parameter from starts scattered within a factor 3, and the intervals of
// 12 x 14 estimates cover the truth at least 80 % of the time (the 90-99 %
// criterion per parameter is the full suite's).
TEST(SuitesTest, StaticStiffnessesAndModesIdentifyScatteredTiresFromScatteredStarts) {
  SuiteOptions o = Options();
  o.replicates = 12;
  StaticSuite r;
  const Status s = RunStaticSuite(o, &r);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(r.failed_fits, 0);
  ASSERT_EQ(r.parameters.size(), 14u);
  long inside = 0, intervals = 0;
  for (const StaticParameter& p : r.parameters) {
    EXPECT_EQ(p.no, 0) << ToString(p.param);
    EXPECT_GE(p.yes, 10) << ToString(p.param);
    inside += std::lround(p.coverage_95 * p.intervals);
    intervals += p.intervals;
  }
  ASSERT_GT(intervals, 0);
  EXPECT_GE(static_cast<double>(inside) / intervals, 0.8);
  testing::ExpectRoundTrip(BenchStaticReport{{}, r});
}

// The forces suite on 60 replicates (the full one is 200, ringid bench
// --suite=forces): 2700 estimates per method. With the true parameters the
// estimates spread as std_measurement says (rms z within 0.1 of 1); with the
// identified ones std_total covers at least 90 % and std_measurement less;
// weighted least squares is at least as accurate as the unweighted
// pseudo-inverse, which five channels for three forces over-determine.
TEST(SuitesTest, ForcesAreRecoveredWithIntervalsThatCover) {
  SuiteOptions o = Options();
  o.replicates = 60;
  o.derivatives = Derivatives::kAnalytic;
  ForcesSuite r;
  const Status s = RunForcesSuite(o, &r);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(r.failed_fits, 0);
  ASSERT_EQ(r.methods.size(), 4u);
  for (const ForcesMethodRow& m : r.methods) EXPECT_EQ(m.estimates, 60 * 3 * 5 * 3) << ToString(m.method);
  EXPECT_TRUE(r.StdIsRight());
  const ForcesMethodRow* fit = r.Find(ForcesMethod::kIdentified);
  ASSERT_NE(fit, nullptr);
  EXPECT_GE(*fit->coverage_total, 0.9);
  EXPECT_LT(*fit->coverage_measurement, *fit->coverage_total);
  EXPECT_LE(fit->rms_error, r.Find(ForcesMethod::kPseudoInverse)->rms_error);
  EXPECT_NEAR(r.resonance_speed_m_s * 20 / (2 * M_PI * ExampleCarTire()[Param::r_e0]),
              RigidRingModel().Solve(ExampleCarTire(), r.resonance_speed_m_s).Find(ModeLabel::kVertical)->frequency_hz,
              1e-3);
  testing::ExpectRoundTrip(BenchForcesReport{{}, r});
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
  r.parameters = {{{190, 10, 0, 200, 0.95, 0, 1}, Param::K_cx, 8e4},
                  {{200, 0, 0, 200, 0.89, 0, 1}, Param::sigma_cx, 0.1}};
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

// The speed suite, timed briefly: every case, both modes where they apply, and
// ratios and verdicts that follow from the times. Never a time threshold: the
// targets are the suite's to report, not the tests' to assert.
TEST(SuitesTest, SpeedSuiteTimesEveryCaseNumericAndAnalyticSideBySide) {
  SuiteOptions o = Options();
  o.speed_batches = 3;
  o.speed_seconds_per_case = 0.02;
  int progress = 0;
  o.on_case = [&](int done, int total) {
    EXPECT_EQ(done, progress + 1);
    EXPECT_GE(total, done);
    progress = done;
  };
  SpeedSuite r;
  const Status s = RunSpeedSuite(o, &r);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_GT(progress, 0);
  EXPECT_EQ(r.batches, 3);
  EXPECT_GT(r.seconds, 0);
  const size_t cases = EnumNames<SpeedCase>::kNames.size();
  ASSERT_EQ(r.rows.size(), cases);
  for (size_t i = 0; i < cases; ++i) {
    const SpeedRow& row = r.rows[i];
    const SpeedCase c = static_cast<SpeedCase>(i);
    ASSERT_EQ(row.name, c) << i;  // every case, once, in order
    ASSERT_TRUE(row.numeric_seconds) << ToString(c);
    EXPECT_GT(*row.numeric_seconds, 0) << ToString(c);
    const bool analytic = c != SpeedCase::kBareEigenSolve && c != SpeedCase::kBareEigenValues &&
                          c != SpeedCase::kModelEvaluationRolling;
    ASSERT_EQ(row.analytic_seconds.has_value(), analytic) << ToString(c);
    if (analytic) EXPECT_GT(*row.analytic_seconds, 0) << ToString(c);
    const bool target = c == SpeedCase::kModelEvaluation || c == SpeedCase::kIdentifyInPlane ||
                        c == SpeedCase::kJointFitThreeConditions;
    EXPECT_EQ(!row.target.empty(), target) << ToString(c);
    EXPECT_EQ(row.met.has_value(), target) << ToString(c);
    EXPECT_EQ(row.met, r.Met(c)) << ToString(c);
  }
  const auto row = [&](SpeedCase c) { return *r.Find(c); };
  const SpeedRow evaluation = row(SpeedCase::kModelEvaluation);
  const SpeedRow bare = row(SpeedCase::kBareEigenSolve);
  const SpeedRow bare_values = row(SpeedCase::kBareEigenValues);
  const SpeedRow standing = row(SpeedCase::kJointFitStanding);
  const SpeedRow three = row(SpeedCase::kJointFitThreeConditions);
  ASSERT_TRUE(r.EvaluationOverBareSolve());
  EXPECT_EQ(*r.EvaluationOverBareSolve(), *evaluation.numeric_seconds / *bare.numeric_seconds);
  EXPECT_EQ(*r.EvaluationOverBareEigenvalues(),
            *evaluation.numeric_seconds / *bare_values.numeric_seconds);
  EXPECT_EQ(*r.DerivativesOverEvaluation(),
            *evaluation.analytic_seconds / *evaluation.numeric_seconds);
  EXPECT_EQ(*r.JointFitOverStanding(Derivatives::kNumeric),
            *three.numeric_seconds / *standing.numeric_seconds);
  EXPECT_EQ(*r.JointFitOverStanding(Derivatives::kAnalytic),
            *three.analytic_seconds / *standing.analytic_seconds);
  EXPECT_EQ(*evaluation.met, *r.EvaluationOverBareSolve() <= r.evaluation_over_bare_solve_max);
  EXPECT_EQ(*row(SpeedCase::kIdentifyInPlane).met,
            *row(SpeedCase::kIdentifyInPlane).analytic_seconds <= r.identify_in_plane_max_seconds);
  EXPECT_EQ(*three.met,
            *r.JointFitOverStanding(Derivatives::kAnalytic) <= r.joint_fit_over_standing_max);
  const std::string md = r.Markdown();
  for (const SpeedRow& x : r.rows) {
    EXPECT_NE(md.find(std::string("| ") + SpeedCaseText(x.name) + " |"), std::string::npos)
        << ToString(x.name);
  }
  testing::ExpectRoundTrip(BenchSpeedReport{{}, r});
}

// The ratios are derived: a report whose times were changed under them does
// not read.
TEST(SuitesTest, SpeedRatiosFollowTheTimes) {
  SpeedSuite r;
  const auto add = [&](SpeedCase c, std::optional<double> numeric, std::optional<double> analytic) {
    r.rows.push_back({c, numeric, analytic, "", std::nullopt});
  };
  add(SpeedCase::kModelEvaluation, 12e-6, 36e-6);
  add(SpeedCase::kBareEigenSolve, 10e-6, std::nullopt);
  add(SpeedCase::kIdentifyInPlane, 1.2e-3, 0.9e-3);
  add(SpeedCase::kJointFitStanding, 5e-3, 1e-3);
  add(SpeedCase::kJointFitThreeConditions, 30e-3, 4e-3);
  EXPECT_DOUBLE_EQ(*r.EvaluationOverBareSolve(), 1.2);
  EXPECT_DOUBLE_EQ(*r.DerivativesOverEvaluation(), 3);
  EXPECT_DOUBLE_EQ(*r.JointFitOverStanding(Derivatives::kNumeric), 6);
  EXPECT_DOUBLE_EQ(*r.JointFitOverStanding(Derivatives::kAnalytic), 4);
  EXPECT_EQ(r.Met(SpeedCase::kIdentifyInPlane), true);
  EXPECT_EQ(r.Met(SpeedCase::kJointFitThreeConditions), true);  // 4x is within 4x
  EXPECT_EQ(r.Met(SpeedCase::kJointFitStanding), std::nullopt);  // no target
  r.rows[2].analytic_seconds = 1.1e-3;
  EXPECT_EQ(r.Met(SpeedCase::kIdentifyInPlane), false);
  r.rows[1].numeric_seconds = std::nullopt;  // a missing time: no ratio, no verdict
  EXPECT_EQ(r.EvaluationOverBareSolve(), std::nullopt);
  EXPECT_EQ(r.Met(SpeedCase::kModelEvaluation), std::nullopt);
  r.rows[1].numeric_seconds = 10e-6;
  testing::ExpectRoundTrip(BenchSpeedReport{{}, r});
  Json tampered = Json::parse(ReportText(BenchSpeedReport{{}, r}));
  tampered["rows"]["bare_eigen_solve"]["numeric_seconds"] = 5e-6;  // the ratio still says 1.2
  BenchSpeedReport read;
  std::string error;
  EXPECT_FALSE(ReadReport(tampered, &read, &error));
  EXPECT_NE(error.find("ratios.evaluation_over_bare_solve"), std::string::npos) << error;
}

TEST(SuitesTest, SpeedSuiteRefusesBadTiming) {
  SpeedSuite r;
  SuiteOptions o = Options();
  o.speed_batches = 0;
  EXPECT_TRUE(RunSpeedSuite(o, &r).invalid_input());
  o = Options();
  for (double seconds : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
    o.speed_seconds_per_case = seconds;
    EXPECT_TRUE(RunSpeedSuite(o, &r).invalid_input()) << seconds;
  }
}

// The cases the Google Benchmark and the speed suite share.
TEST(SuitesTest, SpeedCasesAreTheProblemsTheyName) {
  Dataset in_plane, both;
  ASSERT_TRUE(SpeedTable1(RINGID_SOURCE_DIR, true, &in_plane).ok());
  ASSERT_TRUE(SpeedTable1(RINGID_SOURCE_DIR, false, &both).ok());
  EXPECT_EQ(both.modes.size(), 7u);
  EXPECT_EQ(in_plane.modes.size(), 4u);
  for (const MeasuredMode& m : in_plane.modes) EXPECT_EQ(LabelPlane(m.label), Plane::kInPlane);
  for (const auto& [p, v] : in_plane.initial) {
    EXPECT_NE(Info(p).group, Group::kOutOfPlane) << ToString(p);  // held, not fitted
  }
  Parameters paper;
  ASSERT_TRUE(SpeedPaperParameters(RINGID_SOURCE_DIR, &paper).ok());
  const std::vector<SpeedBlock> blocks = BareEigenBlocks(paper);
  ASSERT_EQ(blocks.size(), 3u);
  EXPECT_EQ(blocks[0].rows(), 6);  // x_b, theta_a, theta_b and their velocities
  EXPECT_EQ(blocks[1].rows(), 2);  // z_b
  EXPECT_EQ(blocks[2].rows(), 6);  // y_b, gamma_b, psi_b
  Dataset three;
  ASSERT_TRUE(SpeedCarTire({0, 6, 12}, &three).ok());
  EXPECT_EQ(three.conditions.size(), 3u);
  EXPECT_EQ(three.initial.size(), 14u);
  EXPECT_EQ(three.ties.size(), 4u);
  Dataset missing;
  EXPECT_TRUE(SpeedTable1("/nonexistent", false, &missing).invalid_input());
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
