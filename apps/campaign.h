// Campaigns: many datasets, one report each and a summary, on several
// threads or split into shards across machines with no coordination.
#ifndef RINGID_APPS_CAMPAIGN_H_
#define RINGID_APPS_CAMPAIGN_H_

#include <functional>
#include <string>
#include <vector>

#include "apps/progress.h"

namespace ringid {

// --shard=I/N: the datasets at positions I, I+N, I+2N, ... (0 <= I < N).
struct Shard {
  int index = 0;
  int count = 1;
};
bool ParseShard(const std::string& text, Shard* shard, std::string* error);

// "FILE,DIR,...": a directory stands for its *.json files in name order.
// Keeps the shard's share of the whole list. False, naming the path, when a
// path is missing or unreadable or nothing is listed.
bool ListDatasets(const std::string& list, const Shard& shard,
                  std::vector<std::string>* files, std::string* error);

// One report per dataset in the output directory, named after the dataset
// file's stem; false when two stems collide.
bool ReportNames(const std::vector<std::string>& files, const std::string& dir,
                 std::vector<std::string>* reports, std::string* error);

// Runs work(i) for i in [0, n) on `jobs` threads (work must only touch
// item i), ticking `progress` as items finish.
void ParallelFor(int n, int jobs, Progress* progress, const std::function<void(int)>& work);

}  // namespace ringid

#endif  // RINGID_APPS_CAMPAIGN_H_
