// The frf block of dataset format 3 (contract §9, datasets/frf.h): a
// hand-written block reads, its points' combinations agree with the
// contract's worked example, hand computations and the rigid-body motion of
// the point; coherence gives Bendat & Piersol's sigma; each rule refuses its
// breach naming the field; what ringid writes reads back to the same bytes.
#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "datasets/dataset.h"
#include "datasets/frf.h"
#include "model/archive.h"
#include "report/schema.h"

namespace ringid {
namespace {

constexpr char kFile[] = "lab.json";
constexpr char kBlock[] = "conditions[0].frf";

// A hand-written block of contract §9 with every kind of input and output.
Json Valid() {
  return Json::parse(R"({
    "inputs": [
      {"name": "hammer_top", "on": "belt", "point_m": [0, 0, -0.31], "direction": [1, 0, 0]},
      {"name": "shaker", "on": "belt", "point_m": [0.1, 0.2, -0.3], "direction": [3, 0, 4]},
      {"name": "rim_tap", "on": "rim", "point_m": [0.2, 0.05, 0.1], "direction": [0, 3, 4]},
      {"name": "drive", "coordinates": {"x_b": 1.0, "theta_b": 0.3}},
      {"name": "contact_x", "contact": "F_x"}
    ],
    "outputs": [
      {"name": "acc_top", "on": "belt", "point_m": [0, 0, -0.31], "direction": [0, 0, 1],
       "quantity": "acceleration"},
      {"name": "belt_x", "coordinates": {"x_b": 1.0}, "quantity": "displacement"},
      {"name": "axle_x", "channel": "axle_force_x"}
    ],
    "frequencies_hz": [50, 60.5, 70],
    "functions": [
      {"output": "acc_top", "input": "hammer_top",
       "re": [0.1, -0.2, 0.3], "im": [0.01, 0.02, -0.03], "sigma": [0.01, 0.02, 0.03]},
      {"output": "axle_x", "input": "hammer_top",
       "re": [3, 1, -2], "im": [4, 0, 0.5], "coherence": [0.5, 0.8, 0.99], "averages": 10},
      {"output": "belt_x", "input": "contact_x",
       "re": [1e-6, 2e-6, 3e-6], "im": [0, 0, 0], "sigma": [1e-7, 1e-7, 1e-7]}
    ]
  })");
}

// A block a condition at speed may hold: contact inputs, channel and
// coordinates outputs.
Json ValidAtSpeed() {
  return Json::parse(R"({
    "inputs": [{"name": "lug_x", "contact": "F_x"}, {"name": "lug_y", "contact": "F_y"}],
    "outputs": [{"name": "fx", "channel": "axle_force_x"},
                {"name": "belt_z", "coordinates": {"z_b": 1.0}, "quantity": "velocity"}],
    "frequencies_hz": [40, 80],
    "functions": [{"output": "fx", "input": "lug_x", "re": [1, 2], "im": [0, 1],
                   "sigma": [0.1, 0.1]}]
  })");
}

struct ReadOutcome {
  bool ok = false;
  Frf frf;
  LoadError error;
};

// `block` read as the frf of condition 0 at `speed`: the archive, then ReadFrf.
ReadOutcome Read(const Json& block, double speed = 0) {
  ReadOutcome o;
  o.error.file = kFile;
  FrfFields fields;
  std::string why;
  if (!JsonReader::FromJson(block, kBlock, &fields, &why)) {
    SetArchiveError(why, &o.error);
    return o;
  }
  o.ok = ReadFrf(fields, speed, kFile, kBlock, &o.frf, &o.error);
  return o;
}

// As a dataset writer writes it (datasets/dataset_writer.cc's dump).
std::string Written(const Frf& frf) {
  return JsonWriter::ToJson(FieldsOf(frf)).dump(2, ' ', false, Json::error_handler_t::replace);
}

void ExpectCombination(const DofCombination& got, const DofCombination& want) {
  ASSERT_EQ(got.size(), want.size());
  for (const auto& [dof, v] : want) {
    ASSERT_TRUE(got.count(dof)) << DofName(dof);
    EXPECT_NEAR(got.at(dof), v, 1e-15) << DofName(dof);
  }
}

