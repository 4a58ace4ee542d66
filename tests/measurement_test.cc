// The measured quantities as units (datasets/measurement.h): every quantity
// registered once; a mode measured without noise fits itself; the noise each
// unit adds has the sigma it writes (a Monte Carlo), with one degree of
// freedom less for a shape, whose scale is fitted.
#include <cmath>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "datasets/measurement.h"
#include "datasets/synthetic.h"
#include "model/rigid_ring_model.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

// Every mode of the car tire standing and at 20 m/s (rolling terms and slip
// states included).
std::vector<Mode> Modes(bool derivatives = false) {
  const RigidRingModel model;
  std::vector<Mode> modes;
  for (double speed : {0.0, 20.0}) {
    const ModalSolution s = model.Solve(ExampleCarTire(), speed, derivatives);
    EXPECT_TRUE(s.ok) << s.error;
    modes.insert(modes.end(), s.modes.begin(), s.modes.end());
  }
  EXPECT_GE(modes.size(), 14u);
  return modes;
}

// A measured mode that carries every quantity of `mode`, without noise.
MeasuredMode Measured(const Mode& mode, const MeasurementOptions& o) {
  MeasuredMode m;
  m.label = mode.label;
  for (const ModeQuantity* unit : ModeQuantities()) unit->Add(mode, o, AdviceSigmas{}, &m);
  return m;
}

TEST(MeasurementTest, EveryQuantityIsRegisteredOnce) {
  std::set<Quantity> seen;
  for (const Measurement* unit : Measurements()) {
    EXPECT_TRUE(seen.insert(unit->quantity()).second) << ToString(unit->quantity());
    EXPECT_EQ(&MeasurementOf(unit->quantity()), unit);
  }
  EXPECT_EQ(seen.size(), EnumNames<Quantity>::kNames.size());
}

TEST(MeasurementTest, AModeMeasuredWithoutNoiseFitsItselfUnderEitherConvention) {
  for (ShapeConvention convention : {ShapeConvention::kContract, ShapeConvention::kPaper}) {
    MeasurementOptions o;
    o.shape_convention = convention;
    for (const Mode& mode : Modes()) {
      const MeasuredMode m = Measured(mode, o);
      for (const ModeQuantity* unit : ModeQuantities()) {
        const int rows = unit->Rows(m, o);
        ASSERT_GT(rows, 0) << ToString(unit->quantity());
        std::vector<double> r(rows, NAN);
        RowMatrix none;
        unit->Evaluate(m, mode, o, r.data(), nullptr, none);
        for (double v : r) {
          EXPECT_NEAR(v, 0, 1e-9) << ToString(unit->quantity()) << " " << LabelName(mode.label)
                                  << " " << ToString(convention);
        }
      }
    }
  }
}

// Measured again from its own measurement, a mode changes in nothing.
TEST(MeasurementTest, MeasuringAgainChangesNothingButTheValues) {
  const MeasurementOptions o;
  const std::vector<Mode> modes = Modes();
  for (size_t i = 0; i + 1 < modes.size(); ++i) {
    MeasuredMode m = Measured(modes[i], o);
    const MeasuredMode before = m;
    for (const ModeQuantity* unit : ModeQuantities()) unit->Measure(modes[i + 1], o, &m);
    for (const ModeQuantity* unit : ModeQuantities()) unit->Measure(modes[i], o, &m);
    EXPECT_DOUBLE_EQ(m.frequency_hz, before.frequency_hz);
    EXPECT_EQ(m.frequency_sigma_hz, before.frequency_sigma_hz);
    EXPECT_EQ(m.damping_sigma, before.damping_sigma);
    EXPECT_EQ(m.shape_sigma, before.shape_sigma);
    ASSERT_EQ(m.shape.size(), before.shape.size());
    for (size_t k = 0; k < m.shape.size(); ++k) EXPECT_EQ(m.shape[k].first, before.shape[k].first);
  }
}

// Residuals of noisy measurements of the true mode: each frequency and
// damping row is N(0, 1) (mean square 1); a shape of n components, its
// scale fitted, has a chi-square of n - 1 degrees of freedom. 4000 draws
// put a mean square within 5 % of its expectation (its standard error is
// sqrt(2 / 4000) = 2.2 % for one degree of freedom, less for more).
TEST(MeasurementTest, TheNoiseOfEachQuantityHasTheSigmaItStates) {
  const MeasurementOptions o;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n(0, 1);
  const std::vector<Mode> modes = Modes();
  for (const Mode& mode : {modes[0], modes[3], modes[9]}) {
    for (const ModeQuantity* unit : ModeQuantities()) {
      const double noise = unit->quantity() == Quantity::kShape ? 0.003 : 0.01;
      const MeasuredMode truth = Measured(mode, o);
      const int rows = unit->Rows(truth, o);
      const double dof = unit->quantity() == Quantity::kShape ? rows - 1 : rows;
      double sum = 0;
      const int draws = 4000;
      for (int d = 0; d < draws; ++d) {
        MeasuredMode m = truth;
        unit->AddNoise(noise, [&] { return n(rng); }, &m);
        std::vector<double> r(rows);
        RowMatrix none;
        unit->Evaluate(m, mode, o, r.data(), nullptr, none);
        for (double v : r) sum += v * v;
      }
      EXPECT_NEAR(sum / draws / dof, 1, 0.05) << ToString(unit->quantity()) << " "
                                               << LabelName(mode.label);
    }
  }
}

}  // namespace
}  // namespace ringid
