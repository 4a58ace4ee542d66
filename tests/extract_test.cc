// extract (issue 37): the modes in a dataset's FRFs as a modal dataset,
// checked against the model's own modes at the synthetic truth, and the
// two-step route (extract, then identify) against that truth.
#include "operations/extract.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>

#include <gtest/gtest.h>

#include "datasets/synthetic.h"
#include "estimation/identify.h"
#include "tests/test_support.h"
#include "validation/suites.h"

namespace ringid {
namespace {

// A scattered tire's standing hammer test (lines every 1 Hz), masses free at
// initial values `mass_factor` times the truth, the others 15 % off; written
// to a scratch file, whose path is returned.
std::string HammerFile(const Parameters& truth, double noise, double mass_factor,
                       std::mt19937_64* rng, const std::string& name) {
  Dataset d = PlanSimulation(truth, 0, {0}, {}, rng);
  FreeMasses(truth, 0, rng, &d);
  d.name = name;
  d.conditions[0].frf = HammerTest(0.31, 5, 250, 1.0);
  SimulateOptions so;
  so.modes = false;
  so.frf_noise = noise;
  std::string why;
  EXPECT_TRUE(Simulate(RigidRingModel(), truth, so, rng, &d, &why)) << why;
  for (auto& [q, v] : d.initial) v = truth[q] * (IsMassOrInertia(q) ? mass_factor : 1.15);
  const std::string path = testing::Scratch(name);
  std::ofstream(path) << DatasetToJson(d);
  return path;
}

TEST(ExtractTest, NoiseFreeFrfsGiveTheModelsModesLabelledAsTheModelLabelsThem) {
  std::mt19937_64 rng(2);
  const Parameters truth = ScatteredTire(&rng);
  const std::string path = HammerFile(truth, 0, 1.2, &rng, "extract_noise_free.json");
  ExtractResult x;
  InputError error;
  ASSERT_TRUE(ExtractDataset(path, ExtractSettings{}, &x, &error)) << error.line;
  const ModalSolution s = RigidRingModel().Solve(truth);
  ASSERT_TRUE(s.ok) << s.error;
  ASSERT_EQ(x.dataset.modes.size(), s.modes.size());
  for (const MeasuredMode& m : x.dataset.modes) {
    const auto model = std::find_if(s.modes.begin(), s.modes.end(),
                                    [&](const Mode& k) { return k.label == m.label; });
    ASSERT_NE(model, s.modes.end());
    EXPECT_NEAR(m.frequency_hz / model->frequency_hz, 1, 1e-6) << LabelName(m.label);
    ASSERT_TRUE(m.damping_ratio.has_value());
    EXPECT_NEAR(*m.damping_ratio / model->damping_ratio, 1, 1e-5) << LabelName(m.label);
    // A hammer test's four in-plane coordinates are determined, its two
    // lateral accelerometers leave the out-of-plane shapes undetermined.
    EXPECT_EQ(m.shape.empty(), model->plane() == Plane::kOutOfPlane) << LabelName(m.label);
  }
  EXPECT_EQ(x.poles.size(), s.modes.size());
  // Modes carry no modal mass: every free mass is known at its initial value.
  for (int i = 0; i < kNumParams; ++i) {
    const Param p = ParamAt(i);
    if (!IsMassOrInertia(p)) continue;
    EXPECT_EQ(x.dataset.initial.count(p), 0u) << ParamName(p);
    ASSERT_EQ(x.dataset.known.count(p), 1u) << ParamName(p);
    EXPECT_NEAR(x.dataset.known.at(p) / truth[p], 1.2, 1e-12) << ParamName(p);
  }
  EXPECT_TRUE(std::none_of(x.dataset.conditions.begin(), x.dataset.conditions.end(),
                           [](const Condition& c) { return c.frf.has_value(); }));
}

// The two-step route: with the masses weighed (known at the truth), the
// extracted modes of noise-free FRFs identify the stiffnesses the modes
// determine at the truth.
TEST(ExtractTest, ExtractThenIdentifyWithTheMassesWeighedRecoversTheTruth) {
  std::mt19937_64 rng(3);
  const Parameters truth = ScatteredTire(&rng);
  const std::string path = HammerFile(truth, 0, 1.0, &rng, "extract_two_step.json");
  ExtractResult x;
  InputError error;
  ASSERT_TRUE(ExtractDataset(path, ExtractSettings{}, &x, &error)) << error.line;
  const std::string modes = testing::Scratch("extract_two_step_modes.json");
  std::ofstream(modes) << DatasetToJson(x.dataset);
  Dataset d;
  LoadError load;
  ASSERT_TRUE(LoadDataset(modes, &d, &load)) << load.OneLine();
  IdentifyOptions o;
  o.residuals.derivatives = Derivatives::kAnalytic;
  IdentifyResult r;
  Identify(RigidRingModel(), d, o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  int checked = 0;
  for (const ParameterEstimate& e : r.estimates) {
    if (e.identifiable != Identifiability::kYes) continue;
    EXPECT_NEAR(e.value / truth[e.param()], 1, 1e-4) << ParamName(e.param());
    ++checked;
  }
  EXPECT_GE(checked, 6);
}

TEST(ExtractTest, ADatasetWithoutFrfsIsOneLineExitTwoAndNothingWritten) {
  const std::string out = testing::Scratch("extract_never_written.json");
  std::remove(out.c_str());
  const std::string table1 = testing::SourcePath("datasets/paper/table1.json");
  const testing::RunResult r = testing::Ringid("extract --dataset=" + table1 + " --output=" + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("table1.json: conditions: no condition has an frf block"), std::string::npos)
      << r.err;
  EXPECT_FALSE(std::ifstream(out).good());
  const testing::RunResult bad = testing::Ringid("extract --dataset=" + table1 + " --max_model_order=0 --output=" + out);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--max_model_order"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::ifstream(out).good());
}

}  // namespace
}  // namespace ringid
