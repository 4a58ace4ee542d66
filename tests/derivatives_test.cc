// Analytic residual Jacobians (eigenvalue and eigenvector derivatives,
// docs/model.md §15) against Ridders' extrapolated finite differences, which
// share no code with them: the paper's point, random points, near the
// camber/yaw crossing, each effect, both shape conventions and at speed.
#include <cmath>
#include <memory>
#include <numeric>
#include <algorithm>
#include <complex>
#include <random>
#include <string>

#include <ceres/dynamic_numeric_diff_cost_function.h>
#include <gtest/gtest.h>

#include "model/static_stiffness.h"

#include "datasets/dataset.h"
#include "datasets/synthetic.h"
#include "estimation/identify.h"
#include "estimation/problem.h"
#include "estimation/residuals.h"
#include "model/effects.h"
#include "model/rigid_ring_model.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using testing::PaperIdentified;
using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The Jacobian at x of the residual cost that `residuals` asks for.
bool JacobianOf(ceres::CostFunction* cost, const Eigen::VectorXd& x, RowMatrix* J) {
  Eigen::VectorXd r(cost->num_residuals());
  J->resize(cost->num_residuals(), x.size());
  const double* parameters[] = {x.data()};
  double* jacobians[] = {J->data()};
  return cost->Evaluate(parameters, r.data(), jacobians);
}

// Norm-wise relative disagreement of the whole Jacobian, and the largest of
// any column (one coordinate's derivatives) relative to that column, a
// column below 1e-3 of the whole measured against 1e-3 of the whole (there
// the reference is rounding divided by its step). Before the state matrix
// was balanced (model/modal.cc) the reference itself was good to about 2e-6
// only.
struct Disagreement {
  double whole = 0, column = 0;
  std::string worst;  // the coordinate of the largest column disagreement
};
Disagreement Compare(const RowMatrix& analytic, const RowMatrix& reference,
                     const internal::ParameterSetup& setup) {
  Disagreement d;
  d.whole = (analytic - reference).norm() / reference.norm();
  for (int j = 0; j < reference.cols(); ++j) {
    const double scale = std::max(reference.col(j).norm(), 1e-3 * reference.norm());
    const double e = (analytic.col(j) - reference.col(j)).norm() / scale;
    if (e > d.column) d.column = e, d.worst = setup.name(j);
  }
  return d;
}

// Analytic and Ridders Jacobians of the dataset's residuals at x (the
// dataset's start when empty) agree to 1e-6, as a whole and in every column.
void ExpectAgreement(const ModalModel& model, const Dataset& dataset, ShapeConvention convention,
                     const Eigen::VectorXd& at, const std::string& what) {
  ResidualOptions o;
  o.derivatives = Derivatives::kAnalytic;
  o.shape_convention = convention;
  Status status;
  const auto problem = Problem::Create(model, dataset, o, &status);
  ASSERT_TRUE(problem) << status.message;
  const auto& residuals = problem->residuals();
  const Eigen::VectorXd x = at.size() ? at : problem->start();
  ASSERT_EQ(x.size(), residuals.num_parameters());
  std::unique_ptr<ceres::CostFunction> analytic(internal::NewResidualCost(residuals));
  ceres::NumericDiffOptions ridders_options;
  // Its first step is 32 times this (x is mostly log values near 10).
  ridders_options.ridders_relative_initial_step_size = 1e-4;
  ceres::DynamicNumericDiffCostFunction<internal::ModalResiduals, ceres::RIDDERS> ridders(
      &residuals, ceres::DO_NOT_TAKE_OWNERSHIP, ridders_options);
  ridders.AddParameterBlock(residuals.num_parameters());
  ridders.SetNumResiduals(residuals.num_residuals());
  RowMatrix Ja, Jr;
  ASSERT_TRUE(JacobianOf(analytic.get(), x, &Ja)) << what;
  ASSERT_TRUE(JacobianOf(&ridders, x, &Jr)) << what;
  const Disagreement d = Compare(Ja, Jr, problem->setup());
  EXPECT_LT(d.whole, 1e-6) << what;
  EXPECT_LT(d.column, 1e-6) << what << ": worst column " << d.worst;
}

// Every baseline parameter free, starting at the truth.
Dataset AllFree(Dataset d, const ModalModel& model, const Parameters& truth) {
  for (Param p : model.parameters()) {
    if (p == Param::m_a) {
      d.known[p] = truth[p];
    } else {
      d.initial[p] = truth[p];
    }
  }
  return d;
}

