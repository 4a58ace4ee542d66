// One answer whatever the start (issue 21): the starts, the stopping rule and
// the diagnosis checked on the datasets that exposed the defects
// (tests/data, README.md there) and on synthetic truths.
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "datasets/synthetic.h"
#include "estimation/diagnose_internal.h"
#include "estimation/diagnose.h"
#include "estimation/identifiability.h"
#include "estimation/identify.h"
#include "estimation/problem.h"
#include "estimation/starts.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using testing::SourcePath;

// A dataset written by a new user, carried in tests/data (README.md there says where from).
Dataset Case(const std::string& name) {
  Dataset d;
  LoadError e;
  EXPECT_TRUE(LoadDataset(SourcePath("tests/data/" + name), &d, &e)) << e.message;
  return d;
}

Dataset Load(const std::string& relative) {
  Dataset d;
  LoadError e;
  EXPECT_TRUE(LoadDataset(SourcePath(relative), &d, &e)) << e.message;
  return d;
}

const ParameterEstimate& Find(const IdentifyResult& s, Param p) {
  for (const ParameterEstimate& e : s.estimates) {
    if (e.param() == p) return e;
  }
  ADD_FAILURE() << ParamName(p);
  return s.estimates.front();
}

// The initial model's lateral and camber modes are swapped against the data:
// from that start alone LM ends at chi-square 692, which was reported as the
// model missing what the data show; the default starts find the fit, and a
// lone start says that it may be to blame.
TEST(StartsTest, SwappedModesAtTheInitialPointStillFitFromTheDefaultStarts) {
  const Dataset d = Case("newcomer_standing_noshape.json");
  IdentifyOptions one;
  one.starts = 1;
  IdentifyResult alone, s;
  Identify(RigidRingModel(), d, one, &alone);
  Identify(RigidRingModel(), d, IdentifyOptions(), &s);
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  ASSERT_TRUE(alone.fit.poor);
  EXPECT_NE(alone.fit.verdict.find("no start found the best point"), std::string::npos)
      << alone.fit.verdict;
  EXPECT_FALSE(s.fit.poor) << s.fit.verdict;
  EXPECT_EQ(s.start_origins.front(), StartOrigin::kInitial);
  // Few starts reach this optimum (the labels of the coupled lateral and
  // camber modes change across it); the report must say so when one does.
  if (s.start_agreement.at_best == 1) {
    EXPECT_NE(s.start_agreement.verdict.find("only 1 of"), std::string::npos);
  }
}

// All four old starts ended at chi-square 1118 with r_e0 = 8.37 m.
TEST(StartsTest, RollingDataWithPriorsFitFromTheDefaultStarts) {
  const Dataset d = Case("newcomer_rolling_priors.json");
  IdentifyOptions o;
  o.residuals.derivatives = Derivatives::kAnalytic;
  IdentifyResult s;
  Identify(RigidRingModel(), d, o, &s);
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  EXPECT_FALSE(s.fit.poor) << s.fit.verdict;
  EXPECT_LT(Find(s, Param::r_e0).value, 0.5);  // a car tire's rolling radius
  EXPECT_GE(s.start_agreement.at_best, 2) << s.start_agreement.verdict;
}

// Stiffnesses three times too high and a third too low in turn: the matched
// start has the measured frequencies of almost noise-free data (the closed form the
// engineer would use), which the initial point misses by tens of percent.
TEST(StartsTest, FrequencyMatchedStartHasTheMeasuredFrequencies) {
  const Parameters truth = ExampleCarTire();
  std::mt19937_64 rng(5);
  Dataset d;
  d.name = "matched";
  SetEngineerPriors(truth, 0, &rng, &d);
  SimulateOptions so;
  so.frequency_noise = 1e-4;  // the sigmas: not 0
  so.damping_noise = 1e-3;
  so.shapes = false;
  std::string why;
  ASSERT_TRUE(Simulate(RigidRingModel(), truth, so, &rng, &d, &why)) << why;
  int k = 0;
  for (auto& [p, v] : d.initial) {
    if (IsStiffness(p)) v *= (k++ % 2 ? 3.0 : 1 / 3.0);
  }
  Status status;
  const auto problem = Problem::Create(RigidRingModel(), d, ResidualOptions(), &status);
  ASSERT_TRUE(problem) << status.message;
  const internal::ModalResiduals& r = problem->residuals();
  const Eigen::VectorXd x0 = problem->start();
  const internal::Box box = internal::BoundsAround(problem->setup(), x0, 1e3);
  auto worst = [&](const Eigen::VectorXd& x) {
    std::vector<ModalSolution> solutions;
    std::vector<int> pairs;
    std::string why;
    EXPECT_TRUE(r.Pair(x.data(), &solutions, &pairs, &why)) << why;
    double w = 0;
    for (size_t i = 0; i < d.modes.size(); ++i) {
      const double f = solutions[d.modes[i].condition].modes[pairs[i]].frequency_hz;
      w = std::max(w, std::abs(std::log(f / d.modes[i].frequency_hz)));
    }
    return w;
  };
  EXPECT_GT(worst(x0), 0.2);
  EXPECT_LT(worst(internal::MatchFrequencies(r, x0, box)), 0.02);
}