TEST(FrfTest, AHandWrittenBlockOfContractSection9Reads) {
  const ReadOutcome o = Read(Valid());
  ASSERT_TRUE(o.ok) << o.error.OneLine();
  const Frf& f = o.frf;
  ASSERT_EQ(f.inputs.size(), 5u);
  ASSERT_EQ(f.outputs.size(), 3u);
  EXPECT_EQ(f.frequencies_hz, (std::vector<double>{50, 60.5, 70}));
  // The contract's example: a tangential blow at the top of the tread drives x_b + 0.31 theta_b.
  ExpectCombination(f.inputs[0].coordinates, {{Dof::kXb, 1.0}, {Dof::kThetaB, 0.31}});
  // d = (3, 0, 4)/5, p = (0.1, 0.2, -0.3), by hand: gamma_b = 0.8 * 0.2 = 0.16,
  // theta_b = 0.8 * 0.1 + 0.6 * 0.3 = 0.26, psi_b = -0.6 * 0.2 = -0.12.
  ExpectCombination(f.inputs[1].coordinates, {{Dof::kXb, 0.6}, {Dof::kZb, 0.8},
                                              {Dof::kGammaB, 0.16}, {Dof::kThetaB, 0.26},
                                              {Dof::kPsiB, -0.12}});
  // On the rim, d = (0, 3, 4)/5, p = (0.2, 0.05, 0.1): theta_a = 0.8 * 0.2 = 0.16.
  ExpectCombination(f.inputs[2].coordinates,
                    {{Dof::kYa, 0.6}, {Dof::kZa, 0.8}, {Dof::kThetaA, 0.16}});
  ExpectCombination(f.inputs[3].coordinates, {{Dof::kXb, 1.0}, {Dof::kThetaB, 0.3}});
  EXPECT_FALSE(f.inputs[3].point);
  ASSERT_TRUE(f.inputs[4].contact);
  EXPECT_EQ(*f.inputs[4].contact, LugForce::kFx);
  EXPECT_TRUE(f.inputs[4].coordinates.empty());  // r_e0's: made at fit time
  // A vertical accelerometer at the top of the tread: z_b, and theta_b through p_x = 0 not at all.
  ExpectCombination(f.outputs[0].coordinates, {{Dof::kZb, 1.0}});
  EXPECT_EQ(f.outputs[0].quantity, FrfQuantity::kAcceleration);
  EXPECT_EQ(f.outputs[1].quantity, FrfQuantity::kDisplacement);
  ASSERT_TRUE(f.outputs[2].channel);
  EXPECT_EQ(*f.outputs[2].channel, AxleChannel::kForceX);
  ASSERT_EQ(f.functions.size(), 3u);
  EXPECT_EQ(f.functions[1].output, 2);
  EXPECT_EQ(f.functions[1].input, 0);
  EXPECT_EQ(f.functions[2].output, 1);
  EXPECT_EQ(f.functions[2].input, 4);
  EXPECT_EQ(f.functions[0].h[1], std::complex<double>(-0.2, 0.02));
  EXPECT_EQ(f.functions[0].sigma, (std::vector<double>{0.01, 0.02, 0.03}));
  EXPECT_FALSE(f.functions[0].coherence);
}

