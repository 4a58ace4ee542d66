// simulate --frf (issue 36 item 6): an FRF test's layout (ringid-frf-spec/1)
// read strictly, every bad field named; the shipped hammer spec is
// HammerTest's layout; simulate writes a format-3 dataset whose FRFs are the
// model's H at the truth, at each condition's speed; identify fits them
// within their noise.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "datasets/dataset.h"
#include "datasets/frf_spec.h"
#include "datasets/parameter_files.h"
#include "datasets/synthetic.h"
#include "model/frequency_response.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using json = nlohmann::ordered_json;

const std::string kHammerSpec = "datasets/examples/hammer_spec.json";
const std::string kDrumSpec = "datasets/examples/drum_spec.json";
const std::string kCarTire = "datasets/examples/car_tire.json";

FrfSpec Read(const std::string& relative) {
  FrfSpec spec;
  LoadError e;
  EXPECT_TRUE(LoadFrfSpec(testing::SourcePath(relative), &spec, &e)) << e.OneLine();
  return spec;
}

// `spec` written to a scratch file named `name`; its path.
std::string Written(const json& spec, const std::string& name) {
  const std::string path = testing::Scratch(name);
  std::ofstream(path) << spec.dump(1);
  return path;
}

void ExpectSamePoint(const std::optional<FrfPoint>& a, const std::optional<FrfPoint>& b,
                     const std::string& what) {
  ASSERT_EQ(a.has_value(), b.has_value()) << what;
  if (!a) return;
  EXPECT_EQ(a->on, b->on) << what;
  EXPECT_EQ(a->point_m, b->point_m) << what;
  EXPECT_EQ(a->direction, b->direction) << what;
}

// The layouts of two blocks: inputs, outputs, lines and (output, input) pairs.
void ExpectSameLayout(const Frf& a, const Frf& b) {
  ASSERT_EQ(a.inputs.size(), b.inputs.size());
  for (size_t i = 0; i < a.inputs.size(); ++i) {
    EXPECT_EQ(a.inputs[i].name, b.inputs[i].name);
    ExpectSamePoint(a.inputs[i].point, b.inputs[i].point, a.inputs[i].name);
    EXPECT_EQ(a.inputs[i].contact, b.inputs[i].contact) << a.inputs[i].name;
    EXPECT_EQ(a.inputs[i].coordinates, b.inputs[i].coordinates) << a.inputs[i].name;
  }
  ASSERT_EQ(a.outputs.size(), b.outputs.size());
  for (size_t i = 0; i < a.outputs.size(); ++i) {
    EXPECT_EQ(a.outputs[i].name, b.outputs[i].name);
    ExpectSamePoint(a.outputs[i].point, b.outputs[i].point, a.outputs[i].name);
    EXPECT_EQ(a.outputs[i].channel, b.outputs[i].channel) << a.outputs[i].name;
    EXPECT_EQ(a.outputs[i].coordinates, b.outputs[i].coordinates) << a.outputs[i].name;
    EXPECT_EQ(a.outputs[i].quantity, b.outputs[i].quantity) << a.outputs[i].name;
  }
  EXPECT_EQ(a.frequencies_hz, b.frequencies_hz);
  ASSERT_EQ(a.functions.size(), b.functions.size());
  for (size_t k = 0; k < a.functions.size(); ++k) {
    EXPECT_EQ(a.functions[k].output, b.functions[k].output) << k;
    EXPECT_EQ(a.functions[k].input, b.functions[k].input) << k;
    EXPECT_EQ(a.functions[k].h.size(), a.frequencies_hz.size()) << k;
  }
}

TEST(FrfSpecTest, TheShippedHammerSpecIsHammerTestsLayout) {
  Frf frf;
  LoadError e;
  ASSERT_TRUE(FrfOfSpec(Read(kHammerSpec), 0, &frf, &e)) << e.OneLine();
  ExpectSameLayout(frf, HammerTest(0.31, 5, 250, 0.5));
  // By hand: 4 blows x 7 sensors; 5 to 250 Hz by 0.5 is 491 lines.
  EXPECT_EQ(frf.functions.size(), 28u);
  ASSERT_EQ(frf.frequencies_hz.size(), 491u);
  EXPECT_EQ(frf.frequencies_hz.front(), 5);
  EXPECT_EQ(frf.frequencies_hz.back(), 250);
  EXPECT_EQ(Read(kHammerSpec).noise, 0.02);
}

