// Static stiffness as a measurement (contract §10, issue 35): dataset format
// 3 reads, refuses and writes back; its rows are the model's static solve;
// added to a standing modal test it narrows k_cz; identify recovers a
// synthetic truth from modes and static stiffnesses together.
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "datasets/dataset.h"
#include "datasets/measurement.h"
#include "datasets/synthetic.h"
#include "estimation/identifiability.h"
#include "estimation/identify.h"
#include "estimation/problem.h"
#include "model/static_stiffness.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using json = nlohmann::json;

std::string LabErrorOf(const json& j) { return testing::DatasetErrorOf(j, "lab.json"); }

// A format-3 dataset: a standing condition with two modes, its static
// stiffnesses and an FRF; a drum condition with one mode.
json Format3() {
  return json::parse(R"({
    "format": "ringid-dataset/3", "name": "lab",
    "known": {"m_b": 7.7, "F_cz0": 4000},
    "conditions": [
      {"name": "standing",
       "modes": [{"label": "vertical", "frequency_hz": 80.1},
                 {"label": "lateral", "frequency_hz": 45.2, "damping_ratio": 0.05}],
       "static": [{"kind": "vertical", "value": 180000, "sigma": 2000},
                  {"kind": "lateral", "value": 95000}],
       "frf": {"inputs": [{"name": "hammer", "coordinates": {"z_b": 1}}],
               "outputs": [{"name": "acc", "coordinates": {"z_b": 1},
                            "quantity": "acceleration"}],
               "frequencies_hz": [10, 20],
               "functions": [{"output": "acc", "input": "hammer", "re": [0.1, 0.2],
                              "im": [0.0, -0.1], "sigma": [0.01, 0.01]}]}},
      {"name": "drum_6", "speed_m_s": 6,
       "modes": [{"label": "vertical", "frequency_hz": 79.5}]}]})");
}

TEST(StaticMeasurementTest, Format3ReadsEachMeasurementOfEachCondition) {
  Dataset d;
  LoadError e;
  ASSERT_TRUE(ParseDataset(Format3().dump(), "lab.json", &d, &e)) << e.OneLine();
  EXPECT_EQ(d.format, 3);
  ASSERT_EQ(d.conditions.size(), 2u);
  EXPECT_EQ(d.modes.size(), 3u);
  ASSERT_EQ(d.statics.size(), 2u);
  EXPECT_EQ(d.statics[0].direction, StaticDirection::kVertical);
  EXPECT_EQ(d.statics[0].value, 180000);
  EXPECT_EQ(d.statics[0].sigma, 2000);
  EXPECT_EQ(d.statics[1].direction, StaticDirection::kLateral);
  EXPECT_FALSE(d.statics[1].sigma.has_value());
  EXPECT_EQ(d.statics[1].condition, 0);
  ASSERT_TRUE(d.conditions[0].frf.has_value());
  EXPECT_EQ(d.conditions[0].frf->functions.size(), 1u);
  EXPECT_FALSE(d.conditions[1].frf.has_value());
}

TEST(StaticMeasurementTest, Format3WrittenReadAndWrittenAgainGivesTheSameBytes) {
  Dataset d;
  LoadError e;
  ASSERT_TRUE(ParseDataset(Format3().dump(), "lab.json", &d, &e)) << e.OneLine();
  const std::string once = DatasetToJson(d);
  Dataset back;
  ASSERT_TRUE(ParseDataset(once, "once.json", &back, &e)) << e.OneLine();
  EXPECT_EQ(DatasetToJson(back), once);
  EXPECT_NE(once.find("\"ringid-dataset/3\""), std::string::npos);
  // A static stiffness alone makes a dataset built in code format 3.
  Dataset built;
  built.name = "built";
  built.modes.push_back({ModeLabel::kVertical, 80.0});
  built.statics.push_back({StaticDirection::kLongitudinal, 1.2e5, std::nullopt, 0});
  Dataset read;
  ASSERT_TRUE(ParseDataset(DatasetToJson(built), "built.json", &read, &e)) << e.OneLine();
  EXPECT_EQ(read.format, 3);
  ASSERT_EQ(read.statics.size(), 1u);
  EXPECT_EQ(read.statics[0].direction, StaticDirection::kLongitudinal);
}