// A point's combination is d . u(p), u the rigid motion of the body at p,
// computed here from the cross product of contract §9 (not its expansion).
TEST(FrfTest, APointsCombinationIsTheRigidMotionOfThePointAlongItsDirection) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    FrfPoint point;
    point.on = trial % 2 ? FrfBody::kRim : FrfBody::kBelt;
    point.point_m = {0.4 * u(rng), 0.2 * u(rng), 0.4 * u(rng)};
    point.direction = {u(rng), u(rng), u(rng)};
    double q[kNumDofs];  // a displacement of every coordinate
    for (double& v : q) v = u(rng);
    auto at = [&](Dof d) { return q[static_cast<int>(d)]; };
    const Eigen::Vector3d p(point.point_m.data()), d(point.direction.data());
    Eigen::Vector3d motion;
    if (point.on == FrfBody::kBelt) {
      motion = Eigen::Vector3d(at(Dof::kXb), at(Dof::kYb), at(Dof::kZb)) +
               Eigen::Vector3d(at(Dof::kGammaB), -at(Dof::kThetaB), at(Dof::kPsiB)).cross(p);
    } else {
      motion = Eigen::Vector3d(at(Dof::kXa), at(Dof::kYa), at(Dof::kZa)) +
               Eigen::Vector3d(0, -at(Dof::kThetaA), 0).cross(p);
    }
    double combined = 0;
    for (const auto& [dof, c] : PointCombination(point)) combined += c * at(dof);
    EXPECT_NEAR(combined, d.normalized().dot(motion), 1e-14) << trial;
  }
}

// At the contact point (z down: p_z = r > 0) a point force has §8's contact
// force's generalised forces: F_x -> x_b: 1, theta_b: -r_e0; F_y at the trail
// (p_x = -t_0) -> y_b: 1, gamma_b: -r_l0, psi_b: -t_0; F_z -> z_b alone.
TEST(FrfTest, APointForceAtTheContactHasSection8sGeneralisedForces) {
  const double r_e0 = 0.3, r_l0 = 0.29, t_0 = 0.02;
  ExpectCombination(PointCombination({FrfBody::kBelt, {0, 0, r_e0}, {2, 0, 0}}),
                    {{Dof::kXb, 1}, {Dof::kThetaB, -r_e0}});
  ExpectCombination(PointCombination({FrfBody::kBelt, {-t_0, 0, r_l0}, {0, 1, 0}}),
                    {{Dof::kYb, 1}, {Dof::kGammaB, -r_l0}, {Dof::kPsiB, -t_0}});
  ExpectCombination(PointCombination({FrfBody::kBelt, {0, 0, r_e0}, {0, 0, 1}}),
                    {{Dof::kZb, 1}});
}

// Bendat & Piersol (Random Data, single-input gain estimates): the normalised
// random error of |H1| from n averages at coherence g2 is
// sqrt(1 - g2) / (|g| sqrt(2 n)); contract §9 takes |H| times it as the
// standard error of re and of im each.
TEST(FrfTest, CoherenceGivesBendatAndPiersolsSigma) {
  const ReadOutcome o = Read(Valid());
  ASSERT_TRUE(o.ok) << o.error.OneLine();
  const FrfFunction& fn = o.frf.functions[1];
  const double h[][2] = {{3, 4}, {1, 0}, {-2, 0.5}};
  const double g2[] = {0.5, 0.8, 0.99};
  ASSERT_TRUE(fn.coherence);
  EXPECT_EQ(fn.coherence->averages, 10);
  ASSERT_EQ(fn.sigma.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const double magnitude = std::hypot(h[i][0], h[i][1]);
    const double expected =
        magnitude * std::sqrt(1 - g2[i]) / (std::sqrt(g2[i]) * std::sqrt(2.0 * 10));
    EXPECT_NEAR(fn.sigma[i], expected, 1e-15 * magnitude) << i;
  }
  // By hand: |H| = 5, g2 = 0.5, n = 10: 5 sqrt(0.5 / 10) = 5 sqrt(0.05).
  EXPECT_NEAR(fn.sigma[0], 1.118033988749895, 1e-14);
  EXPECT_DOUBLE_EQ(CoherenceSigma({3, 4}, 0.5, 2), 2.5);  // 5 sqrt(0.5 / 2)
}

// One refused block: the change to Valid(), the field the error names and a
// fragment of its message.
struct Refused {
  const char* what;
  std::function<void(Json&)> change;
  const char* field;
  const char* message;
};