TEST(StartsTest, StartsAtTheBestAreCountedAndALoneOneIsWarnedAbout) {
  Status status;
  const auto problem = Problem::Create(RigidRingModel(), Load("datasets/template.json"),
                                       ResidualOptions(), &status);
  ASSERT_TRUE(problem) << status.message;
  const internal::ParameterSetup& setup = problem->setup();
  const Eigen::VectorXd x = problem->start();
  Eigen::VectorXd y = x;
  y[0] += std::log(2.0);  // a positive parameter twice as large
  ASSERT_TRUE(setup.is_log(0));
  const StartAgreement two = internal::AssessStarts(setup, {10.0, 10.3, 50.0}, {x, y, x});
  EXPECT_EQ(two.at_best, 2);
  EXPECT_EQ(two.of, 3);
  ASSERT_EQ(two.disagree.count(setup.name(0)), 1u);
  EXPECT_NEAR(two.disagree.at(setup.name(0)), 2.0, 1e-12);
  EXPECT_NE(two.verdict.find("different values of " + setup.name(0)), std::string::npos)
      << two.verdict;
  const StartAgreement alone = internal::AssessStarts(setup, {10.0, 10.6, 50.0}, {x, y, x});
  EXPECT_EQ(alone.at_best, 1);  // 10.6 is chi-square 1.2 above
  EXPECT_TRUE(alone.disagree.empty());
  EXPECT_NE(alone.verdict.find("only 1 of 3"), std::string::npos) << alone.verdict;
}

// Levenberg-Marquardt crawled 700 iterations to Ceres' relative 1e-14 on
// this problem; stopped in chi-square units it converges within the default
// 200, at the same point: cost within the rule's resolution, every standard
// deviation within 1 % and every value within 5 % of its standard deviation.
TEST(StoppingTest, TableOneWithPriorsConvergesWithinTheDefaultIterations) {
  const Dataset d = Load("datasets/paper/table1_priors.json");
  IdentifyOptions o;
  o.starts = 1;
  IdentifyResult s, crawled;
  Identify(RigidRingModel(), d, o, &s);
  o.stop_chi_square = 0;
  o.max_iterations = 5000;
  Identify(RigidRingModel(), d, o, &crawled);
  ASSERT_TRUE(s.status.ok() && crawled.status.ok());
  EXPECT_TRUE(s.converged) << s.status.message;
  EXPECT_NEAR(s.fit.chi_square, crawled.fit.chi_square, 2 * kStopChiSquare);
  for (size_t k = 0; k < s.estimates.size(); ++k) {
    const ParameterEstimate& a = s.estimates[k];
    const ParameterEstimate& b = crawled.estimates[k];
    if (!a.std || !b.std) continue;
    EXPECT_NEAR(*a.std / *b.std, 1.0, 0.01) << a.key.Text();
    EXPECT_NEAR(a.value, b.value, 0.05 * *b.std) << a.key.Text();
  }
}

// From its initial values this rolling dataset's fit crawls to a kink of the
// cost (gradient 7 to the end, each gain a fixed fraction of the one before):
// 67 iterations to Ceres' relative 1e-12 step. The geometric tail of the gains
// stops it where the rest is below the rule's resolution, at the same cost.
TEST(StoppingTest, ACrawlToAKinkStopsWhenWhatItsGainsPromiseIsBelowTheResolution) {
  const Dataset d = Case("newcomer_rolling.json");
  IdentifyOptions o;
  o.starts = 1;
  o.residuals.derivatives = Derivatives::kAnalytic;
  IdentifyResult s, crawled;
  Identify(RigidRingModel(), d, o, &s);
  o.stop_chi_square = 0;
  Identify(RigidRingModel(), d, o, &crawled);
  ASSERT_TRUE(s.status.ok() && crawled.status.ok());
  EXPECT_TRUE(s.converged) << s.status.message;
  EXPECT_NE(s.status.message.find("gains shrink geometrically"), std::string::npos)
      << s.status.message;
  EXPECT_LT(s.evaluations, crawled.evaluations);
  EXPECT_NEAR(s.fit.chi_square, crawled.fit.chi_square, 2 * kStopChiSquare);
  ASSERT_EQ(s.x.size(), crawled.x.size());
  for (int i = 0; i < s.x.size(); ++i) {
    EXPECT_NEAR(s.x[i], crawled.x[i], 1e-3) << s.coordinate_names[i];  // log: 0.1 %
  }
}

