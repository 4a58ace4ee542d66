// The loader accepts the shipped datasets and refuses each kind of bad file
// with a message naming the field.
#include <fstream>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "datasets/dataset.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using nlohmann::json;

json Valid() {
  return json::parse(R"({
    "format": "ringid-modal-dataset/1", "name": "t",
    "known": {"m_b": 2.37}, "initial": {"k_bx": 3e5}, "ties": {"k_bz": "k_bx"},
    "modes": [{"label": "vertical", "plane": "in_plane", "frequency_hz": 74.5,
               "frequency_sigma_hz": 0.5, "damping_ratio": 0.08,
               "damping_sigma": 0.02, "shape": {"z_b": 1.0, "x_b": 0.01},
               "shape_sigma": 0.05}]})");
}

TEST(DatasetTest, ShippedDatasetsLoad) {
  for (const char* f : {"datasets/paper/table1.json",
                        "datasets/paper/inertia_recovery.json"}) {
    Dataset d;
    LoadError e;
    EXPECT_TRUE(LoadDataset(testing::SourcePath(f), &d, &e)) << e.OneLine();
    EXPECT_EQ(d.modes.size(), 7u);
  }
}

TEST(DatasetTest, ContractExampleLoadsAndRoundTrips) {
  Dataset d, again;
  LoadError e;
  ASSERT_TRUE(ParseDataset(Valid().dump(), "x.json", &d, &e)) << e.OneLine();
  ASSERT_TRUE(ParseDataset(DatasetToJson(d), "y.json", &again, &e)) << e.OneLine();
  EXPECT_EQ(again.modes[0].shape.size(), 2u);
  EXPECT_EQ(again.ties.at(Param::k_bz), Param::k_bx);
}

struct Bad {
  const char* what;
  void (*mutate)(json&);
  const char* field;  // must appear in the message
};

const Bad kBad[] = {
    {"missing format", [](json& j) { j.erase("format"); }, "format"},
    {"wrong format", [](json& j) { j["format"] = "other/2"; }, "format"},
    {"missing name", [](json& j) { j.erase("name"); }, "name"},
    {"name not string", [](json& j) { j["name"] = 3; }, "name"},
    {"unknown top key", [](json& j) { j["extra"] = 1; }, "extra"},
    {"missing modes", [](json& j) { j.erase("modes"); }, "modes"},
    {"empty modes", [](json& j) { j["modes"] = json::array(); }, "modes"},
    {"modes not array", [](json& j) { j["modes"] = 1; }, "modes"},
    {"missing label", [](json& j) { j["modes"][0].erase("label"); }, "modes[0].label"},
    {"unknown label", [](json& j) { j["modes"][0]["label"] = "breathing"; }, "modes[0].label"},
    {"hub label", [](json& j) { j["modes"][0]["label"] = "hub_vertical"; }, "modes[0].label"},
    {"plane contradicts", [](json& j) { j["modes"][0]["plane"] = "out_of_plane"; }, "modes[0].plane"},
    {"missing frequency", [](json& j) { j["modes"][0].erase("frequency_hz"); }, "modes[0].frequency_hz"},
    {"zero frequency", [](json& j) { j["modes"][0]["frequency_hz"] = 0; }, "modes[0].frequency_hz"},
    {"negative frequency", [](json& j) { j["modes"][0]["frequency_hz"] = -1; }, "modes[0].frequency_hz"},
    {"string frequency", [](json& j) { j["modes"][0]["frequency_hz"] = "74"; }, "modes[0].frequency_hz"},
    {"zero sigma", [](json& j) { j["modes"][0]["frequency_sigma_hz"] = 0; }, "frequency_sigma_hz"},
    {"damping above 1", [](json& j) { j["modes"][0]["damping_ratio"] = 1.5; }, "damping_ratio"},
    {"negative damping sigma", [](json& j) { j["modes"][0]["damping_sigma"] = -1; }, "damping_sigma"},
    {"damping sigma alone", [](json& j) { j["modes"][0].erase("damping_ratio"); }, "damping_sigma"},
    {"unknown dof", [](json& j) { j["modes"][0]["shape"]["q_b"] = 1; }, "shape.q_b"},
    {"zero shape", [](json& j) { j["modes"][0]["shape"] = {{"z_b", 0.0}}; }, "shape"},
    {"shape sigma alone", [](json& j) { j["modes"][0].erase("shape"); }, "shape_sigma"},
    {"unknown mode key", [](json& j) { j["modes"][0]["freq"] = 1; }, "modes[0].freq"},
    {"duplicate label", [](json& j) { j["modes"].push_back(j["modes"][0]); }, "modes[1].label"},
    {"unknown parameter", [](json& j) { j["known"]["k_qq"] = 1; }, "known.k_qq"},
    {"negative positive parameter", [](json& j) { j["known"]["m_b"] = -2; }, "known.m_b"},
    {"parameter not number", [](json& j) { j["initial"]["k_bx"] = true; }, "initial.k_bx"},
    {"known and initial", [](json& j) { j["initial"]["m_b"] = 2; }, "initial.m_b"},
    {"tie to self", [](json& j) { j["ties"]["k_bz"] = "k_bz"; }, "ties.k_bz"},
    {"tie to unknown", [](json& j) { j["ties"]["k_bz"] = "k_nope"; }, "ties.k_bz"},
    {"tie chain", [](json& j) { j["ties"]["k_btheta"] = "k_bz"; }, "ties.k_btheta"},
    {"tied and known", [](json& j) { j["known"]["k_bz"] = 1; }, "ties.k_bz"},
    {"tie not string", [](json& j) { j["ties"]["k_bz"] = 1; }, "ties.k_bz"},
};