void ExpectRefused(const Refused& c, const Json& valid, double speed) {
  Json j = valid;
  c.change(j);
  const ReadOutcome o = Read(j, speed);
  ASSERT_FALSE(o.ok) << c.what;
  const std::string line = o.error.OneLine();
  EXPECT_EQ(o.error.field, std::string(kBlock) + (*c.field ? "." : "") + c.field)
      << c.what << ": " << line;
  EXPECT_NE(o.error.message.find(c.message), std::string::npos) << c.what << ": " << line;
  EXPECT_EQ(line.find('\n'), std::string::npos) << c.what;
  EXPECT_EQ(line.rfind(std::string(kFile) + ": " + kBlock, 0), 0u) << c.what << ": " << line;
}

const Refused kInputsAndOutputs[] = {
    {"no inputs", [](Json& j) { j["inputs"] = Json::array(); }, "inputs", "non-empty"},
    {"no outputs", [](Json& j) { j["outputs"] = Json::array(); }, "outputs", "non-empty"},
    {"input name empty", [](Json& j) { j["inputs"][1]["name"] = ""; }, "inputs[1].name",
     "must not be empty"},
    {"input name twice", [](Json& j) { j["inputs"][2]["name"] = "shaker"; }, "inputs[2].name",
     "input 'shaker' appears twice (conditions[0].frf.inputs[1])"},
    {"output name twice", [](Json& j) { j["outputs"][2]["name"] = "acc_top"; },
     "outputs[2].name", "appears twice"},
    {"input of no kind", [](Json& j) { j["inputs"][3].erase("coordinates"); }, "inputs[3]",
     "gives none of"},
    {"point and contact", [](Json& j) { j["inputs"][0]["contact"] = "F_z"; },
     "inputs[0].contact", "not with on"},
    {"contact and coordinates", [](Json& j) { j["inputs"][4]["coordinates"] = {{"z_b", 1.0}}; },
     "inputs[4].coordinates", "not with contact"},
    {"point without direction", [](Json& j) { j["inputs"][0].erase("direction"); },
     "inputs[0].direction", "missing"},
    {"point without on", [](Json& j) { j["outputs"][0].erase("on"); }, "outputs[0].on",
     "missing"},
    {"point of two numbers", [](Json& j) { j["inputs"][0]["point_m"] = {0.0, 0.3}; },
     "inputs[0].point_m", "three numbers"},
    {"point not finite", [](Json& j) { j["inputs"][1]["point_m"][2] = nullptr; },
     "inputs[1].point_m[2]", "must be a number"},
    {"direction zero", [](Json& j) { j["inputs"][2]["direction"] = {0.0, 0.0, 0.0}; },
     "inputs[2].direction", "must not be zero"},
    {"point so far out that its coefficients overflow",
     [](Json& j) {
       j["inputs"][1]["point_m"] = {0.0, 1.7e308, 1.7e308};
       j["inputs"][1]["direction"] = {0.0, 1.0, -1.0};
     },
     "inputs[1].point_m", "overflow"},
    {"direction not finite", [](Json& j) { j["outputs"][0]["direction"][0] = nullptr; },
     "outputs[0].direction[0]", "must be a number"},
    {"unknown body", [](Json& j) { j["inputs"][0]["on"] = "tread"; }, "inputs[0].on",
     "unknown name 'tread' (expected belt or rim)"},
    {"unknown contact force", [](Json& j) { j["inputs"][4]["contact"] = "F_q"; },
     "inputs[4].contact", "unknown name 'F_q' (expected F_x, F_z or F_y)"},
    {"unknown coordinate", [](Json& j) { j["inputs"][3]["coordinates"]["x_c"] = 1.0; },
     "inputs[3].coordinates.x_c", "unknown degree of freedom 'x_c' (did you mean 'x_b'?"},
    {"coordinates empty", [](Json& j) { j["outputs"][1]["coordinates"] = Json::object(); },
     "outputs[1].coordinates", "non-empty object"},
    {"coordinates all zero", [](Json& j) { j["inputs"][3]["coordinates"] = {{"x_b", 0.0}}; },
     "inputs[3].coordinates", "all coefficients are zero"},
    {"coordinate not finite", [](Json& j) { j["outputs"][1]["coordinates"]["x_b"] = nullptr; },
     "outputs[1].coordinates.x_b", "must be a number"},
    {"motion without quantity", [](Json& j) { j["outputs"][1].erase("quantity"); },
     "outputs[1].quantity", "missing"},
    {"unknown quantity", [](Json& j) { j["outputs"][0]["quantity"] = "jerk"; },
     "outputs[0].quantity", "unknown name 'jerk'"},
    {"channel with quantity", [](Json& j) { j["outputs"][2]["quantity"] = "velocity"; },
     "outputs[2].quantity", "not with channel"},
    {"unknown channel", [](Json& j) { j["outputs"][2]["channel"] = "axle_force_w"; },
     "outputs[2].channel", "unknown name 'axle_force_w'"},
    {"point and channel", [](Json& j) { j["outputs"][0]["channel"] = "axle_force_z"; },
     "outputs[0].channel", "not with on"},
    {"unknown key in an output", [](Json& j) { j["outputs"][1]["unit"] = "m"; },
     "outputs[1].unit", "unknown key"},
};

