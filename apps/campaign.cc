#include "apps/campaign.h"

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <map>
#include <sstream>
#include <thread>

namespace ringid {

namespace fs = std::filesystem;

bool ParseShard(const std::string& text, Shard* shard, std::string* error) {
  std::istringstream in(text);
  char slash = 0;
  std::string rest;
  if (!(in >> shard->index >> slash >> shard->count) || slash != '/' || (in >> rest) ||
      shard->count < 1 || shard->index < 0 || shard->index >= shard->count) {
    *error = "--shard: must be I/N with 0 <= I < N, got '" + text + "'";
    return false;
  }
  return true;
}

bool ListDatasets(const std::string& list, const Shard& shard,
                  std::vector<std::string>* files, std::string* error) {
  std::vector<std::string> all;
  std::stringstream items(list);
  std::string path;
  while (std::getline(items, path, ',')) {
    if (path.empty()) continue;
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
      std::vector<std::string> in_dir;
      for (fs::directory_iterator it(path, ec), end; !ec && it != end; it.increment(ec)) {
        if (it->path().extension() == ".json" && it->is_regular_file(ec)) {
          in_dir.push_back(it->path().string());
        }
      }
      if (ec) {
        *error = path + ": cannot read directory: " + ec.message();
        return false;
      }
      std::sort(in_dir.begin(), in_dir.end());
      all.insert(all.end(), in_dir.begin(), in_dir.end());
    } else if (fs::exists(path, ec)) {
      all.push_back(path);
    } else {
      *error = path + ": no such file or directory";
      return false;
    }
  }
  if (all.empty()) {
    *error = "--dataset: no dataset listed in '" + list + "'";
    return false;
  }
  files->clear();
  for (size_t i = shard.index; i < all.size(); i += shard.count) files->push_back(all[i]);
  return true;
}

bool ReportNames(const std::vector<std::string>& files, const std::string& dir,
                 std::vector<std::string>* reports, std::string* error) {
  std::map<std::string, std::string> seen;
  reports->clear();
  for (const std::string& f : files) {
    const std::string stem = fs::path(f).stem().string();
    if (stem == "campaign" || seen.count(stem)) {
      *error = f + ": its report " + stem + ".json would overwrite " +
               (stem == "campaign" ? "the campaign summary" : "that of " + seen[stem]);
      return false;
    }
    seen[stem] = f;
    reports->push_back((fs::path(dir) / (stem + ".json")).string());
  }
  return true;
}

void ParallelFor(int n, int jobs, Progress* progress, const std::function<void(int)>& work) {
  std::atomic<int> next{0};
  auto worker = [&] {
    for (int i; (i = next++) < n;) {
      work(i);
      if (progress) progress->Add();
    }
  };
  std::vector<std::thread> threads;
  for (int t = 1; t < std::min(jobs, n); ++t) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
}

}  // namespace ringid
