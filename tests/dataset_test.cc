// The loader accepts the shipped datasets and refuses each kind of bad file
// with a message naming the field.
#include <fstream>

#include <unistd.h>

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

TEST(DatasetTest, RefusesEveryMalformedDataset) {
  const auto cases = testing::MalformedDatasets();
  EXPECT_GE(cases.size(), 169u);  // the README quotes this count
  for (const auto& bad : cases) {
    Dataset d;
    LoadError e;
    EXPECT_FALSE(ParseDataset(bad.text, "bad.json", &d, &e)) << bad.what;
    const std::string line = e.OneLine();
    EXPECT_EQ(line.rfind("bad.json: ", 0), 0u) << bad.what << ": " << line;
    EXPECT_NE(line.find(bad.field), std::string::npos) << bad.what << ": " << line;
    EXPECT_EQ(line.find('\n'), std::string::npos) << bad.what;
    EXPECT_FALSE(e.message.empty()) << bad.what;
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
  const std::string path = ::testing::TempDir() + "parameter_set_" +
                           std::to_string(::getpid()) + ".json";
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
      {R"({"parameters": {"m_b": 1, "m_b": 2}})", "parameters.m_b: duplicate key"},
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