const Refused kLinesAndFunctions[] = {
    {"no lines", [](Json& j) { j["frequencies_hz"] = Json::array(); }, "frequencies_hz",
     "non-empty"},
    {"line zero", [](Json& j) { j["frequencies_hz"][0] = 0.0; }, "frequencies_hz[0]",
     "must be positive"},
    {"line negative", [](Json& j) { j["frequencies_hz"][0] = -50.0; }, "frequencies_hz[0]",
     "must be positive"},
    {"line not finite", [](Json& j) { j["frequencies_hz"][1] = nullptr; }, "frequencies_hz[1]",
     "must be a number"},
    {"line repeated", [](Json& j) { j["frequencies_hz"][2] = 60.5; }, "frequencies_hz[2]",
     "strictly increasing"},
    {"lines decreasing", [](Json& j) { j["frequencies_hz"][1] = 40.0; }, "frequencies_hz[1]",
     "strictly increasing"},
    {"no functions", [](Json& j) { j["functions"] = Json::array(); }, "functions", "non-empty"},
    {"unknown output", [](Json& j) { j["functions"][0]["output"] = "acc_tpo"; },
     "functions[0].output", "unknown output 'acc_tpo' (did you mean 'acc_top'?"},
    {"unknown input", [](Json& j) { j["functions"][1]["input"] = "hamer_top"; },
     "functions[1].input", "unknown input 'hamer_top' (did you mean 'hammer_top'?"},
    {"pair twice", [](Json& j) { j["functions"].push_back(j["functions"][0]); }, "functions[3]",
     "as conditions[0].frf.functions[0] does: a pair is given at most once"},
    {"re short", [](Json& j) { j["functions"][0]["re"].erase(2); }, "functions[0].re",
     "has 2 values for 3 frequency lines"},
    {"im long", [](Json& j) { j["functions"][2]["im"].push_back(0.0); }, "functions[2].im",
     "has 4 values for 3"},
    {"im not finite", [](Json& j) { j["functions"][0]["im"][1] = nullptr; },
     "functions[0].im[1]", "must be a number"},
    {"sigma short", [](Json& j) { j["functions"][0]["sigma"].erase(0); }, "functions[0].sigma",
     "has 2 values"},
    {"sigma zero", [](Json& j) { j["functions"][0]["sigma"][1] = 0.0; }, "functions[0].sigma[1]",
     "must be positive"},
    {"sigma negative", [](Json& j) { j["functions"][2]["sigma"][2] = -1e-7; },
     "functions[2].sigma[2]", "must be positive"},
    {"sigma not finite", [](Json& j) { j["functions"][2]["sigma"][0] = nullptr; },
     "functions[2].sigma[0]", "must be a number"},
    {"sigma and coherence", [](Json& j) { j["functions"][0]["coherence"] = {0.5, 0.5, 0.5}; },
     "functions[0].coherence", "not with sigma"},
    {"sigma and averages", [](Json& j) { j["functions"][0]["averages"] = 4; },
     "functions[0].averages", "not with sigma"},
    {"no noise", [](Json& j) { j["functions"][0].erase("sigma"); }, "functions[0].sigma",
     "missing"},
    {"coherence without averages", [](Json& j) { j["functions"][1].erase("averages"); },
     "functions[1].averages", "missing"},
    {"averages zero", [](Json& j) { j["functions"][1]["averages"] = 0; }, "functions[1].averages",
     "must be at least 1"},
    {"averages not whole", [](Json& j) { j["functions"][1]["averages"] = 2.5; },
     "functions[1].averages", "whole number"},
    {"coherence one", [](Json& j) { j["functions"][1]["coherence"][2] = 1.0; },
     "functions[1].coherence[2]", "must lie in (0, 1)"},
    {"coherence zero", [](Json& j) { j["functions"][1]["coherence"][0] = 0.0; },
     "functions[1].coherence[0]", "must lie in (0, 1)"},
    {"coherence above one", [](Json& j) { j["functions"][1]["coherence"][1] = 1.2; },
     "functions[1].coherence[1]", "must lie in (0, 1)"},
    {"coherence short", [](Json& j) { j["functions"][1]["coherence"].erase(1); },
     "functions[1].coherence", "has 2 values"},
    {"coherence where H is zero",
     [](Json& j) {
       j["functions"][1]["re"][1] = 0.0;
       j["functions"][1]["im"][1] = 0.0;
     },
     "functions[1].coherence[1]", "gives sigma 0"},
};