// Every measured mode pairs with the model mode of its label, whose MAC
// exceeds every other model mode's by 0.01 (in-plane shapes on the belt alone are alike).
bool ClearlyPaired(const internal::ModalResiduals& residuals, const Eigen::VectorXd& x) {
  std::vector<ModalSolution> solutions;
  std::vector<int> pairs;
  std::string why;
  if (!residuals.Pair(x.data(), &solutions, &pairs, &why)) return false;
  for (size_t i = 0; i < pairs.size(); ++i) {
    const MeasuredMode& measured = residuals.dataset().modes[i];
    const ModalSolution& s = solutions[measured.condition];
    if (s.modes[pairs[i]].label != measured.label) return false;
    const auto mac = [&](int b) {
      return Mac(ComparableShape(s.modes[b], ShapeConvention::kContract, measured.shape),
                 measured.shape);
    };
    for (int b = 0; b < static_cast<int>(s.modes.size()); ++b) {
      if (b != pairs[i] && mac(b) > mac(pairs[i]) - 0.01) return false;
    }
  }
  return true;
}

TEST(DerivativesTest, AnalyticJacobianMatchesRiddersOnThePapersTable1) {
  Dataset d;
  LoadError e;
  ASSERT_TRUE(LoadDataset(testing::SourcePath("datasets/paper/table1.json"), &d, &e));
  ExpectAgreement(RigidRingModel(), d, ShapeConvention::kContract, {}, "table1");
}

TEST(DerivativesTest, AnalyticJacobianMatchesRiddersWithShapesAndDampingAtRandomPoints) {
  std::mt19937_64 rng(7);
  const RigidRingModel model;
  const Parameters truth = PaperIdentified();
  const Dataset d = AllFree(testing::SyntheticDataset(model, truth, 0.0025, 0.1, 0.02, &rng),
                            model, truth);
  Status status;
  const auto problem = Problem::Create(model, d, ResidualOptions(), &status);
  ASSERT_TRUE(problem) << status.message;
  std::normal_distribution<double> step(0, 0.2);
  Eigen::VectorXd r(problem->residuals().num_residuals());
  for (int trial = 0; trial < 4; ++trial) {
    Eigen::VectorXd x = problem->start();
    // A point where every measured mode still oscillates and pairs with the
    // model mode of its label by a margin of MAC: where two pairings
    // are nearly as good, the residuals jump within any step.
    for (int draw = 0; trial > 0 && draw < 1000; ++draw) {
      x = problem->start();
      for (int i = 0; i < x.size(); ++i) x[i] += step(rng);
      if (ClearlyPaired(problem->residuals(), x)) break;
    }
    if (trial > 0) ASSERT_TRUE(ClearlyPaired(problem->residuals(), x));
    ExpectAgreement(model, d, ShapeConvention::kContract, x, "trial " + std::to_string(trial));
  }
  // The measured shapes are the contract's; they pair under the paper's
  // convention near the truth only.
  ExpectAgreement(model, d, ShapeConvention::kPaper, problem->start(), "paper convention");
}

// The static stiffness rows (contract §10) through the static solve's exact
// derivatives, with every baseline parameter free, on the baseline and with
// effects that change the static solve (a compliant hub, lug coupling).
TEST(DerivativesTest, AnalyticJacobianMatchesRiddersWithStaticStiffnesses) {
  const Parameters truth = PaperIdentified();
  for (const std::vector<const Effect*>& effects :
       {std::vector<const Effect*>{}, {FindEffect("hub_compliance"), FindEffect("lug_coupling")}}) {
    const RigidRingModel model(effects);
    Parameters p = truth;
    p[Param::s_h] = 2e-7;
    p[Param::m_a] = 10;
    p[Param::k_xy] = 2e4;
    std::mt19937_64 rng(11);
    Dataset d = testing::SyntheticDataset(model, p, 0.0025, 0.1, 0.02, &rng);
    d.format = 3;
    for (int k = 0; k < kNumStaticDirections; ++k) {
      const auto direction = static_cast<StaticDirection>(k);
      const StaticStiffnessResult value = StaticStiffness(model, p, direction);
      ASSERT_TRUE(value.ok) << value.error;
      d.statics.push_back({direction, 1.03 * value.value, 0.02 * value.value, 0});
    }
    d = AllFree(d, model, p);
    ExpectAgreement(model, d, ShapeConvention::kContract, {},
                    effects.empty() ? "baseline" : "hub_compliance + lug_coupling");
  }
}