TEST(StaticMeasurementTest, Format3RefusesEachBadStaticNamingTheField) {
  struct Case {
    std::string what;
    std::function<void(json*)> edit;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"at speed", [](json* j) { (*j)["conditions"][1]["static"] = json::parse(R"([{"kind": "vertical", "value": 1e5}])"); },
       "lab.json: conditions[1].static: a static stiffness is measured standing"},
      {"twice", [](json* j) { (*j)["conditions"][0]["static"][1]["kind"] = "vertical"; },
       "lab.json: conditions[0].static[1].kind: 'vertical' appears twice"},
      {"negative", [](json* j) { (*j)["conditions"][0]["static"][0]["value"] = -1; },
       "lab.json: conditions[0].static[0].value: must be positive"},
      {"zero sigma", [](json* j) { (*j)["conditions"][0]["static"][0]["sigma"] = 0; },
       "lab.json: conditions[0].static[0].sigma: must be positive"},
      {"unknown kind", [](json* j) { (*j)["conditions"][0]["static"][0]["kind"] = "torsional"; },
       "lab.json: conditions[0].static[0].kind"},
      {"unknown key", [](json* j) { (*j)["conditions"][0]["static"][0]["unit"] = "N/m"; },
       "lab.json: conditions[0].static[0].unit"},
      {"empty", [](json* j) { (*j)["conditions"][0]["static"] = json::array(); },
       "lab.json: conditions[0].static: must be a non-empty array"},
      {"nothing measured", [](json* j) { (*j)["conditions"][1].erase("modes"); },
       "lab.json: conditions[1]: holds no measurement"},
      {"format 2", [](json* j) { (*j)["format"] = "ringid-modal-dataset/2"; },
       "lab.json: conditions[0].static: needs format \"ringid-dataset/3\""},
      {"format 2 without modes", [](json* j) {
         (*j)["format"] = "ringid-modal-dataset/2";
         for (auto& c : (*j)["conditions"]) c.erase("static"), c.erase("frf");
         (*j)["conditions"][1].erase("modes");
       },
       "lab.json: conditions[1].modes: missing"},
      {"top-level modes", [](json* j) { (*j)["modes"] = json::array(); },
       "lab.json: modes: not used in format 3"},
  };
  for (const Case& c : cases) {
    json j = Format3();
    c.edit(&j);
    const std::string error = LabErrorOf(j);
    EXPECT_EQ(error.rfind(c.expected, 0), 0u) << c.what << ": " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << c.what;
  }
}

// The car tire standing: its seven modes (frequencies, damping ratios and
// shapes) with noise, and optionally its static stiffnesses.
Dataset StandingTest(const std::vector<StaticDirection>& statics, std::mt19937_64* rng) {
  const Parameters truth = ExampleCarTire();
  Dataset d = PlanSimulation(truth, 0.1, {0}, {}, rng);
  d.name = "standing";
  SimulateOptions so;
  so.statics = statics;
  std::string why;
  EXPECT_TRUE(Simulate(RigidRingModel(), truth, so, rng, &d, &why)) << why;
  return d;
}

double RelativeStd(const IdentifyResult& r, Param p) {
  for (const ParameterEstimate& e : r.estimates) {
    if (e.param() == p && e.std) return *e.std / e.value;
  }
  return NAN;
}

// The residual contact stiffness k_cz sits in series with the sidewall in
// the static vertical stiffness, and beside it in the vertical mode: the two
// together pin it far better than the modes alone.
TEST(StaticMeasurementTest, AStaticVerticalStiffnessNarrowsK_czOfAStandingModalTest) {
  std::mt19937_64 rng(5);
  const Dataset modes = StandingTest({}, &rng);
  Dataset with = modes;
  const Parameters truth = ExampleCarTire();
  const StaticStiffnessResult k = StaticStiffness(RigidRingModel(), truth, StaticDirection::kVertical);
  ASSERT_TRUE(k.ok) << k.error;
  with.format = 3;
  with.statics.push_back({StaticDirection::kVertical, k.value, 0.02 * k.value, 0});
  IdentifyOptions o;
  IdentifyResult a, b;
  Identify(RigidRingModel(), modes, o, &a);
  Identify(RigidRingModel(), with, o, &b);
  ASSERT_TRUE(a.status.ok()) << a.status.message;
  ASSERT_TRUE(b.status.ok()) << b.status.message;
  const double before = RelativeStd(a, Param::k_cz), after = RelativeStd(b, Param::k_cz);
  EXPECT_LT(after, 0.8 * before) << "k_cz relative std " << before << " -> " << after;
  // The report lists the static stiffness measured against fitted.
  ASSERT_TRUE(b.measurements.has_value());
  ASSERT_EQ(b.measurements->size(), 1u);
  EXPECT_EQ((*b.measurements)[0].name, "static vertical stiffness");
  EXPECT_LT(std::abs((*b.measurements)[0].model - k.value), 3 * 0.02 * k.value);
  EXPECT_FALSE(a.measurements.has_value());
}

