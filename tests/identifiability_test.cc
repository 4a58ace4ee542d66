// The identifiability analysis against structure known from the equations.
#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "datasets/synthetic.h"
#include "estimation/identifiability_internal.h"
#include "estimation/fit.h"
#include "estimation/identifiability.h"
#include "estimation/problem.h"
#include "estimation/statistics.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using testing::PaperIdentified;

const ParameterIdentifiability& Find(const IdentifiabilityResult& r, Param p) {
  for (const auto& q : r.parameters) {
    if (q.param() == p) return q;
  }
  ADD_FAILURE() << "no " << ParamName(p);
  return r.parameters.front();
}

bool HasMeaning(const IdentifiabilityResult& r, const std::string& text) {
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
  IdentifiabilityResult r;
  AnalyzeIdentifiability(RigidRingModel(), d, o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.rank, 7);
  EXPECT_NE(r.rank_explanation.find("7 observations cannot determine 16"), std::string::npos)
      << r.rank_explanation;
  // Eq. (9)-(10): K_cx and sigma_cx (K_cy, sigma_cy) enter only as K / sigma.
  for (Param p : {Param::K_cx, Param::sigma_cx, Param::K_cy, Param::sigma_cy}) {
    EXPECT_EQ(Find(r, p).identifiable, Identifiability::kNo) << ParamName(p);
  }
  EXPECT_TRUE(HasMeaning(r, "structurally free: only K_cx / sigma_cx enters the model"));
  EXPECT_TRUE(HasMeaning(r, "structurally free: only K_cy / sigma_cy enters the model"));
  // Every parameter has a component in one of the 9 free directions (class
  // no), so none is determined while the others are free.
  EXPECT_TRUE(r.identifiable_subset.empty());
}