TEST(DatasetTest, RefusesEachKindOfBadField) {
  for (const Bad& bad : kBad) {
    json j = Valid();
    bad.mutate(j);
    Dataset d;
    LoadError e;
    EXPECT_FALSE(ParseDataset(j.dump(), "bad.json", &d, &e)) << bad.what;
    EXPECT_NE(e.OneLine().find("bad.json"), std::string::npos) << bad.what;
    EXPECT_NE(e.OneLine().find(bad.field), std::string::npos)
        << bad.what << ": " << e.OneLine();
    EXPECT_EQ(e.OneLine().find('\n'), std::string::npos);
  }
}

TEST(DatasetTest, RefusesBrokenText) {
  const std::string texts[] = {
      "", "{", "[1,2]", "\x01\x02\xff", "{\"format\": NaN}",
      R"({"name": "a", "name": "b"})",
      std::string(40, '[') + std::string(40, ']'),
      Valid().dump().substr(0, 60),
      R"({"format":"ringid-modal-dataset/1","name":"t","modes":[{"label":"vertical","frequency_hz":1e999}]})"};
  for (const std::string& t : texts) {
    Dataset d;
    LoadError e;
    EXPECT_FALSE(ParseDataset(t, "broken.json", &d, &e)) << t;
    EXPECT_FALSE(e.message.empty());
  }
}

TEST(DatasetTest, MissingFileIsAnError) {
  Dataset d;
  LoadError e;
  EXPECT_FALSE(LoadDataset("/nonexistent/x.json", &d, &e));
  EXPECT_NE(e.OneLine().find("/nonexistent/x.json"), std::string::npos);
}

}  // namespace
}  // namespace ringid

namespace ringid {
namespace {

bool LoadText(const std::string& text, Parameters* p, LoadError* e) {
  const std::string path = ::testing::TempDir() + "parameter_set.json";
  std::ofstream(path) << text;
  return LoadParameterSet(path, p, e);
}

TEST(ParameterSetTest, ReadsTheShippedSetAndRefusesBadOnes) {
  Parameters p;
  LoadError e;
  ASSERT_TRUE(LoadParameterSet(testing::SourcePath("datasets/paper/parameters.json"), &p, &e))
      << e.OneLine();
  EXPECT_NEAR(p[Param::k_bx], 3.84e5, 1);
  const std::pair<std::string, std::string> bad[] = {
      {R"({"parameters": {"k_qq": 1}})", "parameters.k_qq"},
      {R"({"parameters": {"m_b": {"value": "2"}}})", "parameters.m_b.value"},
      {R"({"parameters": {"m_b": 1, "m_b": 2}})", "m_b"},
      {R"({"format": "x", "parameters": {}})", "format"},
      {R"({"parameters": [1]})", "parameters"},
      {"{\"parameters\":" + std::string(30, '[') + std::string(30, ']') + "}", "nested"},
  };
  for (const auto& [text, field] : bad) {
    EXPECT_FALSE(LoadText(text, &p, &e)) << text;
    EXPECT_NE(e.OneLine().find(field), std::string::npos) << e.OneLine();
  }
}

}  // namespace
}  // namespace ringid
