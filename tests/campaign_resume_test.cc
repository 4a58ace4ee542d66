// Campaigns that survive a cluster: a shard killed mid-way and restarted
// re-fits only what it had not finished, and the merged shards are the table
// of one serial run; --keep_going makes a bad dataset one failed row;
// --shard=slurm maps a job array onto shards; merge names what is missing.
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "apps/campaign.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

namespace fs = std::filesystem;
using testing::ReadFile;
using testing::Ringid;
using testing::RunResult;
using testing::Scratch;
using testing::SourcePath;

nlohmann::json Load(const std::string& path) { return nlohmann::json::parse(ReadFile(path)); }

// `n` standing datasets of the paper's tire (seeds 1..n) in DIR/data.
std::string MakeDatasets(const std::string& name, int n) {
  const std::string dir = Scratch(name);
  fs::remove_all(dir);
  fs::create_directories(dir + "/data");
  for (int i = 0; i < n; ++i) {
    char file[32];
    std::snprintf(file, sizeof file, "tire%02d", i);
    const RunResult r = Ringid("simulate --parameters=" + SourcePath("datasets/paper/parameters.json") +
                               " --seed=" + std::to_string(i + 1) + " --output=" + dir + "/data/" +
                               file + ".json --truth=" + dir + "/" + file + "_truth.json");
    EXPECT_EQ(r.status, 0) << r.err;
  }
  return dir;
}

// A summary's rows without what may differ between runs: timings, where the
// report was written, and whether it was kept from an earlier run.
nlohmann::json Rows(const nlohmann::json& summary) {
  nlohmann::json rows = summary["datasets"];
  for (auto& r : rows) {
    for (const char* key : {"seconds", "report_file", "resumed"}) r.erase(key);
  }
  return rows;
}

int Reports(const std::string& dir) {
  int n = 0;
  if (!fs::exists(dir)) return 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    n += e.path().filename().string().rfind("tire", 0) == 0 ? 1 : 0;
  }
  return n;
}

