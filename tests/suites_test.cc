// The quick selection of the benchmark suites, with assertions on accuracy
// and coverage (never on time).
#include <cmath>

#include <gtest/gtest.h>

#include "benchmarks/suites.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

SuiteOptions Options() {
  SuiteOptions o;
  o.source_dir = RINGID_SOURCE_DIR;
  return o;
}

TEST(SuitesTest, SyntheticIntervalsCoverTheTruthAtTheirLevel) {
  SuiteOptions o = Options();
  o.replicates = 60;  // 3 tires x 60 x 10 parameters = 1800 intervals
  const SuiteResult r = RunSuite("synthetic", o);
  ASSERT_TRUE(r.ok) << r.error;
  const double coverage = r.report["coverage_95"].get<double>();
  EXPECT_GT(coverage, 0.90);
  EXPECT_LT(coverage, 0.99);
  for (const auto& tire : r.report["tires"]) {
    EXPECT_EQ(tire["failed_fits"].get<int>(), 0) << tire["tire"];
    // |error| / std is half-normal when the std is right: median 0.674.
    EXPECT_NEAR(tire["median_error_over_std"].get<double>(), 0.674, 0.15) << tire["tire"];
  }
}

TEST(SuitesTest, ConditioningShowsWhatEachKindOfDataDetermines) {
  const SuiteResult r = RunSuite("conditioning", Options());
  ASSERT_TRUE(r.ok) << r.error;
  const auto& v = r.report["variants"];
  ASSERT_EQ(v.size(), 4u);
  EXPECT_EQ(v[0]["rank"], 7);  // 7 frequencies
  // With shapes and damping only the contact ratios stay undetermined (eq. 9).
  EXPECT_EQ(v[3]["rank"], 14);
  EXPECT_EQ(v[3]["classes"]["K_cx"], "no");
  EXPECT_EQ(v[3]["classes"]["sigma_cy"], "no");
  EXPECT_EQ(v[3]["classes"]["k_bx"], "yes");
}

TEST(SuitesTest, PaperSuiteReproducesTable3AndFitsTable1) {
  const SuiteResult r = RunSuite("paper", Options());
  ASSERT_TRUE(r.ok) << r.error;
  for (const auto& row : r.report["table3"]) {
    const bool in_plane = row["label"] == "rotation_in_phase" || row["label"] == "rotation_anti_phase" ||
                          row["label"] == "vertical" || row["label"] == "longitudinal";
    EXPECT_NEAR(row["model_hz"].get<double>(), row["paper_hz"].get<double>(), in_plane ? 0.1 : 0.3)
        << row["label"];
  }
  EXPECT_LT(r.report["identify"]["lm"]["eq19"].get<double>(), 1e-8);
  EXPECT_LT(r.report["identify"]["lm"]["eq20"].get<double>(), 1e-8);
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
