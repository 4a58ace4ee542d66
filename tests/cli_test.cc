// The ringid tool end to end: reports, and the error contract (exit status,
// docs/conventions.md §6).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "apps/reports.h"
#include "tests/test_support.h"

namespace {

using ringid::testing::Exists;
using ringid::testing::ReadFile;
using ringid::testing::Ringid;
using ringid::testing::RunResult;
using ringid::testing::Scratch;

std::string Source(const std::string& f) { return ringid::testing::SourcePath(f); }

TEST(CliTest, IdentifyWritesTheContractReport) {
  const std::string out = Scratch("identify.json");
  std::remove(out.c_str());
  const RunResult r = Ringid("identify --dataset=" + Source("datasets/paper/table1.json") +
                       " --output=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(out);
  const nlohmann::json j = nlohmann::json::parse(in);
  for (const char* key : {"method", "converged", "cost", "evaluations", "seconds",
                          "parameters", "covariance", "modes"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["parameters"]["K_cx"]["identifiable"], "no");
  EXPECT_TRUE(j["parameters"]["K_cx"]["std"].is_null());
  EXPECT_EQ(j["covariance"]["rank"], 7);
  EXPECT_EQ(j["modes"].size(), 7u);
}

TEST(CliTest, PredictReproducesTable3Vertical) {
  const std::string out = Scratch("predict.json");
  const RunResult r = Ringid("predict --parameters=" + Source("datasets/paper/parameters.json") +
                       " --output=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(out);
  const nlohmann::json j = nlohmann::json::parse(in);
  bool found = false;
  for (const auto& m : j["modes"]) {
    if (m["label"] == "vertical") {
      found = true;
      EXPECT_NEAR(m["model_hz"].get<double>(), 72.1, 0.1);
    }
  }
  EXPECT_TRUE(found);
}

TEST(CliTest, BadInputIsOneLineExitTwoAndNoReport) {
  const std::string dir = Scratch("");
  const std::string bad = dir + "bad_dataset.json";
  std::ofstream(bad) << R"({"format":"ringid-modal-dataset/1","name":"x",)"
                        R"("modes":[{"label":"vertical","frequency_hz":-3}]})";
  const std::string partial = dir + "partial_parameters.json";
  std::ofstream(partial) << R"({"format":"ringid-parameters/1","parameters":{"m_b":{"value":2.4}}})";
  const std::string out = dir + "never_written.json";
  std::remove(out.c_str());
  const std::string cases[] = {
      "identify --dataset=" + bad + " --output=" + out,
      "identify --dataset=/nonexistent.json --output=" + out,
      "identify --dataset=" + Source("datasets/paper/table1.json") + " --bogus=1 --output=" + out,
      "identify --dataset=" + Source("datasets/paper/table1.json") + " --starts=abc --output=" + out,
      "identify --dataset=" + Source("datasets/paper/table1.json") + " --method=newton --output=" + out,
      "predict --parameters=" + bad + " --output=" + out,
      "predict --dataset=" + bad + " --output=" + out,
      "predict --parameters=" + partial + " --output=" + out,
      "frobnicate",
  };
  for (const std::string& c : cases) {
    const RunResult r = Ringid(c);
    EXPECT_EQ(r.status, 2) << c;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c << ": " << r.err;
    EXPECT_FALSE(Exists(out)) << c;
  }
  const RunResult r = Ringid("identify --dataset=" + bad);
  EXPECT_NE(r.err.find("bad_dataset.json"), std::string::npos);
  EXPECT_NE(r.err.find("modes[0].frequency_hz"), std::string::npos);
}

TEST(CliTest, EveryMalformedDatasetIsRefusedByEveryCommand) {
  const std::string dir = Scratch("");
  const std::string out = dir + "malformed_report.json";
  int n = 0;
  for (const auto& bad : ringid::testing::MalformedDatasets()) {
    const std::string file = dir + "malformed_" + std::to_string(n++) + ".json";
    std::ofstream(file, std::ios::binary) << bad.text;
    for (const std::string command : {"identify", "predict"}) {
      std::remove(out.c_str());
      const RunResult r = Ringid(command + " --dataset=" + file + " --output=" + out);
      EXPECT_EQ(r.status, 2) << bad.what << " (" << command << ")";
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << bad.what << ": " << r.err;
      EXPECT_NE(r.err.find(file), std::string::npos) << bad.what << ": " << r.err;
      EXPECT_NE(r.err.find(bad.field), std::string::npos) << bad.what << ": " << r.err;
      EXPECT_FALSE(Exists(out)) << bad.what;
    }
    std::remove(file.c_str());
  }
}

TEST(CliTest, AnInterruptedRunLeavesNoReport) {
  const std::string out = Scratch("interrupted.json");
  std::remove(out.c_str());
  // 100000 starts take minutes; SIGINT arrives after half a second.
  const std::string cmd = "timeout -s INT 0.5 " + std::string(RINGID_BINARY) +
                          " identify --starts=100000 --dataset=" +
                          Source("datasets/paper/table1.json") + " --output=" + out +
                          " > /dev/null 2>&1";
  const int raw = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 124);  // timeout: the command was interrupted
  EXPECT_FALSE(Exists(out));
  EXPECT_FALSE(Exists(out + ".ringid-probe"));
}

TEST(CliTest, UnwritableOutputIsRefusedBeforeTheRun) {
  const RunResult r = Ringid("identify --dataset=" + Source("datasets/paper/table1.json") +
                       " --output=/nonexistent-dir/report.json");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("/nonexistent-dir/report.json"), std::string::npos);
}

// A dataset and its truth (or a report and its figures) appear together or
// not at all: a failure on the second file leaves no first file behind.
TEST(CliTest, SeveralFilesAreWrittenAllOrNone) {
  const std::string dir = Scratch("all_or_none");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string first = dir + "/dataset.json";
  const std::string second = dir + "/missing-dir/truth.json";
  std::string error;
  EXPECT_FALSE(ringid::WriteFilesAtomically({{first, "a"}, {second, "b"}}, &error));
  EXPECT_NE(error.find(second), std::string::npos) << error;
  EXPECT_FALSE(Exists(first));
  EXPECT_TRUE(std::filesystem::is_empty(dir)) << "a temporary file was left behind";

  const std::string other = dir + "/truth.json";
  ASSERT_TRUE(ringid::WriteFilesAtomically({{first, "a"}, {other, "b"}}, &error)) << error;
  EXPECT_EQ(ReadFile(first), "a");
  EXPECT_EQ(ReadFile(other), "b");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator()), 2);

  // One path for two outputs (--output equal to --save_parameters): refused,
  // and the file already there is left as it was.
  EXPECT_FALSE(ringid::WriteFilesAtomically({{first, "c"}, {dir + "/./dataset.json", "d"}}, &error));
  EXPECT_NE(error.find("named for two outputs"), std::string::npos) << error;
  EXPECT_EQ(ReadFile(first), "a");
}

}  // namespace
