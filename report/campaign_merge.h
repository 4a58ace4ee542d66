// `ringid merge`: the shard summaries of one campaign as one summary.
#ifndef RINGID_REPORT_CAMPAIGN_MERGE_H_
#define RINGID_REPORT_CAMPAIGN_MERGE_H_

#include <string>
#include <vector>

#include "report/report.h"

namespace ringid {

// The one naming of a campaign's summaries in its directory: the stem,
// `campaign.json` for a whole campaign (count 1) and `campaign.I-of-N.json`
// for shard I of N; a dataset's report may not take a name that starts so.
inline constexpr char kCampaignSummaryStem[] = "campaign";
std::string CampaignSummaryName(int index, int count);
// I and N of a shard summary's file name (no directory); false for any other.
bool ParseShardSummaryName(const std::string& file, int* index, int* count);

// The shard summaries campaign.I-of-N.json in `dir`, checked to be the
// shards of one campaign (same datasets, options, command and N; no dataset
// twice, no shard missing: named), as one summary in the whole list's order
// (shard "merged"; its provenance left for the caller), and the summaries'
// paths. False with one line.
bool MergeShards(const std::string& dir, CampaignReport* merged, std::string* error,
                 std::vector<std::string>* shard_paths = nullptr);

}  // namespace ringid

#endif  // RINGID_REPORT_CAMPAIGN_MERGE_H_