TEST(FrfTest, EachRuleRefusesItsBreachNamingTheField) {
  for (const Refused& c : kInputsAndOutputs) ExpectRefused(c, Valid(), 0);
  for (const Refused& c : kLinesAndFunctions) ExpectRefused(c, Valid(), 0);
}

TEST(FrfTest, AtSpeedOnlyContactInputsAndChannelOrCoordinatesOutputsRead) {
  const ReadOutcome o = Read(ValidAtSpeed(), 8.0);
  ASSERT_TRUE(o.ok) << o.error.OneLine();
  EXPECT_EQ(o.frf.outputs[1].quantity, FrfQuantity::kVelocity);
  const Refused cases[] = {
      {"point input at speed",
       [](Json& j) { j["inputs"][0] = Valid()["inputs"][0]; }, "inputs[0].on",
       "input 'hammer_top' is a point force: at speed_m_s 8 the tread and the rim turn"},
      {"coordinates input at speed",
       [](Json& j) { j["inputs"][1] = Valid()["inputs"][3]; }, "inputs[1].coordinates",
       "input 'drive' is given as coordinates: a condition at speed takes contact inputs only"},
      {"point output at speed",
       [](Json& j) { j["outputs"][1] = Valid()["outputs"][0]; }, "outputs[1].on",
       "output 'acc_top' is a point motion: at speed_m_s 8"},
  };
  for (const Refused& c : cases) ExpectRefused(c, ValidAtSpeed(), 8.0);
  // The same block standing reads: the rule is the speed's.
  Json standing = ValidAtSpeed();
  standing["inputs"].push_back(Valid()["inputs"][0]);
  standing["inputs"].push_back(Valid()["inputs"][3]);
  standing["outputs"].push_back(Valid()["outputs"][0]);
  const ReadOutcome read = Read(standing, 0);
  EXPECT_TRUE(read.ok) << read.error.OneLine();
  ASSERT_FALSE(Read(standing, 8.0).ok);
}

TEST(FrfTest, WrittenReadAndWrittenAgainGivesTheSameBytes) {
  const ReadOutcome first = Read(Valid());
  ASSERT_TRUE(first.ok) << first.error.OneLine();
  const std::string written = Written(first.frf);
  const ReadOutcome again = Read(Json::parse(written));
  ASSERT_TRUE(again.ok) << again.error.OneLine();
  EXPECT_EQ(Written(again.frf), written);
  // As given: the direction not normalised, the noise as coherence and averages.
  const Json j = Json::parse(written);
  EXPECT_EQ(j["inputs"][1]["direction"], Json::parse("[3.0, 0.0, 4.0]"));
  EXPECT_FALSE(j["functions"][1].contains("sigma"));
  EXPECT_EQ(j["functions"][1]["averages"], 10);
  EXPECT_EQ(j["inputs"][3]["coordinates"], Json::parse(R"({"theta_b": 0.3, "x_b": 1.0})"));
  EXPECT_EQ(j["outputs"][2], Json::parse(R"({"name": "axle_x", "channel": "axle_force_x"})"));
}

