// simulate --obstacle (contract §11): the spec and the dataset's obstacle
// block read strictly, every bad field named with nothing written; the
// dataset simulate writes reads back exactly, starts from rest on a flat
// road until the cam reaches the cleat where the cam's geometry puts it, and
// carries noise of the stated size.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "datasets/dataset.h"
#include "datasets/obstacle.h"
#include "datasets/parameter_files.h"
#include "datasets/synthetic.h"
#include "model/time_response.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using json = nlohmann::ordered_json;

const std::string kCleatSpec = "datasets/examples/cleat_spec.json";
const std::string kCarTire = "datasets/examples/car_tire.json";

std::string Written(const json& j, const std::string& name) {
  const std::string path = testing::Scratch(name);
  std::ofstream(path) << j.dump(1);
  return path;
}

json Spec() { return json::parse(testing::ReadFile(testing::SourcePath(kCleatSpec))); }

// simulate of `spec` from the example tire into scratch files named after `tag`.
testing::RunResult Simulate(const std::string& spec, const std::string& tag,
                            const std::string& more = "") {
  return testing::Ringid("simulate --parameters=" + testing::SourcePath(kCarTire) +
                         " --obstacle=" + spec + " --output=" + testing::Scratch(tag + ".json") +
                         " --truth=" + testing::Scratch(tag + "_truth.json") + more);
}

TEST(ObstacleSpecTest, EveryBadSpecIsRefusedNamingItsFieldWithNothingWritten) {
  struct Case {
    std::string field;
    std::function<void(json*)> spoil;
  };
  const std::vector<Case> cases = {
      {"speeds_m_s[1]", [](json* j) { (*j)["speeds_m_s"][1] = 0; }},
      {"speeds_m_s[2]", [](json* j) { (*j)["speeds_m_s"][2] = 5; }},
      {"speeds_m_s", [](json* j) { (*j)["speeds_m_s"] = json::array(); }},
      {"profile.height_m", [](json* j) { (*j)["profile"].erase("height_m"); }},
      {"profile.length_m", [](json* j) { (*j)["profile"]["length_m"] = -1; }},
      {"profile.pitch_m", [](json* j) { (*j)["profile"]["pitch_m"] = 0.1; }},
      {"profile.x_m", [](json* j) { (*j)["profile"]["x_m"] = {0, 1}; }},
      {"profile.kind", [](json* j) { (*j)["profile"]["kind"] = "bump"; }},
      {"profile.angle_deg", [](json* j) { (*j)["profile"]["angle_deg"] = 10; }},
      {"profile.angle_deg",
       [](json* j) { (*j)["profile"]["width_m"] = 0.2, (*j)["profile"]["angle_deg"] = 90; }},
      {"profile.pattern",
       [](json* j) { (*j)["profile"]["width_m"] = 0.2, (*j)["profile"]["pattern"] = "alternating"; }},
      {"profile.lanes",
       [](json* j) {
         *j = Spec();
         (*j)["profile"] = {{"kind", "lugs"}, {"height_m", 0.02}, {"length_m", 0.03},
                            {"pitch_m", 0.1}, {"width_m", 0.3}, {"lanes", 5},
                            {"pattern", "alternating"}};
       }},
      {"profile.x_m",
       [](json* j) {
         (*j)["profile"] = {{"kind", "points"}, {"x_m", {0, 0.01, 0.005}}, {"h_m", {0, 0.01, 0}}};
       }},
      {"profile.x_m, h_m",
       [](json* j) { (*j)["profile"] = {{"kind", "points"}, {"x_m", {0, 0.01}}, {"h_m", {0}}}; }},
      {"sample_rate_hz", [](json* j) { (*j)["sample_rate_hz"] = 0; }},
      {"duration_s", [](json* j) { (*j)["duration_s"] = -1; }},
      {"duration_s", [](json* j) { (*j)["duration_s"] = 1e6; }},
      {"outputs[1]", [](json* j) { (*j)["outputs"][1] = "axle_force_w"; }},
      {"outputs[1]", [](json* j) { (*j)["outputs"][1] = "axle_force_x"; }},
      {"noise", [](json* j) { (*j)["noise"] = -0.1; }},
      {"extra", [](json* j) { (*j)["extra"] = 1; }},
      // Bounds that keep a run's work and numbers finite.
      {"profile.height_m", [](json* j) { (*j)["profile"]["height_m"] = 1e300; }},
      {"profile.lanes",
       [](json* j) { (*j)["profile"]["width_m"] = 0.2, (*j)["profile"]["lanes"] = 1000; }},
      {"position_at_t0_m", [](json* j) { (*j)["position_at_t0_m"] = -1e16; }},
      {"speeds_m_s[0]", [](json* j) { (*j)["speeds_m_s"][0] = 300; }},
      {"noise", [](json* j) { (*j)["noise"] = 5; }},
      {"profile",  // 2000 points 0.1 mm apart over 100 lanes: 7e8 pieces visited
       [](json* j) {
         json x = json::array(), h = json::array();
         for (int i = 0; i < 2000; ++i) x.push_back(1.5e-4 * i), h.push_back(i % 2 ? 0.005 : 0.0);
         (*j)["profile"] = {{"kind", "points"}, {"x_m", x}, {"h_m", h}, {"width_m", 0.2},
                            {"lanes", 100}};
       }},
      // What depends on the parameters: a cam reaching the cleat at t = 0,
      // the tire leaving the road, a channel that stays zero.
      {"position_at_t0_m", [](json* j) { (*j)["position_at_t0_m"] = -0.3; }},
      {"profile",  // a pothole 5 cm deep and 1 m long
       [](json* j) {
         (*j)["profile"]["height_m"] = -0.05, (*j)["profile"]["length_m"] = 1.0;
         (*j)["position_at_t0_m"] = -1.2;
       }},
      {"outputs", [](json* j) { (*j)["outputs"].push_back("axle_force_y"); }},
  };
  for (const Case& c : cases) {
    json j = Spec();
    c.spoil(&j);
    const std::string spec = Written(j, "bad_obstacle_spec.json");
    const testing::RunResult r = Simulate(spec, "refused");
    EXPECT_EQ(r.status, 2) << c.field << ": " << r.err;
    EXPECT_EQ(r.err.find(spec + ": " + c.field + ": "), 8u) << r.err;  // after "ringid: "
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(testing::Exists(testing::Scratch("refused.json"))) << c.field;
    EXPECT_FALSE(testing::Exists(testing::Scratch("refused_truth.json"))) << c.field;
  }
}

