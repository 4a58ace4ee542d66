// `ringid merge`: the shard summaries of one campaign as one summary.
#ifndef RINGID_REPORT_CAMPAIGN_MERGE_H_
#define RINGID_REPORT_CAMPAIGN_MERGE_H_

#include <string>
#include <vector>

#include "report/report.h"

namespace ringid {

// The shard summaries campaign.I-of-N.json in `dir`, checked to be the
// shards of one campaign (same datasets, options, command and N; no dataset
// twice, no shard missing: named), as one summary in the whole list's order
// (shard "merged"; its provenance left for the caller), and the summaries'
// paths. False with one line.
bool MergeShards(const std::string& dir, CampaignReport* merged, std::string* error,
                 std::vector<std::string>* shard_paths = nullptr);

}  // namespace ringid

#endif  // RINGID_REPORT_CAMPAIGN_MERGE_H_