// Noise-free modes and static stiffnesses of the truth: the fit from the
// engineer's start finds it, every free parameter to 1e-4.
TEST(StaticMeasurementTest, ModesAndStaticStiffnessesTogetherRecoverTheTruth) {
  std::mt19937_64 rng(9);
  const Parameters truth = ExampleCarTire();
  Dataset d = PlanSimulation(truth, 0.2, {0}, {}, &rng);
  d.name = "noise-free";
  SimulateOptions so;
  so.frequency_noise = so.damping_noise = so.shape_noise = so.static_noise = 0;
  so.statics = {StaticDirection::kVertical, StaticDirection::kLongitudinal,
                StaticDirection::kLateral};
  std::string why;
  ASSERT_TRUE(Simulate(RigidRingModel(), truth, so, &rng, &d, &why)) << why;
  for (MeasuredMode& m : d.modes) {  // sigmas the noise-free simulation left unset
    m.frequency_sigma_hz = 0.0025 * m.frequency_hz;
    m.damping_sigma = 0.1 * *m.damping_ratio;
    m.shape_sigma = 0.02;
  }
  ASSERT_EQ(d.statics.size(), 3u);
  IdentifyResult r;
  Identify(RigidRingModel(), d, IdentifyOptions{}, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_LT(r.fit.chi_square, 1e-6);
  for (const ParameterEstimate& e : r.estimates) {
    if (!e.free) continue;
    EXPECT_NEAR(e.value / truth[e.param()], 1, 1e-4) << ParamName(e.param());
  }
  ASSERT_TRUE(r.measurements.has_value());
  EXPECT_EQ(r.measurements->size(), 3u);
}

// Modes do not change when every mass, damper and stiffness scales by one
// factor, so with the masses and the load free the modes alone leave them
// structurally undetermined; a
// static stiffness is a stiffness, not a ratio of them, and removes that
// freedom (Measurement::SeesScale in the structural test).
TEST(StaticMeasurementTest, AStaticStiffnessFixesTheScaleTheModesLeaveFree) {
  const Parameters truth = ExampleCarTire();
  for (const bool statics : {false, true}) {
    std::mt19937_64 rng(21);
    Dataset d = StandingTest(statics ? std::vector<StaticDirection>{StaticDirection::kVertical,
                                                                     StaticDirection::kLongitudinal,
                                                                     StaticDirection::kLateral}
                                     : std::vector<StaticDirection>{},
                             &rng);
    for (Param p : {Param::m_b, Param::I_ay, Param::I_by, Param::I_bx, Param::I_bz, Param::F_cz0}) {
      d.known.erase(p);
      d.initial[p] = truth[p];
    }
    d.ties[Param::I_bz] = Param::I_bx;
    d.initial.erase(Param::I_bz);
    IdentifyResult r;
    IdentifyOptions o;
    o.starts = 1;
    Identify(RigidRingModel(), d, o, &r);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    for (const ParameterEstimate& e : r.estimates) {
      if (e.param() != Param::m_b) continue;
      if (statics) {
        EXPECT_EQ(e.identifiable, Identifiability::kYes) << e.reason;
        ASSERT_TRUE(e.std.has_value());
        EXPECT_LT(*e.std / e.value, 0.1);
      } else {
        EXPECT_EQ(e.identifiable, Identifiability::kNo) << e.reason;
      }
    }
  }
}

// Experiment advice weighs a static stiffness the test did not measure,
// named as such, for a parameter it informs.
TEST(StaticMeasurementTest, AdviceWeighsTheStaticStiffnessesNotMeasured) {
  std::mt19937_64 rng(3);
  Dataset d = StandingTest({}, &rng);
  for (MeasuredMode& m : d.modes) m.shape.clear(), m.damping_ratio.reset();
  IdentifiabilityOptions o;
  o.profile_steps = 0;
  IdentifiabilityResult r;
  AnalyzeIdentifiability(RigidRingModel(), d, o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  bool named = false;
  for (const Advice& a : r.advice) named |= a.observation.rfind("a static ", 0) == 0;
  EXPECT_TRUE(named) << "no advice names a static stiffness";
}

}  // namespace
}  // namespace ringid