// predict --lug_profile reads its file as strictly, and refuses a speed of 0.
TEST(ObstacleSpecTest, ALugProfileIsReadStrictlyAndRollsOnlyAtSpeed) {
  const std::string lugs = testing::SourcePath("datasets/examples/cross_stitch_lugs.json");
  json bad = json::parse(testing::ReadFile(lugs));
  bad["profile"]["pitch_m"] = 1e-5;
  const std::string path = Written(bad, "tiny_pitch.json"), out = testing::Scratch("lugs.json");
  testing::RunResult r = testing::Ringid("predict --parameters=" + testing::SourcePath(kCarTire) +
                                         " --lug_profile=" + path + " --speeds=10 --output=" + out);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.find(path + ": profile.pitch_m: "), 8u) << r.err;
  bad = json::parse(testing::ReadFile(lugs));
  bad["profile"]["kind"] = "cleat";
  bad["profile"].erase("pitch_m");
  r = testing::Ringid("predict --parameters=" + testing::SourcePath(kCarTire) + " --lug_profile=" +
                      Written(bad, "a_cleat.json") + " --speeds=10 --output=" + out);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("profile.kind: must be lugs"), std::string::npos) << r.err;
  r = testing::Ringid("predict --parameters=" + testing::SourcePath(kCarTire) + " --lug_profile=" +
                      lugs + " --output=" + out);  // --speeds: 0 by default
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--lug_profile"), std::string::npos) << r.err;
  const std::string copy = Written(json::parse(testing::ReadFile(lugs)), "own.json");
  r = testing::Ringid("predict --parameters=" + testing::SourcePath(kCarTire) + " --lug_profile=" +
                      copy + " --speeds=10 --output=" + copy);  // over its own input
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(json::parse(testing::ReadFile(copy))["format"], "ringid-lug-profile/1");
  EXPECT_FALSE(testing::Exists(out));
}

TEST(ObstacleSpecTest, AParameterSetWithoutTheCamIsRefusedNamingWhatItLacks) {
  json p = json::parse(testing::ReadFile(testing::SourcePath(kCarTire)));
  p["parameters"].erase("c_e");
  const std::string params = Written(p, "no_cam.json"), out = testing::Scratch("nocam.json");
  const testing::RunResult r = testing::Ringid(
      "simulate --parameters=" + params + " --obstacle=" + testing::SourcePath(kCleatSpec) +
      " --output=" + out + " --truth=" + testing::Scratch("nocam_truth.json"));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("c_e"), std::string::npos) << r.err;
  EXPECT_FALSE(testing::Exists(out));
}

