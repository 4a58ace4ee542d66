// The FRF fit's start (estimation/frf_start.h, issue 36 item 2): the modes in
// a hammer test's FRFs, their shapes on the coordinates the outputs determine
// and their labels, checked against the model's own modes at the truth; and
// identify from initial values scattered within a factor 3 reaching the fit
// started at the truth.
#include "estimation/frf_start.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "datasets/synthetic.h"
#include "estimation/identify.h"
#include "validation/suites.h"

namespace ringid {
namespace {

// A scattered tire's hammer test (lines every `step_hz`), masses free, 2 %
// noise (0: none); its initial values scattered within `factor` of the truth.
Dataset Hammer(const Parameters& truth, double noise, double factor, double step_hz,
               std::mt19937_64* rng) {
  Dataset d = PlanSimulation(truth, 0, {0}, {}, rng);
  FreeMasses(truth, 0, rng, &d);
  d.conditions[0].frf = HammerTest(0.31, 5, 250, step_hz);
  SimulateOptions so;
  so.modes = false;
  so.frf_noise = noise;
  std::string why;
  EXPECT_TRUE(Simulate(RigidRingModel(), truth, so, rng, &d, &why)) << why;
  std::uniform_real_distribution<double> u(-1, 1);
  for (auto& [q, v] : d.initial) v = truth[q] * std::pow(factor, u(*rng));
  return d;
}

// The model's mode at the truth nearest in frequency to `hz`.
const Mode& Nearest(const ModalSolution& s, double hz) {
  const Mode* best = &s.modes[0];
  for (const Mode& m : s.modes) {
    if (std::abs(m.frequency_hz - hz) < std::abs(best->frequency_hz - hz)) best = &m;
  }
  return *best;
}

TEST(FrfStartTest, TheModesInNoiseFreeFrfsAreTheModelsWithTheirShapesAndLabels) {
  std::mt19937_64 rng(3);
  const Parameters truth = ScatteredTire(&rng);
  const Dataset d = Hammer(truth, 0, 1, 1.0, &rng);
  const Frf& frf = *d.conditions[0].frf;
  const auto found = internal::ModesInFrfs(d);
  ASSERT_EQ(found.size(), 1u);
  const ModalSolution s = RigidRingModel().Solve(truth);
  ASSERT_TRUE(s.ok) << s.error;
  ASSERT_EQ(found[0].size(), s.modes.size());
  const std::vector<ModeLabel> labels = internal::LabelsOnOutputs(RigidRingModel(), frf, found[0], s);
  ASSERT_EQ(labels.size(), found[0].size());
  for (size_t k = 0; k < found[0].size(); ++k) {
    const Mode& model = Nearest(s, found[0][k].frequency_hz);
    EXPECT_NEAR(found[0][k].frequency_hz / model.frequency_hz, 1, 1e-6);
    EXPECT_EQ(labels[k], model.label) << found[0][k].frequency_hz << " Hz";
    const auto shape = internal::ShapeOnCoordinates(RigidRingModel(), frf, found[0][k]);
    if (model.plane() == Plane::kOutOfPlane) {
      // Two lateral accelerometers do not separate y_b, gamma_b and psi_b.
      EXPECT_TRUE(shape.empty()) << LabelName(model.label);
      continue;
    }
    // In plane: x_b, z_b, theta_b and theta_a, each as the model's shape
    // (largest component 1, docs/conventions.md §2).
    ASSERT_EQ(shape.size(), 4u) << LabelName(model.label);
    const RealShapeVector expected = model.RealShape();
    for (const auto& [dof, value] : shape) {
      EXPECT_NEAR(value, expected[static_cast<int>(dof)], 1e-6)
          << LabelName(model.label) << " " << ToString(dof);
    }
  }
}

// identify on `d` with its default starts, and with one start at the truth
// (the reference: the best fit's chi-square), analytic derivatives.
void FitAndFitAtTruth(const Dataset& d, const Parameters& truth, IdentifyResult* fit,
                      IdentifyResult* at_truth) {
  IdentifyOptions o;
  o.residuals.derivatives = Derivatives::kAnalytic;
  Identify(RigidRingModel(), d, o, fit);
  Dataset t = d;
  for (auto& [q, v] : t.initial) v = truth[q];
  o.starts = 1;
  Identify(RigidRingModel(), t, o, at_truth);
}

// Issue 36's criterion on a few tires (validation's frf suite runs 100):
// from initial values scattered within a factor 3, masses free, identify's
// default starts reach the chi-square of the fit started at the truth.
TEST(FrfStartTest, FromInitialValuesScatteredByAFactorThreeTheBestFitIsFound) {
  for (unsigned seed : {1u, 4u}) {  // without the modal stage six starts miss both
    std::mt19937_64 rng(seed);
    const Parameters truth = ScatteredTire(&rng);
    IdentifyResult fit, at_truth;
    FitAndFitAtTruth(Hammer(truth, 0.02, 3, 2.0, &rng), truth, &fit, &at_truth);
    ASSERT_TRUE(fit.status.ok()) << fit.status.message;
    ASSERT_TRUE(at_truth.status.ok()) << at_truth.status.message;
    EXPECT_LE(fit.fit.chi_square, at_truth.fit.chi_square + 1) << "seed " << seed;
    EXPECT_FALSE(fit.fit.poor) << "seed " << seed << ": " << fit.fit.verdict;
  }
}

// Two lateral accelerometers give the out-of-plane modes no shape, and their
// output MAC at a far start can label them wrongly, consistently: on this
// tire only 1 of 6 starts reached the best fit when the stage kept those
// labels (with numeric derivatives on 0.5 Hz lines, none). Each order of the
// shapeless modes' labels is fitted and the one the FRFs fit best kept.
TEST(FrfStartTest, ShapelessModesAreLabelledByTheFrfsSoTheStartsAgree) {
  std::mt19937_64 rng(6);
  const Parameters truth = ScatteredTire(&rng);
  IdentifyResult fit, at_truth;
  FitAndFitAtTruth(Hammer(truth, 0.02, 3, 1.0, &rng), truth, &fit, &at_truth);
  ASSERT_TRUE(fit.status.ok()) << fit.status.message;
  ASSERT_TRUE(at_truth.status.ok()) << at_truth.status.message;
  EXPECT_LE(fit.fit.chi_square, at_truth.fit.chi_square + 1);
  EXPECT_GE(fit.start_agreement.at_best, 5) << "of " << fit.start_agreement.of;
}

}  // namespace
}  // namespace ringid