// One problem, built once and passed: Identify on it gives the fit of the
// one-call form, AnalyzeIdentifiability of that fit the one-call analysis,
// and a fit of another problem is refused as input, not analysed.
TEST(IdentifiabilityTest, AProblemBuiltOnceAndPassedGivesTheOneCallResults) {
  Dataset d;
  LoadError e;
  ASSERT_TRUE(LoadDataset(testing::SourcePath("datasets/paper/table1.json"), &d, &e));
  IdentifiabilityOptions o;
  o.profile_steps = 0;
  Status status;
  const auto problem = Problem::Create(RigidRingModel(), d, o.fit.residuals, &status);
  ASSERT_TRUE(problem) << status.message;
  IdentifyResult fit, once;
  Identify(*problem, o.fit, &fit);
  Identify(RigidRingModel(), d, o.fit, &once);
  ASSERT_TRUE(fit.status.ok()) << fit.status.message;
  EXPECT_EQ(fit.cost, once.cost);
  EXPECT_EQ(fit.x, once.x);
  EXPECT_EQ(fit.evaluations, once.evaluations);
  IdentifiabilityResult passed, whole;
  AnalyzeIdentifiability(*problem, fit, o, &passed);
  AnalyzeIdentifiability(RigidRingModel(), d, o, &whole);
  ASSERT_TRUE(passed.status.ok()) << passed.status.message;
  EXPECT_EQ(passed.rank, whole.rank);
  EXPECT_EQ(passed.singular_values, whole.singular_values);
  ASSERT_EQ(passed.parameters.size(), whole.parameters.size());
  for (size_t i = 0; i < passed.parameters.size(); ++i) {
    EXPECT_EQ(passed.parameters[i].identifiable, whole.parameters[i].identifiable) << i;
  }
  Dataset fewer = d;
  fewer.known[Param::t_0] = fewer.initial.at(Param::t_0);
  fewer.initial.erase(Param::t_0);
  const auto other = Problem::Create(RigidRingModel(), fewer, o.fit.residuals, &status);
  ASSERT_TRUE(other) << status.message;
  IdentifiabilityResult refused;
  AnalyzeIdentifiability(*other, fit, o, &refused);
  EXPECT_TRUE(refused.status.invalid_input()) << refused.status.message;
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
    if (IsBaseline(ParamAt(i))) d.known[ParamAt(i)] = truth[ParamAt(i)];
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
  IdentifiabilityResult r;
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

// 2 delta cost with coordinate i held at `value` (physical units), the
// others refitted from the optimum: a refit of its own, independent of the
// path the profile took to get there.
double DeltaChi2At(const Dataset& d, const IdentifiabilityOptions& o,
                   const IdentifiabilityResult& r, int i, double value) {
  Status status;
  const auto problem = Problem::Create(RigidRingModel(), d, o.fit.residuals, &status);
  EXPECT_TRUE(problem) << status.message;
  if (!problem) return NAN;
  const internal::ParameterSetup& setup = problem->setup();
  const internal::Box box =
      internal::BoundsAround(setup, problem->start(), o.fit.bound_factor, o.fit.bounds);
  Eigen::VectorXd x = r.fit.x;
  x[i] = setup.ToCoordinate(i, value);
  const internal::LocalFit fit =
      internal::FitLocally(problem->residuals(), Method::kLevenbergMarquardt, x, box,
                           o.fit.max_iterations, o.fit.simplex, i);
  return 2 * (fit.cost - r.fit.cost);
}

// The closed profile bounds as (coordinate, value).
std::vector<std::pair<int, double>> ClosedBounds(const IdentifiabilityResult& r) {
  std::vector<std::pair<int, double>> bounds;
  for (int i = 0; i < static_cast<int>(r.parameters.size()); ++i) {
    const ProfileInterval& p = r.parameters[i].profile_95;
    for (const std::optional<double>& bound : {p.lower, p.upper}) {
      if (bound) bounds.emplace_back(i, *bound);
    }
  }
  return bounds;
}

// The paper's tire measured as `ringid simulate
// --parameters=datasets/paper/parameters.json --seed=SEED` does (the
// engineer's priors and ties), under `model`, with `set` changed in the truth.
Dataset SimulatedPaperTire(const RigidRingModel& model, const std::map<Param, double>& set,
                           Parameters* truth, uint64_t seed = IdentifyOptions().seed) {
  LoadError error;
  EXPECT_TRUE(LoadParameterSet(testing::SourcePath("datasets/paper/parameters.json"), truth,
                               &error))
      << error.OneLine();
  for (const auto& [p, value] : set) (*truth)[p] = value;
  std::mt19937_64 rng(seed);
  Dataset d;
  d.name = "paper_tire";
  SetEngineerPriors(*truth, 0.1, &rng, &d);
  std::string why;
  EXPECT_TRUE(Simulate(model, *truth, SimulateOptions{}, &rng, &d, &why)) << why;
  return d;
}

// With m_a = 15 the lateral mode is strongly complex, and at the best fit
// its y_b and gamma_b components are nearly as large as each other. Rotated
// by the phase of the model's largest component, its real part flipped where
// the two tied: a step in the shape residuals at which Levenberg-Marquardt
// stalled. Fits from the dataset's start ended 1.5 in chi-square and more
// above the best point, and the c_bx profile, refitted across the step,
// came out 20 times narrower than its Wald interval. Rotated by the measured
// shape's largest component, the residuals are smooth there.
TEST(IdentifiabilityTest, FitsAndProfilesCrossWhereTwoComponentsOfAModelShapeTie) {
  Parameters truth;
  const Dataset d = SimulatedPaperTire(RigidRingModel(), {{Param::m_a, 15.0}}, &truth, 3);
  IdentifyOptions o;
  o.starts = 1;
  o.residuals.derivatives = Derivatives::kAnalytic;
  Dataset from_truth = d;
  for (auto& [p, v] : from_truth.initial) v = truth[p];
  IdentifyResult rough, near;
  Identify(RigidRingModel(), d, o, &rough);
  Identify(RigidRingModel(), from_truth, o, &near);
  ASSERT_TRUE(rough.status.ok() && near.status.ok());
  EXPECT_NEAR(2 * rough.cost, 2 * near.cost, kSameOptimumChiSquare);
  // One standard deviation of c_bx from the better of the two, a refit of
  // the others gives about 1 in chi-square (near-linear: the in-plane block
  // does not involve the lateral shape).
  const IdentifyResult& best = rough.cost < near.cost ? rough : near;
  IdentifiabilityOptions io;
  io.fit = o;
  IdentifiabilityResult r;
  r.fit = best;
  const auto e = std::find_if(best.estimates.begin(), best.estimates.end(),
                              [](const ParameterEstimate& p) { return p.param() == Param::c_bx; });
  const int i = static_cast<int>(std::find(best.coordinate_names.begin(),
                                           best.coordinate_names.end(), "c_bx") -
                                 best.coordinate_names.begin());
  ASSERT_TRUE(e != best.estimates.end() && e->std);
  ASSERT_LT(i, static_cast<int>(best.coordinate_names.size()));
  for (double side : {-1.0, 1.0}) {
    const double delta = DeltaChi2At(d, io, r, i, e->value + side * *e->std);
    EXPECT_GT(delta, 0.6) << side;
    EXPECT_LT(delta, 1.5) << side;
  }
}

// In-plane only (the out-of-plane parameters known), every coordinate is
// determined; the k_cz profile is curved enough that interpolating between
// its steps missed the threshold by 0.12.
TEST(IdentifiabilityTest, EveryProfileBoundIsWhereAnIndependentRefitCrossesTheThreshold) {
  Parameters truth;
  Dataset d = SimulatedPaperTire(RigidRingModel(), {}, &truth);
  for (int i = 0; i < kNumParams; ++i) {
    const Param p = ParamAt(i);
    if (Info(p).group == Group::kOutOfPlane && d.initial.erase(p)) d.known[p] = truth[p];
  }
  const IdentifiabilityOptions o;
  IdentifiabilityResult r;
  AnalyzeIdentifiability(RigidRingModel(), d, o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.parameters.size(), 7u);
  for (const auto& p : r.parameters) {
    EXPECT_EQ(p.identifiable, Identifiability::kYes) << p.key.Text();
    EXPECT_TRUE(p.profile_95.lower && p.profile_95.upper) << p.key.Text();
  }
  for (const auto& [i, bound] : ClosedBounds(r)) {
    EXPECT_NEAR(DeltaChi2At(d, o, r, i, bound), kChiSquare1Dof95, 0.05)
        << r.parameters[i].key.Text() << " at " << bound;
  }
  for (const auto& p : r.parameters) {  // a smooth profile has no jump
    EXPECT_FALSE(p.profile_95.lower_jump_at || p.profile_95.upper_jump_at) << p.key.Text();
  }
}

// The paper's tire with a soft hub (`simulate --effects=hub_compliance
// --set=s_h=2e-7,m_a=15`), fitted without it. Its out-of-plane profiles jump
// (2 delta cost 0.14, then 399 one step on) where the refits stall against
// modes going overdamped; interpolating across a jump put bounds far inside
// the interval, and a jump was once reported as the bound. Each bound is now
// a refitted crossing of the threshold, and each jump a field of its own: the
// first point over the threshold, a refitted point under it within 1e-6 (log
// coordinates here: a relative 1e-6). And no independent refit from the
// optimum finds a bound or a jump inside the interval. (The converse cannot
// be asked of one refit here: from the optimum it stalls too, or cannot
// start where a mode is overdamped.)
TEST(IdentifiabilityTest, ProfileBoundsAreRefittedCrossingsAndJumpsAreSaidApart) {
  Parameters truth;
  const Dataset d = SimulatedPaperTire(RigidRingModel({FindEffect("hub_compliance")}),
                                       {{Param::s_h, 2e-7}, {Param::m_a, 15}}, &truth);
  const IdentifiabilityOptions o;
  IdentifiabilityResult r;
  AnalyzeIdentifiability(RigidRingModel(), d, o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  for (int i = 0; i < static_cast<int>(r.parameters.size()); ++i) {
    const ProfileInterval& p = r.parameters[i].profile_95;
    const std::string name = r.parameters[i].key.Text();
    for (const std::optional<double>& bound : {p.lower, p.upper}) {
      if (!bound) continue;
      bool at_threshold = false;
      for (const auto& [value, delta_chi2] : p.curve) {
        at_threshold |= value == *bound && std::abs(delta_chi2 - kChiSquare1Dof95) < 0.05;
      }
      EXPECT_TRUE(at_threshold) << name << " at " << *bound << " is not a refitted crossing";
      EXPECT_GT(DeltaChi2At(d, o, r, i, *bound), kChiSquare1Dof95 - 0.05) << name << " at " << *bound;
    }
    for (const std::optional<double>& jump : {p.lower_jump_at, p.upper_jump_at}) {
      if (!jump) continue;
      bool over = false, under_next_to_it = false;
      for (const auto& [value, delta_chi2] : p.curve) {
        over |= value == *jump && delta_chi2 >= kChiSquare1Dof95;
        under_next_to_it |= std::abs(value - *jump) <= 2e-6 * std::abs(*jump) &&
                            delta_chi2 < kChiSquare1Dof95;
      }
      EXPECT_TRUE(over && under_next_to_it) << name << " at " << *jump << " is not a jump";
      EXPECT_GT(DeltaChi2At(d, o, r, i, *jump), kChiSquare1Dof95 - 0.05) << name << " at " << *jump;
    }
    // A side holds one of bound, jump, failure (or none: open).
    EXPECT_LE(p.lower.has_value() + p.lower_jump_at.has_value() + p.lower_failed_at.has_value(), 1)
        << name;
    EXPECT_LE(p.upper.has_value() + p.upper_jump_at.has_value() + p.upper_failed_at.has_value(), 1)
        << name;
  }
}

// `identifiability --derivatives=analytic` on a new user's rolling dataset
// (tests/data/newcomer_rolling.json, simulated without any effect): the
// K_cy profile's 2 delta cost went from 0.14 at 94827.55 to 797 at 94827.50,
// and that jump was the lower bound. It was a refit that failed: a walk warm-
// started from one point to the next finds 0.14 there. Further down, the
// cost itself leaps (from a point under the threshold, K_cy moved a little
// and nothing refitted is already far over it): a second optimum, said as a
// jump beside the bound, never as the bound.
TEST(IdentifiabilityTest, AFailedRefitIsRetriedAndOnlyARealJumpIsSaid) {
  Dataset d;
  LoadError e;
  ASSERT_TRUE(LoadDataset(testing::SourcePath("tests/data/newcomer_rolling.json"), &d, &e))
      << e.OneLine();
  IdentifiabilityOptions o;
  o.fit.residuals.derivatives = Derivatives::kAnalytic;
  IdentifyResult fit;
  Identify(RigidRingModel(), d, o.fit, &fit);
  ASSERT_TRUE(fit.status.ok()) << fit.status.message;
  Status status;
  const auto problem = Problem::Create(RigidRingModel(), d, o.fit.residuals, &status);
  ASSERT_TRUE(problem) << status.message;
  const internal::ParameterSetup& setup = problem->setup();
  int i = 0;
  while (i < setup.size() && setup.key(i).param != Param::K_cy) ++i;
  ASSERT_LT(i, setup.size());
  const ProfileInterval p =
      internal::ProfileCoordinate(*problem, fit.x, fit.cost, i, fit.uncertainty.std[i], o);
  ASSERT_TRUE(p.upper) << "the upper side closes as before";
  EXPECT_FALSE(p.lower) << "a jump reported as the bound: " << *p.lower;
  ASSERT_TRUE(p.lower_jump_at);
  const double jump = *p.lower_jump_at;
  EXPECT_LT(jump, 0.99 * 94827.50);  // well past the failed refit

  // Independently: refits walked down from the optimum, each started from
  // the one before, in steps of 0.5 % and finer near the jump.
  const internal::Box box =
      internal::BoundsAround(setup, problem->start(), o.fit.bound_factor, o.fit.bounds);
  const internal::ModalResiduals& residuals = problem->residuals();
  Eigen::VectorXd x = fit.x;
  auto refit = [&](double value, Eigen::VectorXd* from) {
    Eigen::VectorXd start = *from;
    start[i] = setup.ToCoordinate(i, value);
    const internal::LocalFit f = internal::FitLocally(residuals, Method::kLevenbergMarquardt, start,
                                                      box, o.fit.max_iterations, o.fit.simplex, i);
    *from = f.x;
    return 2 * (f.cost - fit.cost);
  };
  auto delta_at_start = [&](double value, Eigen::VectorXd start) -> double {
    start[i] = setup.ToCoordinate(i, value);
    std::vector<double> r(residuals.num_residuals());
    if (!residuals.Evaluate(start.data(), r.data())) return INFINITY;
    double cost = 0;
    for (double v : r) cost += 0.5 * v * v;
    return 2 * (cost - fit.cost);
  };
  const double upper = jump * (1 + 2e-6);
  double delta = 0;
  for (double v = setup.ToPhysical(i, fit.x[i]); v > upper; ) {
    v = std::max(upper, v * (v > 1.01 * upper ? 0.995 : 0.9995));
    delta = refit(v, &x);
    ASSERT_LT(delta, kChiSquare1Dof95) << "the walk jumps at " << v;
    if (std::abs(v - 94827.50) < 0.003 * v) EXPECT_LT(delta, 1) << v;
  }
  // Within 0.1 % past the jump the cost leaps before any refit, and stays
  // over after it. (Where exactly the low valley ends depends on the path of
  // the other coordinates: a walk in steps of 0.09 % leaps from 0.20 at
  // 91444 to 3e4 at 91363, the profile at 91395.)
  const double lower = jump * (1 - 1e-3);
  EXPECT_GT(delta_at_start(lower, x), 100 * kChiSquare1Dof95);
  EXPECT_GT(refit(lower, &x), kChiSquare1Dof95);

  // The report says it beside the bound, not as the bound.
  IdentifiabilityResult r;
  r.status = Status::Success();
  ParameterIdentifiability q;
  q.key = setup.key(i);
  q.profile_95 = p;
  r.parameters.push_back(q);
  const std::string text = r.FullReport();
  EXPECT_NE(text.find("jumps to another optimum at"), std::string::npos) << text;
}

// The camber mode, damped near critical, seen only as a broad hump (its
// frequency to +-100 %, damping ratio to +-0.5), beside a sharp vertical mode
// and no shapes. Raising c_bgamma costs little until the camber mode is
// overdamped; past that it has no model counterpart and no refit is possible.
TEST(IdentifiabilityTest, ASideWhereRefitsFailSaysWhereNotOpen) {
  const Parameters truth = PaperIdentified();
  std::mt19937_64 rng(6);
  const Dataset all = WellPosed(truth, &rng, {Param::c_bgamma, Param::k_bz}, true);
  Dataset d = all;
  d.modes.clear();
  for (MeasuredMode m : all.modes) {
    m.shape.clear();
    m.shape_sigma.reset();
    if (m.label == ModeLabel::kCamber) {
      m.frequency_sigma_hz = m.frequency_hz;
      m.damping_sigma = 0.5;
    }
    if (m.label == ModeLabel::kCamber || m.label == ModeLabel::kVertical) d.modes.push_back(m);
  }
  ASSERT_EQ(d.modes.size(), 2u);
  IdentifiabilityResult r;
  AnalyzeIdentifiability(RigidRingModel(), d, IdentifiabilityOptions{}, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const ParameterIdentifiability& c = Find(r, Param::c_bgamma);
  ASSERT_TRUE(c.profile_95.computed);
  EXPECT_FALSE(c.profile_95.upper) << *c.profile_95.upper;
  ASSERT_TRUE(c.profile_95.upper_failed_at);
  EXPECT_TRUE(c.profile_95.lower);  // the other side closes as usual
  EXPECT_FALSE(c.profile_95.lower_failed_at);
  // Where the camber mode is overdamped (c_bgamma alone decides it: k_bz is
  // in-plane), by bisection on the model itself.
  auto oscillates = [&](double c_bgamma) {
    Parameters p = truth;
    p[Param::c_bgamma] = c_bgamma;
    const ModalSolution s = RigidRingModel().Solve(p);
    return s.ok && s.Find(ModeLabel::kCamber) != nullptr;
  };
  double below = truth[Param::c_bgamma], above = 2 * below;
  ASSERT_TRUE(oscillates(below));
  ASSERT_FALSE(oscillates(above));
  for (int k = 0; k < 50; ++k) {
    const double middle = 0.5 * (below + above);
    (oscillates(middle) ? below : above) = middle;
  }
  // Refits fail a little short of it, where the Jacobian's differences
  // reach past it.
  EXPECT_NEAR(*c.profile_95.upper_failed_at, above, 0.01 * above);
  const std::string report = r.FullReport();
  EXPECT_NE(report.find("failed at"), std::string::npos) << report;
}

TEST(IdentifiabilityTest, VerticalStiffnessesFromOneFrequencyAreOneCombination) {
  // The vertical mode sees only k_bz + k_cz (its 1-DOF closed form); with
  // the hub rigid both springs hold z_b to ground, so the model does too.
  std::mt19937_64 rng(4);
  const Dataset d = WellPosed(PaperIdentified(), &rng,
                              {Param::k_bz, Param::k_cz, Param::k_btheta}, false);
  IdentifiabilityOptions o;
  o.profile_steps = 0;
  IdentifiabilityResult r;
  AnalyzeIdentifiability(RigidRingModel(), d, o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.rank, 2);
  EXPECT_EQ(Find(r, Param::k_bz).identifiable, Identifiability::kNo);
  EXPECT_EQ(Find(r, Param::k_cz).identifiable, Identifiability::kNo);
  EXPECT_EQ(Find(r, Param::k_btheta).identifiable, Identifiability::kYes);
  EXPECT_TRUE(HasMeaning(r, "structurally free: only k_bz + k_cz enters the model"));
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
    if (IsBaseline(ParamAt(i))) d.known[ParamAt(i)] = truth[ParamAt(i)];
  }
  for (Param p : {Param::k_bx, Param::c_bx, Param::K_cx, Param::sigma_cx, Param::k_by,
                  Param::K_cy, Param::sigma_cy}) {
    d.known.erase(p);
    d.initial[p] = truth[p] * 1.2;
  }
  return d;
}

// The unit direction of a listed combination, from its terms, in the
// report's coordinates.
Eigen::VectorXd Direction(const IdentifiabilityResult& r, const Combination& c) {
  Eigen::VectorXd d = Eigen::VectorXd::Zero(r.coordinate_names.size());
  for (const auto& [name, coefficient] : c.terms) {
    const auto at = std::find(r.coordinate_names.begin(), r.coordinate_names.end(), name);
    EXPECT_NE(at, r.coordinate_names.end()) << name;
    if (at != r.coordinate_names.end()) d[at - r.coordinate_names.begin()] = coefficient;
  }
  return d.normalized();
}

// The unit direction moving `a` and `b` together in log coordinates.
Eigen::VectorXd Together(const IdentifiabilityResult& r, const std::string& a, const std::string& b) {
  Eigen::VectorXd d = Eigen::VectorXd::Zero(r.coordinate_names.size());
  for (const std::string& name : {a, b}) {
    const auto at = std::find(r.coordinate_names.begin(), r.coordinate_names.end(), name);
    EXPECT_NE(at, r.coordinate_names.end()) << name;
    if (at != r.coordinate_names.end()) d[at - r.coordinate_names.begin()] = 1;
  }
  return d.normalized();
}

// No two listed combinations are one (to 1 %) up to a direction in the span
// of `structural` (orthonormal columns), which no data can see.
void ExpectEachCombinationOnce(const IdentifiabilityResult& r, const Eigen::MatrixXd& structural) {
  std::vector<Eigen::VectorXd> seen;
  for (const Combination& c : r.combinations) {
    const Eigen::VectorXd d = Direction(r, c);
    seen.push_back(d - structural * (structural.transpose() * d));
  }
  for (size_t i = 0; i < seen.size(); ++i) {
    for (size_t j = i + 1; j < seen.size(); ++j) {
      const Combination &a = r.combinations[i], &b = r.combinations[j];
      if (seen[i].norm() < 1e-3 || seen[j].norm() < 1e-3) {  // structural: listed as such
        EXPECT_FALSE(seen[i].norm() < 1e-3 && seen[j].norm() < 1e-3 &&
                     std::abs(Direction(r, a).dot(Direction(r, b))) > 0.99)
            << "listed twice: " << a.text << " (" << a.meaning << ") and " << b.text << " (" << b.meaning << ")";
        continue;
      }
      EXPECT_LT(std::abs(seen[i].normalized().dot(seen[j].normalized())), 0.99)
          << "listed twice: " << a.text << " (" << a.meaning << ") and " << b.text << " (" << b.meaning << ")";
    }
  }
}

// The unit direction along which the value k_bz + k_cz stays, in log
// coordinates.
Eigen::VectorXd SumStays(const IdentifiabilityResult& r) {
  Eigen::VectorXd d = Eigen::VectorXd::Zero(r.coordinate_names.size());
  for (size_t i = 0; i < r.parameters.size(); ++i) {
    if (r.parameters[i].param() == Param::k_bz) d[i] = 1 / r.parameters[i].value;
    if (r.parameters[i].param() == Param::k_cz) d[i] = -1 / r.parameters[i].value;
  }
  return d.normalized();
}

// Standing, eq. (9): K_cx and sigma_cx (K_cy, sigma_cy) enter only as their
// ratio, so log K + log sigma of each contact is free whatever the data, and
// nothing else is structurally free. Each is listed once, as structural: not
// again among the free directions of the data (alone or mixed with the other
// pair) nor as a collinear pair. Likewise k_bz + k_cz, all one frequency sees
// (with the hub rigid, only their sum enters the model).
TEST(IdentifiabilityTest, EachCombinationIsListedOnceAndAStructuralPairOnlyAsStructural) {
  IdentifiabilityOptions o;
  o.profile_steps = 0;
  o.fit.starts = 1;
  IdentifiabilityResult r;
  AnalyzeIdentifiability(RigidRingModel(), CarTireTest({0}, 5), o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const Eigen::VectorXd x = Together(r, "K_cx", "sigma_cx"), y = Together(r, "K_cy", "sigma_cy");
  Eigen::MatrixXd exact(x.size(), 2);
  exact << x, y;
  int along_x = 0, along_y = 0;
  for (const Combination& c : r.combinations) {
    const Eigen::VectorXd d = Direction(r, c);
    if ((d - exact * (exact.transpose() * d)).norm() > 1e-3) continue;  // not structural
    const bool is_x = std::abs(d.dot(x)) > 1 - 1e-6, is_y = std::abs(d.dot(y)) > 1 - 1e-6;
    EXPECT_TRUE(is_x || is_y) << "a mixture of the structural directions: " << c.text;
    along_x += is_x;
    along_y += is_y;
    EXPECT_EQ(c.singular_value, 0) << c.text;
    EXPECT_NE(c.meaning.find("structurally free"), std::string::npos) << c.meaning;
  }
  EXPECT_EQ(along_x, 1);
  EXPECT_EQ(along_y, 1);
  for (const CollinearSubset& p : r.collinear_pairs) {
    const std::set<std::string> names(p.names.begin(), p.names.end());
    EXPECT_NE(names, (std::set<std::string>{"K_cx", "sigma_cx"}));
    EXPECT_NE(names, (std::set<std::string>{"K_cy", "sigma_cy"}));
  }
  ExpectEachCombinationOnce(r, exact);

  std::mt19937_64 rng(4);
  const Dataset vertical = WellPosed(PaperIdentified(), &rng,
                                     {Param::k_bz, Param::k_cz, Param::k_btheta}, false);
  AnalyzeIdentifiability(RigidRingModel(), vertical, o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const Eigen::VectorXd sum = SumStays(r);
  int along_sum = 0;
  for (const Combination& c : r.combinations) along_sum += std::abs(Direction(r, c).dot(sum)) > 1 - 1e-4;
  EXPECT_EQ(along_sum, 1);
  ExpectEachCombinationOnce(r, sum);
}

// The subset never holds a parameter with a component in a free direction:
// standing, not the contact's K or sigma (eq. 9, whichever of the pair the
// pivoting would take); from frequencies alone, not k_bz or k_cz (the
// vertical mode's closed form sees only k_bz + k_cz); on Table 1 not t_0,
// free for these data though not for the model: doubled, it moves none of
// the frequencies by a millionth of its sigma (checked on the model directly).
TEST(IdentifiabilityTest, TheIdentifiableSubsetHoldsNoParameterWithAComponentInAFreeDirection) {
  IdentifiabilityOptions o;
  o.profile_steps = 0;
  o.fit.starts = 1;
  auto in = [](const IdentifiabilityResult& r, const std::string& name) {
    return std::find(r.identifiable_subset.begin(), r.identifiable_subset.end(), name) !=
           r.identifiable_subset.end();
  };
  IdentifiabilityResult r;
  AnalyzeIdentifiability(RigidRingModel(), CarTireTest({0}, 5), o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  for (const char* name : {"K_cx", "sigma_cx", "K_cy", "sigma_cy"}) EXPECT_FALSE(in(r, name)) << name;
  // The rest are determined by full modal data.
  EXPECT_EQ(std::set<std::string>(r.identifiable_subset.begin(), r.identifiable_subset.end()),
            (std::set<std::string>{"k_bx", "c_bx", "k_by"}));

  std::mt19937_64 rng(4);
  AnalyzeIdentifiability(RigidRingModel(),
                         WellPosed(PaperIdentified(), &rng, {Param::k_bz, Param::k_cz, Param::k_btheta}, false),
                         o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.identifiable_subset, std::vector<std::string>{"k_btheta"});

  Dataset d;
  LoadError e;
  ASSERT_TRUE(LoadDataset(testing::SourcePath("datasets/paper/table1.json"), &d, &e));
  AnalyzeIdentifiability(RigidRingModel(), d, o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  Parameters moved = r.fit.parameters;
  moved[Param::t_0] *= 2;
  const ModalSolution at = RigidRingModel().Solve(r.fit.parameters), there = RigidRingModel().Solve(moved);
  ASSERT_TRUE(at.ok && there.ok);
  for (const MeasuredMode& m : d.modes) {
    ASSERT_TRUE(at.Find(m.label) && there.Find(m.label));
    ASSERT_NEAR(at.Find(m.label)->frequency_hz, there.Find(m.label)->frequency_hz,
                1e-6 * *m.frequency_sigma_hz)
        << LabelName(m.label);
  }
  EXPECT_FALSE(in(r, "t_0"));
}

// The advice is checked by doing what it says: the drum test it proposes,
// simulated and added, makes sigma_cx identifiable.
TEST(IdentifiabilityTest, AdvisedDrumTestMakesTheRelaxationLengthIdentifiable) {
  IdentifiabilityOptions o;
  o.profile_steps = 0;
  o.fit.starts = 1;
  IdentifiabilityResult standing;
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
  IdentifiabilityResult rolling;
  AnalyzeIdentifiability(RigidRingModel(), CarTireTest({0, advised}, 5), o, &rolling);
  ASSERT_TRUE(rolling.status.ok()) << rolling.status.message;
  EXPECT_EQ(Find(rolling, Param::sigma_cx).identifiable, Identifiability::kYes) << advised;
  EXPECT_EQ(Find(rolling, Param::K_cx).identifiable, Identifiability::kYes) << advised;
}


// The steps a progress line shows (IdentifiabilityOptions::on_step): from
// none done to all, never back, over the fit, Table 1's 16 free coordinates'
// profiles (on two threads) and the rest.
TEST(IdentifiabilityTest, ItsStepsRunFromNoneToAllOverTheFitAndEachProfile) {
  Dataset d;
  LoadError e;
  ASSERT_TRUE(LoadDataset(testing::SourcePath("datasets/paper/table1.json"), &d, &e));
  IdentifiabilityOptions o;
  o.profile_steps = 1;
  o.fit.threads = 2;
  std::vector<std::pair<int, int>> steps;
  o.on_step = [&](int done, int total) { steps.emplace_back(done, total); };
  IdentifiabilityResult r;
  AnalyzeIdentifiability(RigidRingModel(), d, o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_GE(steps.size(), 3u);
  EXPECT_EQ(steps.front(), std::make_pair(0, 16 + 2));
  EXPECT_EQ(steps.back(), std::make_pair(16 + 2, 16 + 2));
  for (size_t k = 1; k < steps.size(); ++k) {
    EXPECT_GE(steps[k].first, steps[k - 1].first) << k;
    EXPECT_EQ(steps[k].second, 18) << k;
  }
}

// A hammer test (lines every 5 Hz from 5 to 150 Hz, 2 % noise) with three
// parameters free: an FRF problem small enough to profile in a test.
Dataset ThreeFreeHammer() {
  std::mt19937_64 rng(7);
  const Parameters truth = ExampleCarTire();
  Dataset d = PlanSimulation(truth, 0.0, {0}, {}, &rng);
  d.conditions[0].frf = HammerTest(0.31, 5, 150, 5);
  SimulateOptions so;
  so.modes = false;
  so.frf_noise = 0.02;
  std::string why;
  EXPECT_TRUE(Simulate(RigidRingModel(), truth, so, &rng, &d, &why)) << why;
  std::vector<Param> fix;
  for (const auto& [p, value] : d.initial) {
    if (p != Param::k_bx && p != Param::k_btheta && p != Param::k_by) fix.push_back(p);
  }
  EXPECT_TRUE(FixParameters(fix, &d, &why)) << why;
  return d;
}

// Profiles are a series of refits each: on FRFs they run only when asked,
// and the report says so. Asked, on a fit this well determined (2 % noise,
// 30 lines x 28 functions, three parameters), each profile interval is the
// Wald interval, which a linear model would make exact.
TEST(IdentifiabilityTest, FrfDataAreProfiledOnlyWhenAskedAndThenAsWaldPredicts) {
  const Dataset d = ThreeFreeHammer();
  IdentifiabilityOptions o;
  o.fit.starts = 1;
  IdentifiabilityResult skipped, profiled;
  AnalyzeIdentifiability(RigidRingModel(), d, o, &skipped);
  ASSERT_TRUE(skipped.status.ok()) << skipped.status.message;
  EXPECT_FALSE(skipped.profiles.computed);
  EXPECT_NE(skipped.profiles.why.find("FRFs"), std::string::npos) << skipped.profiles.why;
  ASSERT_EQ(skipped.parameters.size(), 3u);
  for (const ParameterIdentifiability& p : skipped.parameters) {
    EXPECT_FALSE(p.profile_95.computed) << p.key.Text();
    EXPECT_TRUE(p.wald_95) << p.key.Text();
  }
  o.profiles = Profiles::kAlways;
  AnalyzeIdentifiability(RigidRingModel(), d, o, &profiled);
  ASSERT_TRUE(profiled.status.ok()) << profiled.status.message;
  EXPECT_TRUE(profiled.profiles.computed);
  for (const ParameterIdentifiability& p : profiled.parameters) {
    ASSERT_TRUE(p.profile_95.computed && p.profile_95.lower && p.profile_95.upper) << p.key.Text();
    ASSERT_TRUE(p.wald_95) << p.key.Text();
    const double width = p.wald_95->second - p.wald_95->first;
    EXPECT_NEAR(*p.profile_95.lower, p.wald_95->first, 0.02 * width) << p.key.Text();
    EXPECT_NEAR(*p.profile_95.upper, p.wald_95->second, 0.02 * width) << p.key.Text();
  }
}

// The coordinates' profiles share the threads, each on its own copy of the
// problem: the same curves on two threads as on one.
TEST(IdentifiabilityTest, ProfilesOnTwoThreadsAreThoseOnOne) {
  Dataset d;
  LoadError e;
  ASSERT_TRUE(LoadDataset(testing::SourcePath("datasets/paper/table1.json"), &d, &e));
  IdentifiabilityOptions o;
  o.fit.starts = 1;
  o.profile_steps = 2;
  IdentifiabilityResult one, two;
  o.fit.threads = 1;
  AnalyzeIdentifiability(RigidRingModel(), d, o, &one);
  o.fit.threads = 2;
  AnalyzeIdentifiability(RigidRingModel(), d, o, &two);
  ASSERT_TRUE(one.status.ok() && two.status.ok()) << one.status.message << two.status.message;
  EXPECT_TRUE(one.profiles.computed);
  ASSERT_EQ(one.parameters.size(), two.parameters.size());
  size_t points = 0;  // refitted profile points to compare, beyond each optimum
  for (const auto& q : one.parameters) points += q.profile_95.curve.size() - 1;
  EXPECT_GE(points, 2 * one.parameters.size());
  for (size_t i = 0; i < one.parameters.size(); ++i) {
    EXPECT_EQ(one.parameters[i].profile_95.curve, two.parameters[i].profile_95.curve) << i;
    EXPECT_EQ(one.parameters[i].profile_95.lower, two.parameters[i].profile_95.lower) << i;
    EXPECT_EQ(one.parameters[i].profile_95.upper, two.parameters[i].profile_95.upper) << i;
  }
}

}  // namespace
}  // namespace ringid