// Where the measured shape's largest component is not the model's largest
// (but within kShapeReferenceShare of it), the phase removed is the measured
// one's (ComparableShape), and its derivative enters every shape row.
TEST(DerivativesTest, AnalyticJacobianMatchesRiddersWhereTheMeasuredShapeSetsThePhase) {
  std::mt19937_64 rng(7);
  const RigidRingModel model;
  Parameters truth = PaperIdentified();
  truth[Param::m_a] = 15;  // a lateral mode with y_b and gamma_b far out of phase
  Dataset d = AllFree(testing::SyntheticDataset(model, truth, 0.0025, 0.1, 0.02, &rng), model,
                      truth);
  Status status;
  auto problem = Problem::Create(model, d, ResidualOptions(), &status);
  ASSERT_TRUE(problem) << status.message;
  std::vector<ModalSolution> solutions;
  std::vector<int> pairs;
  std::string why;
  ASSERT_TRUE(problem->residuals().Pair(problem->start().data(), &solutions, &pairs, &why)) << why;
  // A measured shape whose model mode has a second component at least 0.6 of
  // its largest and out of phase with it gets that component as its largest.
  int moved = 0;
  for (size_t i = 0; i < d.modes.size(); ++i) {
    const Mode& mode = solutions[d.modes[i].condition].modes[pairs[i]];
    auto& shape = d.modes[i].shape;
    if (shape.size() < 2) continue;
    std::vector<size_t> order(shape.size());
    std::iota(order.begin(), order.end(), 0);
    const auto size = [&](size_t k) { return std::abs(mode.shape[static_cast<int>(shape[k].first)]); };
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return size(a) > size(b); });
    const std::complex<double> ratio = mode.shape[static_cast<int>(shape[order[1]].first)] /
                                       mode.shape[static_cast<int>(shape[order[0]].first)];
    if (std::abs(ratio) < 0.6 || std::abs(ratio.imag()) < 0.2 * std::abs(ratio)) continue;
    double largest = 0;
    for (const auto& [dof, v] : shape) largest = std::max(largest, std::abs(v));
    shape[order[1]].second = 1.2 * largest;
    ASSERT_EQ(ShapeReference(mode, shape), static_cast<int>(shape[order[1]].first));
    ++moved;
  }
  ASSERT_GE(moved, 1);
  ExpectAgreement(model, d, ShapeConvention::kContract, {}, "measured phase");
}

TEST(DerivativesTest, AnalyticJacobianMatchesRiddersNearTheCamberYawCrossing) {
  // Move the yaw stiffness until the yaw mode sits within 1 % of camber.
  Parameters truth = PaperIdentified();
  const RigidRingModel model;
  double best = 1, best_k = truth[Param::k_bpsi];
  for (double f = 0.2; f < 5; f *= 1.01) {
    Parameters q = truth;
    q[Param::k_bpsi] = truth[Param::k_bpsi] * f;
    const ModalSolution s = model.Solve(q);
    if (!s.ok || !s.Find(ModeLabel::kCamber) || !s.Find(ModeLabel::kYaw)) continue;
    const double gap = std::abs(s.Find(ModeLabel::kCamber)->frequency_hz /
                                    s.Find(ModeLabel::kYaw)->frequency_hz - 1);
    if (gap < best) best = gap, best_k = q[Param::k_bpsi];
  }
  ASSERT_LT(best, 0.01);
  truth[Param::k_bpsi] = best_k;
  std::mt19937_64 rng(3);
  const Dataset d = AllFree(testing::SyntheticDataset(model, truth, 0.0025, 0.1, 0.02, &rng),
                            model, truth);
  ExpectAgreement(model, d, ShapeConvention::kContract, {}, "crossing");
}

TEST(DerivativesTest, AnalyticJacobianMatchesRiddersWithEachEffect) {
  for (const Effect* effect : EffectCatalogue()) {
    const RigidRingModel model({effect});
    Parameters truth = PaperIdentified();
    truth[Param::m_a] = 15;
    truth[effect->size()] = ValueForShift(truth, *effect, effect->size(), 0.03);
    // Shapes with the hub's components, as rim accelerometers give them:
    // without them the hub modes' shapes match the belt's, and the pairing by
    // MAC (not differentiable) can flip within any step.
    SimulateOptions simulate;
    std::mt19937_64 rng(11);
    Dataset d;
    std::string why;
    ASSERT_TRUE(Simulate(model, truth, simulate, &rng, &d, &why)) << why;
    d = AllFree(d, model, truth);
    ExpectAgreement(model, d, ShapeConvention::kContract, {}, effect->name());
  }
}

TEST(DerivativesTest, AnalyticJacobianMatchesRiddersAtSpeedAndAcrossConditions) {
  Dataset d;
  LoadError e;
  ASSERT_TRUE(LoadDataset(testing::SourcePath("datasets/examples/car_tire_rolling.json"), &d, &e))
      << e.OneLine();
  ASSERT_GT(d.conditions.size(), 1u);
  ExpectAgreement(RigidRingModel(), d, ShapeConvention::kContract, {}, "rolling");
}