TEST(FrfSpecTest, TheShippedDrumSpecIsDrumTestsLayout) {
  Frf frf;
  LoadError e;
  ASSERT_TRUE(FrfOfSpec(Read(kDrumSpec), 1, &frf, &e)) << e.OneLine();
  ExpectSameLayout(frf, DrumTest(4, 160, 2));
  // By hand: F_x and F_z to axle x and z, F_y to axle y, m_x, m_z; 4 to 160 Hz by 2.
  EXPECT_EQ(frf.functions.size(), 7u);
  ASSERT_EQ(frf.frequencies_hz.size(), 79u);
}

// The spec's fields written back read as the same layout, and the lines
// given as a list are the range's.
TEST(FrfSpecTest, ASpecWrittenBackAndItsLinesListedReadAsTheSameLayout) {
  for (const std::string& relative : {kHammerSpec, kDrumSpec}) {
    std::string text = testing::ReadFile(testing::SourcePath(relative));
    FrfSpecFields fields;
    std::string why;
    ASSERT_TRUE(JsonReader::FromJson(json::parse(text), "", &fields, &why)) << why;
    const FrfSpec spec = Read(relative);
    FrfSpec back;
    LoadError e;
    ASSERT_TRUE(ParseFrfSpec(JsonWriter::ToJson(fields).dump(), "back", &back, &e)) << e.OneLine();
    fields.lines_hz.reset();
    fields.frequencies_hz = spec.layout.frequencies_hz;
    FrfSpec listed;
    ASSERT_TRUE(ParseFrfSpec(JsonWriter::ToJson(fields).dump(), "listed", &listed, &e))
        << e.OneLine();
    Frf a, b, c;
    ASSERT_TRUE(FrfOfSpec(spec, 0, &a, &e) && FrfOfSpec(back, 0, &b, &e) &&
                FrfOfSpec(listed, 0, &c, &e))
        << e.OneLine();
    ExpectSameLayout(a, b);
    ExpectSameLayout(a, c);
    EXPECT_EQ(back.noise, spec.noise);
  }
}

TEST(FrfSpecTest, WithoutFunctionsEveryOutputIsPairedWithEveryInputOutputByOutput) {
  Frf frf;
  LoadError e;
  ASSERT_TRUE(FrfOfSpec(Read(kHammerSpec), 0, &frf, &e)) << e.OneLine();
  for (int o = 0, k = 0; o < 7; ++o) {
    for (int i = 0; i < 4; ++i, ++k) {
      EXPECT_EQ(frf.functions[k].output, o);
      EXPECT_EQ(frf.functions[k].input, i);
    }
  }
  // The drum spec lists 7 of 15 pairs, in its order.
  ASSERT_TRUE(FrfOfSpec(Read(kDrumSpec), 10, &frf, &e)) << e.OneLine();
  ASSERT_EQ(frf.functions.size(), 7u);
  EXPECT_EQ(frf.outputs[frf.functions[5].output].name, "axle_mx");
  EXPECT_EQ(frf.inputs[frf.functions[5].input].name, "contact_y");
  EXPECT_FALSE(Read(kDrumSpec).layout.functions.empty());
}

// A small valid spec: two blows, two sensors, three lines.
json SmallSpec() {
  return json::parse(R"({
    "format": "ringid-frf-spec/1",
    "inputs": [
      {"name": "top", "on": "belt", "point_m": [0, 0, -0.3], "direction": [0, 0, 1]},
      {"name": "side", "on": "belt", "point_m": [0, 0.08, -0.3], "direction": [0, 1, 0]}],
    "outputs": [
      {"name": "a", "on": "belt", "point_m": [0.3, 0, 0], "direction": [1, 0, 0],
       "quantity": "acceleration"},
      {"name": "b", "coordinates": {"theta_b": 1}, "quantity": "velocity"}],
    "frequencies_hz": [20, 40, 60],
    "noise": 0.01})");
}

