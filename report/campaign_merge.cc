#include "report/campaign_merge.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace ringid {
namespace {

// A shard summary, read whole (no size cap: a 10,000-dataset campaign's is
// several MiB) and typed.
bool ReadSummary(const std::string& path, CampaignReport* report, std::string* error) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  if (!in) {
    *error = path + ": cannot read";
    return false;
  }
  const Json json = Json::parse(text.str(), nullptr, false);
  std::string why;
  if (json.is_discarded()) {
    *error = path + ": not valid JSON";
    return false;
  }
  if (!ReadReport(json, report, &why)) {
    *error = path + ": " + why;
    return false;
  }
  return true;
}

}  // namespace

std::string CampaignSummaryName(int index, int count) {
  const std::string stem = kCampaignSummaryStem;
  if (count == 1) return stem + ".json";
  return stem + "." + std::to_string(index) + "-of-" + std::to_string(count) + ".json";
}

bool ParseShardSummaryName(const std::string& file, int* index, int* count) {
  static const std::regex name(std::string(kCampaignSummaryStem) +
                               "\\.([0-9]{1,6})-of-([0-9]{1,6})\\.json");
  std::smatch m;
  if (!std::regex_match(file, m, name)) return false;
  *index = std::stoi(m[1]);
  *count = std::stoi(m[2]);
  return true;
}

bool MergeShards(const std::string& dir, CampaignReport* merged, std::string* error,
                 std::vector<std::string>* shard_paths) {
  std::map<int, std::string> paths;  // by shard index
  std::error_code ec;
  int count = 0;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string file = it->path().filename().string();
    int index = 0, of = 0;
    if (!ParseShardSummaryName(file, &index, &of)) continue;
    if (index >= of) {
      *error = dir + ": " + file + " names no shard (I/N needs 0 <= I < N)";
      return false;
    }
    if (count && of != count) {
      *error = dir + ": " + file + " is a shard of " + std::to_string(of) + ", " +
               paths.begin()->second + " of " + std::to_string(count) + ": not one campaign";
      return false;
    }
    count = of;
    if (paths.count(index)) {
      *error = dir + ": " + file + " and " + paths[index] + " are both shard " +
               std::to_string(index);
      return false;
    }
    paths[index] = it->path().string();
  }
  if (ec) {
    *error = dir + ": cannot read directory: " + ec.message();
    return false;
  }
  if (paths.empty()) {
    *error = dir + ": no shard summary (" + kCampaignSummaryStem + ".I-of-N.json) to merge";
    return false;
  }
  std::map<std::string, CampaignRow> rows;
  CampaignBody& body = merged->body;
  body = CampaignBody{};
  for (const auto& [index, path] : paths) {
    CampaignReport shard;
    if (!ReadSummary(path, &shard, error)) return false;
    const auto differs = [&, &path = path](const std::string& what) {  // clang: no binding captures
      *error = path + ": its " + what + " differ(s) from " + paths.begin()->second +
               "'s: not a shard of the same campaign";
      return false;
    };
    if (index == paths.begin()->first) {
      body.command = shard.body.command;
      body.campaign_datasets = shard.body.campaign_datasets;
      body.options = shard.body.options;
      body.jobs = shard.body.jobs;
    } else if (shard.body.command != body.command) {
      return differs("command");
    } else if (shard.body.campaign_datasets != body.campaign_datasets) {
      return differs("campaign_datasets");
    } else if (shard.body.options != body.options) {
      return differs("options");
    }
    if (shard.body.shard != std::to_string(index) + "/" + std::to_string(count)) {
      *error = path + ": says it is shard " + shard.body.shard + ", its name " +
               std::to_string(index) + "/" + std::to_string(count);
      return false;
    }
    body.seconds += shard.body.seconds;
    for (const CampaignRow& r : shard.body.datasets) {
      body.resumed += r.resumed.value_or(false) ? 1 : 0;
      body.failed += r.status.ok() ? 0 : 1;
      if (!rows.emplace(r.dataset, r).second) {
        *error = path + ": " + r.dataset + " is also in another shard";
        return false;
      }
    }
  }
  std::string missing;
  int n_missing = 0;
  for (int i = 0; i < count; ++i) {
    if (paths.count(i)) continue;
    missing += (n_missing++ ? ", " : "") + CampaignSummaryName(i, count);
  }
  if (n_missing) {
    *error = dir + ": " + std::to_string(n_missing) + " of " + std::to_string(count) +
             " shard summaries missing: " + missing + " (run those shards, then merge)";
    return false;
  }
  for (const std::string& d : body.campaign_datasets) {
    const auto it = rows.find(d);
    if (it == rows.end()) {
      *error = dir + ": no shard has a row for " + d;
      return false;
    }
    body.datasets.push_back(it->second);
  }
  if (rows.size() != body.datasets.size()) {
    *error = dir + ": a shard has a row for a dataset not in the campaign's list";
    return false;
  }
  body.shard = "merged";
  if (shard_paths) {
    shard_paths->clear();
    for (const auto& [index, path] : paths) shard_paths->push_back(path);
  }
  return true;
}

}  // namespace ringid