// The default (numeric) Jacobian takes each perturbed point's labels from
// the point it perturbs (ModalModel::SolveFrom), sparing a continuation in
// speed per step. On scattered starts of a rolling dataset (a factor 3
// around its initial values, where nearly degenerate modes make continuation
// costly) it is the Jacobian of solving every step on its own, as Ceres'
// central differences of the residuals give it, and matches the exact one.
TEST(DerivativesTest, NumericJacobianCarryingLabelsIsThatOfSolvingEachStep) {
  Dataset d;
  LoadError e;
  ASSERT_TRUE(LoadDataset(testing::SourcePath("tests/data/newcomer_rolling.json"), &d,
                          &e))
      << e.OneLine();
  const RigidRingModel model;
  ResidualOptions analytic, numeric;
  analytic.derivatives = Derivatives::kAnalytic;
  Status status;
  const auto a = Problem::Create(model, d, analytic, &status);
  const auto n = Problem::Create(model, d, numeric, &status);
  ASSERT_TRUE(a && n) << status.message;
  const internal::ParameterSetup& setup = n->setup();
  std::unique_ptr<ceres::CostFunction> ca(internal::NewResidualCost(a->residuals()));
  std::unique_ptr<ceres::CostFunction> cn(internal::NewResidualCost(n->residuals()));
  ceres::NumericDiffOptions step;
  step.relative_step_size = 1e-4;
  ceres::DynamicNumericDiffCostFunction<internal::ModalResiduals, ceres::CENTRAL> each(
      &n->residuals(), ceres::DO_NOT_TAKE_OWNERSHIP, step);
  each.AddParameterBlock(setup.size());
  each.SetNumResiduals(n->residuals().num_residuals());
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> factor(-std::log(3.0), std::log(3.0));
  int compared = 0;
  for (int k = 0; k < 60; ++k) {
    Eigen::VectorXd x = n->start();
    for (int i = 0; i < x.size(); ++i) {
      if (setup.is_log(i)) x[i] += factor(rng);
    }
    RowMatrix Ja, Jn, Je;
    if (!JacobianOf(ca.get(), x, &Ja)) continue;
    ASSERT_TRUE(JacobianOf(cn.get(), x, &Jn)) << "point " << k;
    ASSERT_TRUE(JacobianOf(&each, x, &Je)) << "point " << k;
    ++compared;
    EXPECT_LT((Jn - Je).norm(), 1e-9 * Je.norm()) << "point " << k;
    EXPECT_LT((Jn - Ja).norm(), 1e-3 * Ja.norm()) << "point " << k;
  }
  EXPECT_GE(compared, 50);
}

// A model whose every solution says its derivatives do not exist.
class NoDerivatives final : public ModalModel {
 public:
  std::unique_ptr<ModalModel> Clone() const override {
    return std::make_unique<NoDerivatives>();
  }
  using ModalModel::Solve;
  ModalSolution Solve(const Parameters& p, double speed, bool derivatives) const override {
    ModalSolution s = model_.Solve(p, speed, false);
    if (derivatives) s.derivatives_undefined = "two eigenvalues coincide (test)";
    return s;
  }
  MechanicalSystem Assemble(const Parameters& p, double speed) const override {
    return model_.Assemble(p, speed);
  }
  BasicSystem<ParameterJet> Assemble(const ParameterArray<ParameterJet>& p,
                                     double speed) const override {
    return model_.Assemble(p, speed);
  }
  std::vector<Param> parameters() const override { return model_.parameters(); }

 private:
  RigidRingModel model_;
};

TEST(DerivativesTest, WhereDerivativesDoNotExistTheCentralDifferencesAreUsed) {
  Dataset d;
  LoadError e;
  ASSERT_TRUE(LoadDataset(testing::SourcePath("datasets/paper/table1.json"), &d, &e));
  ResidualOptions analytic, numeric;
  analytic.derivatives = Derivatives::kAnalytic;
  Status status;
  const auto a = Problem::Create(NoDerivatives(), d, analytic, &status);
  const auto n = Problem::Create(NoDerivatives(), d, numeric, &status);
  ASSERT_TRUE(a && n);
  std::unique_ptr<ceres::CostFunction> ca(internal::NewResidualCost(a->residuals()));
  std::unique_ptr<ceres::CostFunction> cn(internal::NewResidualCost(n->residuals()));
  RowMatrix Ja, Jn;
  ASSERT_TRUE(JacobianOf(ca.get(), a->start(), &Ja));
  ASSERT_TRUE(JacobianOf(cn.get(), n->start(), &Jn));
  EXPECT_EQ(Ja, Jn);
}