// The profile bounds move by less than 1 % when the fits inside them stop in
// chi-square units instead of at 1e-14.
TEST(StoppingTest, ProfileBoundsDoNotMoveWithTheStoppingRule) {
  const Dataset d = Load("datasets/template.json");
  IdentifiabilityOptions o;
  IdentifiabilityResult loose, tight;
  AnalyzeIdentifiability(RigidRingModel(), d, o, &loose);
  o.fit.stop_chi_square = 0;
  AnalyzeIdentifiability(RigidRingModel(), d, o, &tight);
  ASSERT_TRUE(loose.status.ok() && tight.status.ok());
  ASSERT_EQ(loose.parameters.size(), tight.parameters.size());
  for (size_t k = 0; k < loose.parameters.size(); ++k) {
    const auto& a = loose.parameters[k];
    const auto& b = tight.parameters[k];
    for (const auto& [x, y] : {std::pair{a.profile_95.lower, b.profile_95.lower},
                               std::pair{a.profile_95.upper, b.profile_95.upper}}) {
      if (!x || !y) continue;
      EXPECT_NEAR(*x / *y, 1.0, 0.01) << a.key.Text();
    }
  }
}

// Made from simulated values without any effect (identify: chi-square 3.05
// on 26 dof), this was called anisotropic_sidewall at p = 1.6e-117, with a
// contact_yaw_stiffness row at k_cpsi = 0 'supported' at p = 6e-139.
TEST(DiagnoseStartTest, EffectFreeRollingDataRaiseNoAlarm) {
  DiagnoseOptions o;
  o.held_out = false;
  o.fit.residuals.derivatives = Derivatives::kAnalytic;
  DiagnosisResult r;
  Diagnose(RigidRingModel(), Case("newcomer_rolling.json"), o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.verdict, nullptr) << r.explanation;
  EXPECT_FALSE(r.significant) << r.explanation;
  for (const EffectFit& f : r.ranking) {
    EXPECT_FALSE(f.supported) << f.effect->name();
    if (f.ok) EXPECT_LE(f.chi2, r.chi2_before + 0.1) << f.effect->name();
  }
}

// The initial values are where the fits start, never a prior: the same data
// from a guess a factor 3 off and from the truth get the same verdict and gap.
TEST(DiagnoseStartTest, GuessAFactorThreeOffGetsTheVerdictOfTheTruth) {
  Parameters truth = ExampleCarTire();
  std::mt19937_64 rng(11);
  Dataset exact;
  exact.name = "factor3";
  SetEngineerPriors(truth, 0, &rng, &exact);
  std::string why;
  ASSERT_TRUE(Simulate(RigidRingModel(), truth, SimulateOptions{}, &rng, &exact, &why)) << why;
  Dataset rough = exact;
  int k = 0;
  for (auto& [p, v] : rough.initial) v *= (k++ % 2 ? 3.0 : 1 / 3.0);
  DiagnoseOptions o;
  o.held_out = false;
  o.fit.residuals.derivatives = Derivatives::kAnalytic;
  DiagnosisResult a, b;
  Diagnose(RigidRingModel(), rough, o, &a);
  Diagnose(RigidRingModel(), exact, o, &b);
  ASSERT_TRUE(a.status.ok() && b.status.ok());
  EXPECT_EQ(a.verdict, nullptr) << a.explanation;
  EXPECT_EQ(b.verdict, nullptr) << b.explanation;
  EXPECT_NEAR(a.chi2_before, b.chi2_before, 2 * kSameOptimumChiSquare);
  EXPECT_EQ(a.significant, b.significant);
}

TEST(DiagnoseStartTest, HeldOutMisfitThatRisesIsSaidToRise) {
  const std::string worse = internal::HeldOutChange(6515.11, 118667);
  EXPECT_NE(worse.find("rises from chi-square 6515.11 to 118667"), std::string::npos) << worse;
  EXPECT_EQ(worse.find("less"), std::string::npos) << worse;
  EXPECT_EQ(worse.find("%"), std::string::npos) << worse;
  const std::string better = internal::HeldOutChange(200, 50);
  EXPECT_NE(better.find("falls from chi-square 200 to 50 (75 % less)"), std::string::npos) << better;
}

}  // namespace
}  // namespace ringid