// Values of every size and sign, subnormal ones included, come back bit for
// bit and write the same bytes.
TEST(FrfTest, EveryDoubleWrittenReadsBackExactly) {
  std::mt19937_64 rng(35);
  std::uniform_real_distribution<double> mantissa(-1, 1), exponent(-300, 300), unit(0.001, 0.999);
  auto any = [&] { return mantissa(rng) * std::pow(10.0, exponent(rng)); };
  Frf frf;
  frf.inputs = {{"in", FrfPoint{FrfBody::kRim, {any(), any(), any()}, {any(), 1, any()}}, {}, {}},
                {"gen", {}, {}, {{Dof::kYb, any()}, {Dof::kPsiB, any()}}}};
  frf.outputs = {{"out", {}, {}, {{Dof::kZa, any()}}, FrfQuantity::kVelocity}};
  for (int i = 1; i <= 200; ++i) frf.frequencies_hz.push_back(i * 0.37 + 1e-9 * unit(rng));
  FrfFunction with_sigma{0, 0, {}, {}, {}}, with_coherence{0, 1, {}, {}, FrfCoherence{{}, 7}};
  for (size_t i = 0; i < frf.frequencies_hz.size(); ++i) {
    with_sigma.h.emplace_back(any(), any());
    with_sigma.sigma.push_back(std::abs(any()) + std::numeric_limits<double>::denorm_min());
    with_coherence.h.emplace_back(mantissa(rng) + 2, any());
    with_coherence.coherence->gamma2.push_back(unit(rng));
  }
  with_sigma.h[0] = {std::numeric_limits<double>::denorm_min(), -0.0};
  frf.functions = {with_sigma, with_coherence};
  const std::string written = Written(frf);
  const ReadOutcome read = Read(Json::parse(written));
  ASSERT_TRUE(read.ok) << read.error.OneLine();
  EXPECT_EQ(Written(read.frf), written);
  EXPECT_EQ(read.frf.frequencies_hz, frf.frequencies_hz);
  EXPECT_EQ(read.frf.functions[0].h, frf.functions[0].h);
  EXPECT_EQ(read.frf.functions[0].sigma, frf.functions[0].sigma);
  EXPECT_EQ(read.frf.functions[1].coherence->gamma2, frf.functions[1].coherence->gamma2);
  EXPECT_EQ(read.frf.inputs[0].point->point_m, frf.inputs[0].point->point_m);
  EXPECT_EQ(read.frf.inputs[1].coordinates, frf.inputs[1].coordinates);
}

// The field list documents (report/schema.h) every key contract §9 names.
TEST(FrfTest, TheFieldListDocumentsEveryKeyOfContractSection9) {
  const std::string schema = InputSchema(FrfFields{});
  for (const char* line :
       {"`inputs[].name`: string", "`inputs[].on`: one of belt or rim (optional)",
        "`inputs[].point_m`: list of number (optional)", "`inputs[].direction`",
        "`inputs[].contact`: one of F_x, F_z or F_y (optional)", "`inputs[].coordinates`",
        "`outputs[].quantity`: one of displacement, velocity or acceleration (optional)",
        "`outputs[].channel`: one of axle_force_x, axle_force_z, axle_force_y, axle_moment_x "
        "or axle_moment_z (optional)",
        "`frequencies_hz`: list of number", "`functions[].output`: string",
        "`functions[].input`: string", "`functions[].re`", "`functions[].im`",
        "`functions[].sigma`", "`functions[].coherence`", "`functions[].averages`: integer"}) {
    EXPECT_NE(schema.find(line), std::string::npos) << line << "\n" << schema;
  }
}

}  // namespace
}  // namespace ringid