// The dataset's obstacle block (format 3), spoilt one field at a time.
TEST(ObstacleSpecTest, EveryBadObstacleBlockIsRefusedNamingItsField) {
  const testing::RunResult made = Simulate(testing::SourcePath(kCleatSpec), "block");
  ASSERT_EQ(made.status, 0) << made.err;
  const json good = json::parse(testing::ReadFile(testing::Scratch("block.json")));
  int at = -1;
  for (size_t c = 0; c < good["conditions"].size(); ++c) {
    if (good["conditions"][c].contains("obstacle")) at = static_cast<int>(c), c = 1000;
  }
  ASSERT_GE(at, 0);
  const std::string prefix = "conditions[" + std::to_string(at) + "]";
  struct Case {
    std::string field;
    std::function<void(json*)> spoil;
  };
  const std::vector<Case> cases = {
      {".speed_m_s", [](json* c) { (*c)["speed_m_s"] = -1; }},
      {".obstacle", [](json* c) { (*c)["speed_m_s"] = 0; }},
      {".obstacle.time_s[1]",
       [](json* c) {
         json& o = (*c)["obstacle"];
         const size_t n = o["samples"];
         o.erase("sample_rate_hz"), o.erase("samples");
         o["time_s"] = json::array();
         for (size_t k = 0; k < n; ++k) o["time_s"].push_back(k == 1 ? 0.0 : 0.001 * k);
       }},
      {".obstacle.time_s[0]",
       [](json* c) {
         json& o = (*c)["obstacle"];
         const size_t n = o["samples"];
         o.erase("sample_rate_hz"), o.erase("samples");
         o["time_s"] = json::array();
         for (size_t k = 0; k < n; ++k) o["time_s"].push_back(0.001 * k - 0.0005);
       }},
      {".obstacle.time_s", [](json* c) { (*c)["obstacle"]["time_s"] = {0, 1}; }},
      {".obstacle.samples", [](json* c) { (*c)["obstacle"].erase("samples"); }},
      {".obstacle.outputs.axle_force_q",
       [](json* c) { (*c)["obstacle"]["outputs"]["axle_force_q"] = (*c)["obstacle"]["outputs"]["axle_force_x"]; }},
      {".obstacle.outputs.axle_force_x.values",
       [](json* c) { (*c)["obstacle"]["outputs"]["axle_force_x"]["values"].erase(0); }},
      {".obstacle.outputs.axle_force_x.sigma",
       [](json* c) { (*c)["obstacle"]["outputs"]["axle_force_x"]["sigma"] = 0; }},
      {".obstacle.outputs.axle_force_x.sigma",
       [](json* c) { (*c)["obstacle"]["outputs"]["axle_force_x"]["sigma"] = {1, 2}; }},
      {".obstacle.outputs.axle_force_x.sigma",
       [](json* c) { (*c)["obstacle"]["outputs"]["axle_force_x"]["sigma"] = "1"; }},
      {".obstacle.outputs", [](json* c) { (*c)["obstacle"]["outputs"] = json::object(); }},
      {".obstacle.profile.kind", [](json* c) { (*c)["obstacle"]["profile"]["kind"] = 3; }},
  };
  for (const Case& c : cases) {
    json j = good;
    c.spoil(&j["conditions"][at]);
    const std::string path = Written(j, "bad_block.json");
    Dataset d;
    LoadError e;
    EXPECT_FALSE(LoadDataset(path, &d, &e)) << c.field;
    EXPECT_EQ(e.field.rfind(prefix + c.field, 0), 0u) << c.field << " -> " << e.OneLine();
  }
  // A format-2 dataset takes no obstacle block.
  json two = good;
  two["format"] = "ringid-modal-dataset/2";
  two["conditions"][at]["modes"] = json::array();
  Dataset d;
  LoadError e;
  EXPECT_FALSE(LoadDataset(Written(two, "two.json"), &d, &e));
  EXPECT_EQ(e.field, prefix + ".obstacle") << e.OneLine();
}