TEST(DerivativesTest, CoincidingEigenvaluesInOneBlockGiveNoDerivativesAndSaySo) {
  // Two equal oscillators on x_b and z_b joined by a coupling too small to
  // split them: one block, one repeated eigenvalue.
  const auto build = [](auto m, auto k, auto* s) {
    for (int i = 0; i < kNumDofs; ++i) {
      const Dof dof = static_cast<Dof>(i);
      if (!s->active(dof)) continue;
      s->AddMass(dof, m);
      s->AddSpring(std::nullopt, k * (1.0 + 0.1 * i * (dof != Dof::kZb)), {{dof, 1}});
    }
    s->AddStiffness(std::nullopt, Dof::kXb, Dof::kZb, k * 1e-300);
  };
  MechanicalSystem s;
  build(2.0, 3e5, &s);
  BasicSystem<ParameterJet> jets;
  build(ParameterJet(2.0, 0), ParameterJet(3e5, 1), &jets);
  const ModalSolution solution = SolveModes(s, &jets);
  ASSERT_TRUE(solution.ok) << solution.error;
  EXPECT_NE(solution.derivatives_undefined.find("coincide"), std::string::npos);
  for (const Mode& mode : solution.modes) {
    const bool in_block = std::abs(mode.shape[static_cast<int>(Dof::kXb)]) > 0 ||
                          std::abs(mode.shape[static_cast<int>(Dof::kZb)]) > 0;
    if (in_block) EXPECT_EQ(mode.derivatives, nullptr);
  }
}

// Each thread keeps the last point a problem differentiated exactly: asked
// there again it gives what it made, without making it; another problem at
// the same coordinates (other data) is not given it; and once forgotten (a
// fit's start) the point is made again, to the same bits.
TEST(DerivativesTest, AKeptJacobianIsTheOneMadeThereAndOnlyThatProblems) {
  Dataset a;
  LoadError e;
  ASSERT_TRUE(LoadDataset(testing::SourcePath("datasets/paper/table1.json"), &a, &e));
  Dataset b = a;
  for (MeasuredMode& m : b.modes) m.frequency_hz *= 1.01;
  ResidualOptions o;
  o.derivatives = Derivatives::kAnalytic;
  Status status;
  const auto pa = Problem::Create(RigidRingModel(), a, o, &status);
  const auto pb = Problem::Create(RigidRingModel(), b, o, &status);
  ASSERT_TRUE(pa && pb) << status.message;
  const internal::ModalResiduals& ra = pa->residuals();
  const internal::ModalResiduals& rb = pb->residuals();
  ASSERT_EQ(ra.setup().num_conditions(), 1);
  const int rows = ra.row_begin(1), n = ra.setup().num_shared();
  const Eigen::VectorXd x = pa->start();
  struct Made {
    std::vector<double> r, J;
  };
  const auto make = [&](const internal::ModalResiduals& res, const Eigen::VectorXd& at) {
    Made m{std::vector<double>(rows), std::vector<double>(static_cast<size_t>(rows) * n)};
    bool defined = false;
    EXPECT_TRUE(res.EvaluateConditionJacobian(0, at.data(), nullptr, m.r.data(), m.J.data(),
                                              nullptr, &defined));
    EXPECT_TRUE(defined);
    return m;
  };
  const Made first = make(ra, x);
  const long made = ra.evaluations();
  const Made again = make(ra, x);
  EXPECT_EQ(ra.evaluations(), made);
  EXPECT_EQ(again.r, first.r);
  EXPECT_EQ(again.J, first.J);

  ra.ForgetKept();
  const Made remade = make(ra, x);
  EXPECT_EQ(ra.evaluations(), made + 1);
  EXPECT_EQ(remade.r, first.r);
  EXPECT_EQ(remade.J, first.J);

  const long made_b = rb.evaluations();
  const Made other = make(rb, x);
  EXPECT_EQ(rb.evaluations(), made_b + 1);
  EXPECT_NE(other.r, first.r);
  make(ra, x);  // the thread now keeps rb's point
  EXPECT_EQ(ra.evaluations(), made + 2);
  Eigen::VectorXd moved = x;
  moved[0] += 1e-3;
  const Made elsewhere = make(ra, moved);
  EXPECT_EQ(ra.evaluations(), made + 3);
  EXPECT_NE(elsewhere.J, first.J);
}

}  // namespace
}  // namespace ringid
