// Campaigns: results independent of --jobs and of sharding; a bad dataset
// stops the campaign before anything is written.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "report/campaign_merge.h"
#include "tests/test_support.h"

namespace {

namespace fs = std::filesystem;
using ringid::testing::ReadFile;
using ringid::testing::Ringid;
using ringid::testing::RunResult;
using ringid::testing::Scratch;
using ringid::testing::SourcePath;

// Four withheld-effect datasets (one without an effect) in a fresh directory,
// at `speeds` (m/s, one condition each).
std::string MakeDatasets(const std::string& name, const std::string& speeds = "0") {
  const std::string dir = Scratch(name);
  fs::remove_all(dir);
  fs::create_directories(dir + "/data");
  const char* effects[] = {"", "lug_coupling", "hub_compliance", "sensor_mass"};
  for (int i = 0; i < 4; ++i) {
    std::string args = "simulate --parameters=" + SourcePath("datasets/paper/parameters.json") +
                       " --set=m_a=15 --seed=" + std::to_string(i + 1) + " --output=" + dir +
                       "/data/case" + std::to_string(i) + ".json --truth=" + dir + "/truth" +
                       std::to_string(i) + ".json --speeds=" + speeds;
    if (*effects[i]) args += std::string(" --effects=") + effects[i] + " --shift=0.05";
    const RunResult r = Ringid(args);
    EXPECT_EQ(r.status, 0) << r.err;
  }
  return dir;
}

// A report without its timings, which are all that may differ between runs.
// The report without its timings and the command line that made it.
nlohmann::json Untimed(nlohmann::json j) {
  if (j.is_object()) {
    for (const char* key : {"seconds", "seconds_per_fit", "command_line"}) j.erase(key);
    for (auto& [k, v] : j.items()) v = Untimed(v);
  } else if (j.is_array()) {
    for (auto& v : j) v = Untimed(v);
  }
  return j;
}

nlohmann::json Load(const std::string& path) { return nlohmann::json::parse(ReadFile(path)); }

// Rolling labels come from anchors each thread's model keeps for itself
// (docs/rolling.md §5); what the threads answer is what one thread does.
TEST(CampaignTest, RollingIdentificationDoesNotDependOnJobs) {
  const std::string dir = MakeDatasets("rolling_jobs", "0,10,20");
  for (const char* jobs : {"1", "2"}) {
    const RunResult r = Ringid("identify --derivatives=analytic --dataset=" + dir +
                               "/data --output_dir=" + dir + "/out" + jobs + " --jobs=" + jobs);
    ASSERT_EQ(r.status, 0) << r.err;
  }
  for (int i = 0; i < 4; ++i) {
    const std::string name = "/case" + std::to_string(i) + ".json";
    EXPECT_EQ(Untimed(Load(dir + "/out1" + name)), Untimed(Load(dir + "/out2" + name))) << name;
  }
}

TEST(CampaignTest, DiagnosisDoesNotDependOnJobs) {
  const std::string dir = MakeDatasets("jobs");
  for (const char* jobs : {"1", "2"}) {
    const RunResult r = Ringid("diagnose --derivatives=analytic --dataset=" + dir +
                               "/data --output_dir=" + dir + "/out" + jobs + " --jobs=" + jobs);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "") << "progress goes to a terminal only";
    // The text table says what its gap columns are, not only the page.
    EXPECT_NE(r.out.find("gap before"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("chi-square in excess of its degrees of freedom"), std::string::npos)
        << r.out;
  }
  for (int i = 0; i < 4; ++i) {
    const std::string name = "/case" + std::to_string(i) + ".json";
    EXPECT_EQ(Untimed(Load(dir + "/out1" + name)), Untimed(Load(dir + "/out2" + name))) << name;
  }
  const nlohmann::json summary = Load(dir + "/out2/campaign.json");
  ASSERT_EQ(summary["datasets"].size(), 4u);
  EXPECT_EQ(summary["jobs"], 2);
  // The synthetic truth: lug coupling at a 5 % shift is what the suite names.
  EXPECT_EQ(summary["datasets"][1]["verdict"], "lug_coupling");
  EXPECT_EQ(summary["datasets"][0]["verdict"], "none");
}

TEST(CampaignTest, ShardsPartitionTheDatasetsAndReproduceTheirReports) {
  const std::string dir = MakeDatasets("shards");
  ASSERT_EQ(Ringid("identify --dataset=" + dir + "/data --output_dir=" + dir + "/all").status, 0);
  std::multiset<std::string> seen;
  for (int i = 0; i < 3; ++i) {
    const std::string shard = std::to_string(i) + "/3";
    const RunResult r = Ringid("identify --dataset=" + dir + "/data --output_dir=" + dir +
                               "/sharded --shard=" + shard);
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json summary =
        Load(dir + "/sharded/campaign." + std::to_string(i) + "-of-3.json");
    for (const auto& row : summary["datasets"]) seen.insert(row["dataset"].get<std::string>());
  }
  ASSERT_EQ(seen.size(), 4u);
  EXPECT_EQ(std::set<std::string>(seen.begin(), seen.end()).size(), 4u) << "no dataset twice";
  for (int i = 0; i < 4; ++i) {
    const std::string name = "/case" + std::to_string(i) + ".json";
    EXPECT_EQ(Untimed(Load(dir + "/all" + name)), Untimed(Load(dir + "/sharded" + name)));
  }
}

TEST(CampaignTest, ABadDatasetStopsTheCampaignBeforeAnythingIsWritten) {
  const std::string dir = Scratch("bad");
  fs::remove_all(dir);
  fs::create_directories(dir + "/data");
  fs::copy_file(SourcePath("datasets/paper/table1.json"), dir + "/data/a.json");
  std::ofstream(dir + "/data/b.json") << "{\"format\": \"ringid-modal-dataset/1\", \"name\": 3}";
  const RunResult r =
      Ringid("identify --dataset=" + dir + "/data --output_dir=" + dir + "/out --jobs=2");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(dir + "/data/b.json"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("name"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

// File names need not be UTF-8; the reports that name them are still
// written whole (the byte becomes U+FFFD), never an uncaught exception.
TEST(CampaignTest, ANonUtf8FileNameIsReportedNotFatal) {
  const std::string dir = Scratch("utf8");
  fs::remove_all(dir);
  fs::create_directories(dir + "/data");
  const std::string name = dir + "/data/tire\xff";
  const RunResult sim = Ringid("simulate --parameters=" + SourcePath("datasets/paper/parameters.json") +
                               " --output='" + name + ".json' --truth='" + name + "-truth.txt'");
  ASSERT_EQ(sim.status, 0) << sim.err;
  const RunResult r = Ringid("identify --dataset=" + dir + "/data --output_dir=" + dir + "/out");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json summary = Load(dir + "/out/campaign.json");
  ASSERT_EQ(summary["datasets"].size(), 1u);
  EXPECT_NE(summary["datasets"][0]["dataset"].get<std::string>().find("tire\xef\xbf\xbd"),
            std::string::npos);
  EXPECT_TRUE(fs::exists(fs::path(dir + "/out/tire\xff.json")));
}

TEST(CampaignTest, BadCampaignFlagsAreRefused) {
  const std::string data = SourcePath("datasets/paper/table1.json");
  const std::string out = Scratch("flags-out");
  for (const std::string& flags :
       {"--shard=3/3", "--shard=1", "--shard=-1/2", "--jobs=0", "--output=x.json",
        "--save_parameters=p.json"}) {
    const RunResult r = Ringid("identify --dataset=" + data + " --output_dir=" + out + " " + flags);
    EXPECT_EQ(r.status, 2) << flags;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << flags << ": " << r.err;
  }
  EXPECT_EQ(Ringid("identify --dataset=/no/such/dir --output_dir=" + out).status, 2);
  EXPECT_FALSE(fs::exists(out));
}


// Without --keep_going a campaign stops on bad datasets, and names every one
// of them (the first five and how many more) in its one line, so that one
// run finds them all.
TEST(CampaignTest, EveryBadDatasetIsNamedBeforeTheCampaignStops) {
  const std::string dir = Scratch("all_bad");
  fs::remove_all(dir);
  fs::create_directories(dir + "/data");
  fs::copy_file(SourcePath("datasets/paper/table1.json"), dir + "/data/a.json");
  const char* bad[] = {"b", "c", "d", "e", "f", "g", "h"};
  for (const char* b : bad) {
    std::ofstream(dir + "/data/" + b + ".json") << "{\"format\": \"ringid-modal-dataset/1\", \"name\": 3}";
  }
  fs::create_directories(dir + "/two");
  fs::copy_file(dir + "/data/b.json", dir + "/two/b.json");
  fs::copy_file(dir + "/data/c.json", dir + "/two/c.json");
  fs::copy_file(dir + "/data/a.json", dir + "/two/a.json");
  RunResult r = Ringid("identify --dataset=" + dir + "/two --output_dir=" + dir + "/out");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("2 datasets cannot be used"), std::string::npos) << r.err;
  for (const char* b : {"b", "c"}) {
    EXPECT_NE(r.err.find(dir + "/two/" + b + ".json"), std::string::npos) << b << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(dir + "/out"));
  r = Ringid("diagnose --dataset=" + dir + "/data --output_dir=" + dir + "/out");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("7 datasets cannot be used"), std::string::npos) << r.err;
  for (const char* b : {"b", "c", "d", "e", "f"}) {
    EXPECT_NE(r.err.find(dir + "/data/" + b + ".json"), std::string::npos) << b << ": " << r.err;
  }
  EXPECT_EQ(r.err.find(dir + "/data/g.json"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("and 2 more"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}


// One naming of the summaries, which the campaign writes by and merge reads
// by: a shard's name read back is that shard, the whole campaign's is none.
TEST(CampaignTest, TheSummaryNamesAreMadeAndReadByOneRule) {
  EXPECT_EQ(ringid::CampaignSummaryName(0, 1), "campaign.json");
  EXPECT_EQ(ringid::CampaignSummaryName(2, 5), "campaign.2-of-5.json");
  for (const auto& [index, count] : {std::pair{0, 2}, {1, 2}, {7, 12}, {99, 100}}) {
    int i = -1, n = -1;
    ASSERT_TRUE(ringid::ParseShardSummaryName(ringid::CampaignSummaryName(index, count), &i, &n));
    EXPECT_EQ(i, index);
    EXPECT_EQ(n, count);
  }
  int i = 0, n = 0;
  EXPECT_FALSE(ringid::ParseShardSummaryName("campaign.json", &i, &n));
  EXPECT_FALSE(ringid::ParseShardSummaryName("campaign.1-of-2.json.tmp", &i, &n));
}

}  // namespace