TEST(ObstacleSpecTest, SimulateWritesEachSpeedAsAConditionThatReadsBackExactly) {
  const testing::RunResult r = Simulate(testing::SourcePath(kCleatSpec), "cleat");
  ASSERT_EQ(r.status, 0) << r.err;
  Dataset d;
  LoadError e;
  ASSERT_TRUE(LoadDataset(testing::Scratch("cleat.json"), &d, &e)) << e.OneLine();
  EXPECT_EQ(DatasetToJson(d), testing::ReadFile(testing::Scratch("cleat.json")));
  std::vector<std::string> names;
  for (const Condition& c : d.conditions) {
    if (!c.obstacle) continue;
    names.push_back(c.name);
    EXPECT_EQ(c.obstacle->times_s.size(), 600u);
    EXPECT_EQ(c.obstacle->channels.size(), 2u);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"obstacle_5", "obstacle_10", "obstacle_15"}));
  EXPECT_EQ(d.conditions.front().name, "standing");  // --speeds' default beside them
  Truth truth;
  ASSERT_TRUE(LoadTruth(testing::Scratch("cleat_truth.json"), &truth, &e)) << e.OneLine();
  for (const char* cam : {"a_e", "b_e", "c_e", "l_s"}) {
    EXPECT_EQ(truth.parameters.count(cam), 1u) << cam;
    EXPECT_TRUE(d.known.count(*ParseParam(cam))) << cam;
  }
  // identify says it does not fit them, naming the condition.
  const testing::RunResult fit =
      testing::Ringid("identify --dataset=" + testing::Scratch("cleat.json") +
                      " --output=" + testing::Scratch("cleat_report.json"));
  EXPECT_EQ(fit.status, 2) << fit.err;
  EXPECT_NE(fit.err.find("obstacle_5"), std::string::npos) << fit.err;
  EXPECT_FALSE(testing::Exists(testing::Scratch("cleat_report.json")));
}

// Without noise, every channel is exactly 0 until the front cam rises: its
// bottom, b_e((1 - |s/a_e|^c_e)^(1/c_e) - 1) below its centre at s, clears
// the cleat's height h from d = a_e (1 - (1 - h/b_e)^c_e)^(1/c_e) on, so at
// X = -L/2 - l_s/2 - d (the cam's geometry, not the code's search; the held
// forces ramp over one travel step before it); with noise, (value -
// noise-free) / sigma has unit spread and sigma is the stated share of the
// peak-to-peak.
TEST(ObstacleSpecTest, TheResponseStartsWhenTheCamReachesTheCleatAndCarriesTheStatedNoise) {
  json quiet = Spec();
  quiet["noise"] = 0;
  ASSERT_EQ(Simulate(Written(quiet, "quiet_spec.json"), "quiet").status, 0);
  ASSERT_EQ(Simulate(testing::SourcePath(kCleatSpec), "noisy").status, 0);
  Dataset exact, noisy;
  LoadError e;
  ASSERT_TRUE(LoadDataset(testing::Scratch("quiet.json"), &exact, &e)) << e.OneLine();
  ASSERT_TRUE(LoadDataset(testing::Scratch("noisy.json"), &noisy, &e)) << e.OneLine();
  const Parameters car = ExampleCarTire();
  const double x0 = quiet["position_at_t0_m"], half = 0.5 * double(quiet["profile"]["length_m"]);
  const double h = quiet["profile"]["height_m"], a = car[Param::a_e], b = car[Param::b_e],
               ce = car[Param::c_e];
  const double d = a * std::pow(1 - std::pow(1 - h / b, ce), 1 / ce);
  const double onset = -half - 0.5 * car[Param::l_s] - d;
  double sum = 0;
  int n = 0;
  for (size_t c = 0; c < exact.conditions.size(); ++c) {
    if (!exact.conditions[c].obstacle) continue;
    const ObstacleTest& t = *exact.conditions[c].obstacle;
    const ObstacleTest& u = *noisy.conditions[c].obstacle;
    const double v = exact.conditions[c].speed_m_s, contact_s = (onset - x0) / v;
    for (size_t ch = 0; ch < t.channels.size(); ++ch) {
      const std::vector<double>& y = t.channels[ch].values;
      double lo = 1e300, hi = -1e300;
      for (size_t k = 0; k < y.size(); ++k) {
        const double tk = t.times_s[k];
        if (tk < contact_s - kTravelStep / v - 1e-9) EXPECT_EQ(y[k], 0.0) << exact.conditions[c].name << " " << tk;
        if (tk > contact_s + 2e-3) EXPECT_NE(y[k], 0.0) << exact.conditions[c].name << " " << tk;
        lo = std::min(lo, y[k]), hi = std::max(hi, y[k]);
        const double z = (u.channels[ch].values[k] - y[k]) / u.channels[ch].sigma[k];
        sum += z * z, ++n;
      }
      EXPECT_DOUBLE_EQ(u.channels[ch].sigma[0], 0.01 * (hi - lo));
      EXPECT_TRUE(u.channels[ch].one_sigma);
    }
  }
  ASSERT_EQ(n, 3 * 2 * 600);
  // chi2 over 3600 unit normals: sd of the mean square sqrt(2/3600) = 0.024.
  EXPECT_NEAR(sum / n, 1.0, 4 * std::sqrt(2.0 / n));
}

}  // namespace
}  // namespace ringid