TEST(CampaignResumeTest, AKilledShardRefitsOnlyWhatItHadNotFinishedAndTheMergeIsTheSerialTable) {
  const std::string dir = MakeDatasets("resume", 40);
  const std::string fit = "identify --derivatives=analytic --starts=12 --dataset=" + dir + "/data ";
  RunResult r = Ringid(fit + "--output_dir=" + dir + "/serial");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string out = dir + "/sharded";
  for (int i : {0, 1, 3}) {
    r = Ringid(fit + "--output_dir=" + out + " --shard=" + std::to_string(i) + "/4");
    ASSERT_EQ(r.status, 0) << r.err;
  }
  // Shard 2 (10 datasets, one job): killed once some of its reports are written.
  const std::string err = Scratch("resume_err.txt");
  const int before_shards = Reports(out);  // shards 0, 1, 3: 30 reports
  const int pid = testing::StartRingid(fit + "--output_dir=" + out + " --shard=2/4", err);
  for (int wait = 0; wait < 600 && Reports(out) < before_shards + 3; ++wait) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(pid, SIGTERM);
  EXPECT_EQ(testing::WaitFor(pid), 128 + SIGTERM) << ReadFile(err);
  const int finished = Reports(out) - before_shards;
  ASSERT_GE(finished, 3);
  ASSERT_LT(finished, 10) << "the shard ended before it was killed";
  EXPECT_FALSE(fs::exists(out + "/campaign.2-of-4.json"));
  // The merge says what is missing, and writes nothing.
  r = Ringid("merge --output_dir=" + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("1 of 4 shard summaries missing: campaign.2-of-4.json"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(out + "/campaign.json"));
  // Restarted, it fits only what it had not finished.
  r = Ringid(fit + "--output_dir=" + out + " --shard=2/4");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json shard = Load(out + "/campaign.2-of-4.json");
  EXPECT_EQ(shard["resumed"].get<int>(), finished);
  int refitted = 0;
  for (const auto& row : shard["datasets"]) refitted += row.contains("resumed") ? 0 : 1;
  EXPECT_EQ(refitted, 10 - finished);
  r = Ringid("merge --output_dir=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json merged = Load(out + "/campaign.json"), serial = Load(dir + "/serial/campaign.json");
  EXPECT_EQ(Rows(merged), Rows(serial));
  EXPECT_EQ(merged["campaign_datasets"], serial["campaign_datasets"]);
  EXPECT_TRUE(fs::exists(out + "/campaign.html"));
  // Run once more: everything is kept, nothing refitted; --force refits all;
  // a shard of other options is not one campaign with the rest.
  r = Ringid(fit + "--output_dir=" + out + " --shard=0/4");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(Load(out + "/campaign.0-of-4.json")["resumed"].get<int>(), 10);
  r = Ringid(fit + "--output_dir=" + out + " --shard=0/4 --force");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(Load(out + "/campaign.0-of-4.json")["resumed"].get<int>(), 0);
  r = Ringid(fit + "--output_dir=" + out + " --shard=0/4 --relative_sigma=0.02");
  ASSERT_EQ(r.status, 0) << r.err;
  r = Ringid("merge --output_dir=" + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("its options differ(s)"), std::string::npos) << r.err;
}

TEST(CampaignResumeTest, AReportOfOtherBytesOrOptionsIsFittedAgain) {
  const std::string dir = MakeDatasets("resume_changed", 3);
  const std::string out = dir + "/out";
  const std::string fit = "identify --dataset=" + dir + "/data --output_dir=" + out;
  ASSERT_EQ(Ringid(fit).status, 0);
  EXPECT_EQ(Load(out + "/campaign.json")["resumed"].get<int>(), 0);
  ASSERT_EQ(Ringid(fit).status, 0);
  EXPECT_EQ(Load(out + "/campaign.json")["resumed"].get<int>(), 3);
  std::ofstream(dir + "/data/tire01.json", std::ios::app) << "\n";  // other bytes, same data
  ASSERT_EQ(Ringid(fit).status, 0);
  EXPECT_EQ(Load(out + "/campaign.json")["resumed"].get<int>(), 2);
  ASSERT_EQ(Ringid(fit + " --relative_sigma=0.02").status, 0);
  EXPECT_EQ(Load(out + "/campaign.json")["resumed"].get<int>(), 0);
  std::ofstream(out + "/tire00.json") << "{\"half a report";  // a kill cannot leave this; a user can
  ASSERT_EQ(Ringid(fit + " --relative_sigma=0.02").status, 0);
  EXPECT_EQ(Load(out + "/campaign.json")["resumed"].get<int>(), 2);
}

// Shards write into one directory: a report name two datasets of the whole
// list share, or one a summary has, is refused in every shard.
TEST(CampaignResumeTest, ReportNamesAreCheckedOverTheWholeListNotTheShard) {
  const std::string dir = MakeDatasets("names", 2);
  fs::create_directories(dir + "/other");
  fs::copy_file(dir + "/data/tire00.json", dir + "/other/tire00.json");
  const std::string list = dir + "/data/tire00.json," + dir + "/other/tire00.json";
  for (const char* shard : {"0/2", "1/2"}) {
    const RunResult r = Ringid("identify --dataset=" + list + " --output_dir=" + dir +
                               "/out --shard=" + shard);
    EXPECT_EQ(r.status, 2) << shard;
    EXPECT_NE(r.err.find("would overwrite that of"), std::string::npos) << r.err;
  }
  fs::copy_file(dir + "/data/tire01.json", dir + "/other/campaign.1-of-2.json");
  const RunResult r = Ringid("identify --dataset=" + dir + "/other --output_dir=" + dir + "/out");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("would overwrite a campaign summary"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

TEST(CampaignResumeTest, KeepGoingMakesABadDatasetOneFailedRowAndWithoutItNothingIsWritten) {
  const std::string dir = MakeDatasets("keep_going", 2);
  std::ofstream(dir + "/data/bad.json")
      << R"({"format": "ringid-modal-dataset/1", "name": "bad", "modes": [{"label": "vertical", "frequency_hz": "x"}]})";
  const std::string out = dir + "/out";
  RunResult r = Ringid("identify --dataset=" + dir + "/data --output_dir=" + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("bad.json: modes[0].frequency_hz"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  r = Ringid("identify --dataset=" + dir + "/data --output_dir=" + out + " --keep_going");
  EXPECT_EQ(r.status, 1) << r.err;
  const nlohmann::json summary = Load(out + "/campaign.json");
  EXPECT_EQ(summary["failed"].get<int>(), 1);
  ASSERT_EQ(summary["datasets"].size(), 3u);
  const nlohmann::json& bad = summary["datasets"][0];
  EXPECT_EQ(bad["dataset"], dir + "/data/bad.json");
  EXPECT_EQ(bad["field"], "modes[0].frequency_hz");
  EXPECT_EQ(bad["status"], "invalid_input");
  EXPECT_NE(bad["message"].get<std::string>().find("must be a number"), std::string::npos);
  EXPECT_FALSE(fs::exists(out + "/bad.json"));
  EXPECT_EQ(summary["datasets"][1]["status"], "success");
  // A mistake in a flag is the command's: exit 2 even with --keep_going.
  fs::remove_all(out);
  r = Ringid("identify --dataset=" + dir + "/data --output_dir=" + out + " --keep_going --fix=nonsense");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

// A campaign of thousands of datasets has a summary past the 4 MiB an input
// file may be; `ringid report` still renders it.
TEST(CampaignResumeTest, ASummaryOfThousandsOfRowsRendersAsAPage) {
  CampaignReport r;
  r.body.shard = "merged";
  for (int i = 0; i < 7000; ++i) {
    CampaignRow row;
    row.dataset = "data/tire" + std::to_string(i) + ".json";
    row.report_file = "out/tire" + std::to_string(i) + ".json";
    row.status = Status::Success("converged");
    row.converged = true;
    row.cost = 10 + i % 7;
    std::map<Param, double> values;
    for (int k = 0; k < 14; ++k) values[ParamAt(k + 6)] = 1e5 * (1 + 1e-3 * ((i * k) % 17));
    row.parameters = values;
    r.body.campaign_datasets.push_back(row.dataset);
    r.body.datasets.push_back(row);
  }
  const std::string json = Scratch("big_campaign.json"), html = Scratch("big_campaign.html");
  std::ofstream(json) << ReportText(r);
  ASSERT_GT(fs::file_size(json), 4u << 20);
  const RunResult out = Ringid("report --input=" + json + " --output=" + html);
  ASSERT_EQ(out.status, 0) << out.err;
  EXPECT_NE(ReadFile(html).find("data/tire6999.json"), std::string::npos);
}

TEST(CampaignResumeTest, ASlurmJobArrayMapsOntoShardsAndAnythingElseIsSaid) {
  const auto shard_of = [](std::map<std::string, std::string> env, Shard* s, std::string* e) {
    return SlurmShard(
        [&](const char* name) { return env.count(name) ? env.at(name).c_str() : nullptr; }, s, e);
  };
  const auto array = [](int id, int min, int max, int count, int step) {
    std::map<std::string, std::string> env = {{"SLURM_ARRAY_TASK_ID", std::to_string(id)},
                                              {"SLURM_ARRAY_TASK_MIN", std::to_string(min)},
                                              {"SLURM_ARRAY_TASK_MAX", std::to_string(max)},
                                              {"SLURM_ARRAY_TASK_COUNT", std::to_string(count)}};
    if (step) env["SLURM_ARRAY_TASK_STEP"] = std::to_string(step);
    return env;
  };
  Shard s;
  std::string e;
  ASSERT_TRUE(shard_of(array(0, 0, 3, 4, 0), &s, &e)) << e;  // --array=0-3
  EXPECT_EQ(s.index, 0);
  EXPECT_EQ(s.count, 4);
  ASSERT_TRUE(shard_of(array(7, 1, 9, 9, 1), &s, &e)) << e;  // --array=1-9%2 (the cap is not seen)
  EXPECT_EQ(s.index, 6);
  EXPECT_EQ(s.count, 9);
  ASSERT_TRUE(shard_of(array(5, 1, 9, 5, 2), &s, &e)) << e;  // --array=1-9:2
  EXPECT_EQ(s.index, 2);
  EXPECT_EQ(s.count, 5);
  EXPECT_FALSE(shard_of({}, &s, &e));
  EXPECT_NE(e.find("SLURM_ARRAY_TASK_ID is not set"), std::string::npos) << e;
  EXPECT_FALSE(shard_of(array(3, 1, 7, 3, 0), &s, &e));  // --array=1,3,7
  EXPECT_NE(e.find("not an evenly stepped range"), std::string::npos) << e;
  EXPECT_FALSE(shard_of(array(4, 1, 9, 5, 2), &s, &e));
  EXPECT_NE(e.find("task 4 is not in the array 1-9:2"), std::string::npos) << e;
  auto bad = array(1, 0, 3, 4, 0);
  bad["SLURM_ARRAY_TASK_ID"] = "one";
  EXPECT_FALSE(shard_of(bad, &s, &e));
  EXPECT_NE(e.find("is not a task number"), std::string::npos) << e;
  // Through the command line, outside an array: one line, exit 2.
  ::unsetenv("SLURM_ARRAY_TASK_ID");
  const RunResult r = Ringid("identify --dataset=" + SourcePath("datasets/paper/table1.json") +
                             " --output_dir=" + Scratch("slurm_out") + " --shard=slurm");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--shard=slurm: SLURM_ARRAY_TASK_ID is not set"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ringid