TEST(FrfSpecTest, EachBadFieldIsRefusedNamingTheFileAndIt) {
  struct Case {
    const char* field;   // the field the error names
    const char* says;    // a part of its message
    std::function<void(json*)> edit;
  };
  const std::vector<Case> cases = {
      {"format", "must be \"ringid-frf-spec/1\"", [](json* j) { (*j)["format"] = "ringid-frf-spec/2"; }},
      {"format", "this is a modal dataset", [](json* j) { (*j)["format"] = "ringid-dataset/3"; }},
      {"nois", "", [](json* j) { (*j)["nois"] = 0.1; }},
      {"description", "", [](json* j) { (*j)["description"] = 3; }},
      {"inputs", "non-empty", [](json* j) { (*j)["inputs"] = json::array(); }},
      {"outputs", "non-empty", [](json* j) { (*j)["outputs"] = json::array(); }},
      {"inputs[1].name", "twice", [](json* j) { (*j)["inputs"][1]["name"] = "top"; }},
      {"inputs[0].name", "empty", [](json* j) { (*j)["inputs"][0]["name"] = ""; }},
      {"inputs[0].direction", "zero",
       [](json* j) { (*j)["inputs"][0]["direction"] = {0, 0, 0}; }},
      {"inputs[0].point_m", "missing", [](json* j) { (*j)["inputs"][0].erase("point_m"); }},
      {"inputs[0].point_m", "three", [](json* j) { (*j)["inputs"][0]["point_m"] = {0, 1}; }},
      {"inputs[0].contact", "not with on", [](json* j) { (*j)["inputs"][0]["contact"] = "F_x"; }},
      {"inputs[1].coordinates.x_q", "degree of freedom", [](json* j) {
         (*j)["inputs"][1] = {{"name", "side"}, {"coordinates", {{"x_q", 1}}}};
       }},
      {"outputs[0].quantity", "missing", [](json* j) { (*j)["outputs"][0].erase("quantity"); }},
      {"outputs[1].quantity", "not with channel",
       [](json* j) { (*j)["outputs"][1] = {{"name", "b"}, {"channel", "axle_force_x"},
                                            {"quantity", "velocity"}}; }},
      {"outputs[1].coordinates", "all coefficients are zero",
       [](json* j) { (*j)["outputs"][1]["coordinates"] = {{"theta_b", 0}}; }},
      {"frequencies_hz", "missing", [](json* j) { j->erase("frequencies_hz"); }},
      {"frequencies_hz[1]", "strictly increasing",
       [](json* j) { (*j)["frequencies_hz"] = {20, 10}; }},
      {"frequencies_hz[0]", "positive", [](json* j) { (*j)["frequencies_hz"] = {0, 10}; }},
      {"frequencies_hz", "non-empty", [](json* j) { (*j)["frequencies_hz"] = json::array(); }},
      {"lines_hz", "not with frequencies_hz",
       [](json* j) { (*j)["lines_hz"] = {{"from", 5}, {"to", 10}, {"step", 1}}; }},
      {"lines_hz.from", "positive", [](json* j) {
         j->erase("frequencies_hz");
         (*j)["lines_hz"] = {{"from", 0}, {"to", 10}, {"step", 1}};
       }},
      {"lines_hz.step", "positive", [](json* j) {
         j->erase("frequencies_hz");
         (*j)["lines_hz"] = {{"from", 5}, {"to", 10}, {"step", -1}};
       }},
      {"lines_hz.to", "not below", [](json* j) {
         j->erase("frequencies_hz");
         (*j)["lines_hz"] = {{"from", 50}, {"to", 10}, {"step", 1}};
       }},
      {"lines_hz.step", "more than", [](json* j) {
         j->erase("frequencies_hz");
         (*j)["lines_hz"] = {{"from", 1}, {"to", 1000}, {"step", 1e-4}};
       }},
      {"lines_hz.step", "would not increase", [](json* j) {  // below 1e6's spacing (1.2e-10)
         j->erase("frequencies_hz");
         (*j)["lines_hz"] = {{"from", 1e6}, {"to", 1e6 + 4.7e-10}, {"step", 1e-11}};
       }},
      {"lines_hz.to", "", [](json* j) {
         j->erase("frequencies_hz");
         (*j)["lines_hz"] = {{"from", 5}, {"step", 1}};
       }},
      {"functions", "non-empty", [](json* j) { (*j)["functions"] = json::array(); }},
      {"functions[0].output", "unknown output", [](json* j) {
         (*j)["functions"] = {{{"output", "c"}, {"input", "top"}}};
       }},
      {"functions[0].input", "unknown input", [](json* j) {
         (*j)["functions"] = {{{"output", "a"}, {"input", "tip"}}};
       }},
      {"functions[1]", "at most once", [](json* j) {
         (*j)["functions"] = {{{"output", "a"}, {"input", "top"}}, {{"output", "a"}, {"input", "top"}}};
       }},
      {"noise", ">= 0", [](json* j) { (*j)["noise"] = -0.01; }},
      {"noise", ">= 0", [](json* j) { (*j)["noise"] = nullptr; }},
  };
  {
    FrfSpec spec;
    LoadError e;
    ASSERT_TRUE(ParseFrfSpec(SmallSpec().dump(), "spec.json", &spec, &e)) << e.OneLine();
  }
  for (const Case& c : cases) {
    json j = SmallSpec();
    c.edit(&j);
    FrfSpec spec;
    LoadError e;
    EXPECT_FALSE(ParseFrfSpec(j.dump(), "spec.json", &spec, &e)) << c.field;
    EXPECT_EQ(e.file, "spec.json") << c.field;
    EXPECT_EQ(e.field, c.field) << e.OneLine();
    EXPECT_NE(e.message.find(c.says), std::string::npos) << c.field << ": " << e.OneLine();
    EXPECT_EQ(e.OneLine().find('\n'), std::string::npos) << e.OneLine();
  }
}

// At speed, contract §9 takes contact inputs and channel or coordinates
// outputs only: a point force in the spec is refused naming it.
TEST(FrfSpecTest, AtSpeedAPointForceIsRefusedNamingTheSpecsField) {
  const FrfSpec spec = Read(kHammerSpec);
  Frf frf;
  LoadError e;
  EXPECT_FALSE(FrfOfSpec(spec, 10, &frf, &e));
  EXPECT_EQ(e.field, "inputs[0].on") << e.OneLine();
  EXPECT_NE(e.message.find("at speed_m_s 10"), std::string::npos) << e.OneLine();
  EXPECT_TRUE(FrfOfSpec(Read(kDrumSpec), 10, &frf, &e)) << e.OneLine();
}

// The command line: a bad spec is exit 2 with one line naming the file and
// the field, nothing written.
TEST(FrfSpecTest, SimulateRefusesABadSpecWithOneLineAndWritesNothing) {
  json lacking = SmallSpec();  // x_a without hub_compliance
  lacking["inputs"][1] = {{"name", "side"}, {"coordinates", {{"x_a", 1}}}};
  const struct {
    std::string spec, speeds, field;
  } cases[] = {
      {testing::SourcePath(kHammerSpec), "0,10", "inputs[0].on"},
      {Written(lacking, "lacking_spec.json"), "0", "inputs[1].coordinates"},
      {testing::SourcePath(kCarTire), "0", "format"},
  };
  for (const auto& c : cases) {
    const std::string out = testing::Scratch("refused.json"), truth = testing::Scratch("t.json");
    const testing::RunResult r =
        testing::Ringid("simulate --parameters=" + testing::SourcePath(kCarTire) + " --frf=" +
                        c.spec + " --speeds=" + c.speeds + " --output=" + out + " --truth=" + truth);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.err.find(c.spec + ": " + c.field + ": "), 8u) << r.err;  // after "ringid: "
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(testing::Exists(out)) << c.field;
    EXPECT_FALSE(testing::Exists(truth)) << c.field;
  }
  testing::RunResult r = testing::Ringid(
      "simulate --parameters=" + testing::SourcePath(kCarTire) + " --frf_modes --output=" +
      testing::Scratch("m.json") + " --truth=" + testing::Scratch("mt.json"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--frf_modes: only with --frf"), std::string::npos) << r.err;
  // A valid spec whose dataset the loader could not read back (over 4 MiB).
  json big = json::parse(testing::ReadFile(testing::SourcePath(kHammerSpec)));
  big["lines_hz"] = {{"from", 1}, {"to", 1000}, {"step", 0.5}};
  const std::string spec = Written(big, "big_spec.json"), out = testing::Scratch("big.json");
  r = testing::Ringid("simulate --parameters=" + testing::SourcePath(kCarTire) + " --frf=" + spec +
                      " --output=" + out + " --truth=" + testing::Scratch("big_truth.json"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--frf: " + spec + " lays out a dataset of "), std::string::npos) << r.err;
  EXPECT_FALSE(testing::Exists(out));
}

// What the model gives for `frf`'s functions at `p` and `speed_m_s`,
// asked of FrequencyResponse directly.
Eigen::MatrixXcd ModelH(const Frf& frf, const Parameters& p, double speed_m_s) {
  ResponseRequest request;
  for (const FrfInput& in : frf.inputs) {
    ResponseInput r;
    r.contact = in.contact;
    r.coordinates.assign(in.coordinates.begin(), in.coordinates.end());
    r.on_rim = in.point && in.point->on == FrfBody::kRim;
    request.inputs.push_back(r);
  }
  for (const FrfOutput& out : frf.outputs) {
    ResponseOutput r;
    r.channel = out.channel;
    r.coordinates.assign(out.coordinates.begin(), out.coordinates.end());
    r.order = static_cast<int>(out.quantity);  // displacement 0, velocity 1, acceleration 2
    r.on_rim = out.point && out.point->on == FrfBody::kRim;
    request.outputs.push_back(r);
  }
  for (const FrfFunction& f : frf.functions) request.pairs.emplace_back(f.output, f.input);
  request.frequencies_hz = frf.frequencies_hz;
  const ResponseResult r = FrequencyResponse(RigidRingModel(), p, speed_m_s, request);
  EXPECT_TRUE(r.ok) << r.error;
  return r.H;
}

// simulate --frf with noise 0: a format-3 dataset of the spec's FRFs and no
// modes, each value the model's H at the truth in its condition; sigma at
// the default level (FrfSigma); standing a hammer test, on the drum at two
// speeds the contact-to-axle FRFs.
TEST(FrfSpecTest, SimulateWritesTheModelsFrfsAtTheTruthInEachCondition) {
  json hammer = json::parse(testing::ReadFile(testing::SourcePath(kHammerSpec)));
  hammer["lines_hz"] = {{"from", 20}, {"to", 120}, {"step", 10}};
  hammer["noise"] = 0;
  json drum = json::parse(testing::ReadFile(testing::SourcePath(kDrumSpec)));
  drum["lines_hz"] = {{"from", 10}, {"to", 100}, {"step", 15}};
  drum["noise"] = 0;
  const struct {
    json spec;
    std::string speeds;
    std::vector<double> at;
  } runs[] = {{hammer, "0", {0}}, {drum, "5,15", {5, 15}}};
  Parameters truth;
  LoadError e;
  ASSERT_TRUE(LoadParameterSet(testing::SourcePath(kCarTire), &truth, &e)) << e.OneLine();
  for (const auto& run : runs) {
    const std::string spec = Written(run.spec, "spec.json");
    const std::string out = testing::Scratch("frf.json"), truth_file = testing::Scratch("tr.json");
    const testing::RunResult r =
        testing::Ringid("simulate --parameters=" + testing::SourcePath(kCarTire) + " --frf=" +
                        spec + " --speeds=" + run.speeds + " --output=" + out +
                        " --truth=" + truth_file);
    ASSERT_EQ(r.status, 0) << r.err;
    const size_t functions = run.spec.contains("functions") ? run.spec["functions"].size() : 28;
    EXPECT_NE(r.out.find(std::to_string(functions * run.at.size()) + " FRFs"), std::string::npos)
        << r.out;
    EXPECT_EQ(json::parse(testing::ReadFile(out))["format"], "ringid-dataset/3");
    Dataset d;
    ASSERT_TRUE(LoadDataset(out, &d, &e)) << e.OneLine();
    EXPECT_TRUE(d.modes.empty());
    for (Param q : {Param::m_b, Param::I_ay, Param::I_by, Param::I_bx, Param::I_bz}) {
      EXPECT_FALSE(d.known.count(q)) << ParamName(q) << ": the FRFs weigh it";
      EXPECT_TRUE(d.initial.count(q)) << ParamName(q);
    }
    ASSERT_EQ(d.conditions.size(), run.at.size());
    for (size_t c = 0; c < run.at.size(); ++c) {
      ASSERT_TRUE(d.conditions[c].frf) << c;
      const Frf& frf = *d.conditions[c].frf;
      EXPECT_EQ(d.conditions[c].speed_m_s, run.at[c]);
      const Eigen::MatrixXcd h = ModelH(frf, truth, run.at[c]);
      ASSERT_EQ(h.cols(), static_cast<long>(frf.functions.size()));
      std::vector<double> peak(frf.outputs.size(), 0.0);
      for (size_t f = 0; f < frf.functions.size(); ++f) {
        for (long l = 0; l < h.rows(); ++l) {
          peak[frf.functions[f].output] = std::max(peak[frf.functions[f].output], std::abs(h(l, f)));
        }
      }
      for (size_t f = 0; f < frf.functions.size(); ++f) {
        for (long l = 0; l < h.rows(); ++l) {
          EXPECT_LE(std::abs(frf.functions[f].h[l] - h(l, f)), 1e-12 * std::abs(h(l, f)))
              << "function " << f << " line " << l;
          EXPECT_NEAR(frf.functions[f].sigma[l],
                      FrfSigma(kDefaultFrfRelativeSigma, h(l, f), peak[frf.functions[f].output]),
                      1e-12 * frf.functions[f].sigma[l]);
        }
      }
    }
  }
}

TEST(FrfSpecTest, FrfModesKeepsTheSevenModesBesideTheFrfs) {
  const std::string out = testing::Scratch("both.json");
  const testing::RunResult r = testing::Ringid(
      "simulate --parameters=" + testing::SourcePath(kCarTire) + " --frf=" +
      testing::SourcePath(kDrumSpec) + " --frf_modes --speeds=0,10 --output=" + out +
      " --truth=" + testing::Scratch("both_truth.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("14 modes, 14 FRFs in 2 conditions"), std::string::npos) << r.out;
  Dataset d;
  LoadError e;
  ASSERT_TRUE(LoadDataset(out, &d, &e)) << e.OneLine();
  EXPECT_EQ(d.modes.size(), 14u);
  EXPECT_TRUE(d.conditions[1].frf);
}

// With 2 % noise, identify from simulate's initial values (10 % off) fits
// the FRFs within their noise.
TEST(FrfSpecTest, IdentifyFitsASimulatedHammerTestWithinItsNoise) {
  json spec = json::parse(testing::ReadFile(testing::SourcePath(kHammerSpec)));
  spec["lines_hz"] = {{"from", 10}, {"to", 150}, {"step", 5}};
  const std::string out = testing::Scratch("noisy.json");
  testing::RunResult r = testing::Ringid(
      "simulate --parameters=" + testing::SourcePath(kCarTire) + " --frf=" +
      Written(spec, "noisy_spec.json") + " --seed=5 --output=" + out + " --truth=" +
      testing::Scratch("noisy_truth.json"));
  ASSERT_EQ(r.status, 0) << r.err;
  r = testing::Ringid("identify --dataset=" + out + " --starts=1 --derivatives=analytic");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("the model fits within the noise"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace ringid
