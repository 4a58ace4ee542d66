// Campaigns: many datasets, one report each and a summary, on several
// threads or split into shards across machines with no coordination.
#ifndef RINGID_APPS_CAMPAIGN_H_
#define RINGID_APPS_CAMPAIGN_H_

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "apps/progress.h"
#include "datasets/dataset.h"
#include "estimation/diagnose.h"
#include "estimation/identify.h"
#include "model/rigid_ring_model.h"
#include "report/campaign_merge.h"
#include "report/report.h"

namespace ringid {

// --shard=I/N: the datasets at positions I, I+N, I+2N, ... (0 <= I < N).
// --shard=slurm: I and N from a Slurm job array's variables.
struct Shard {
  int index = 0;
  int count = 1;
};
bool ParseShard(const std::string& text, Shard* shard, std::string* error);
// I and N of a Slurm job array task (SLURM_ARRAY_TASK_ID, _COUNT, _MIN, _MAX,
// _STEP, read by `getenv`); false, saying why, outside an array or for one
// that does not map onto shards 0..N-1.
bool SlurmShard(const std::function<const char*(const char*)>& getenv, Shard* shard,
                std::string* error);

// "FILE,DIR,...": a directory stands for its *.json files in name order.
// `all` gets the whole list, `files` the shard's share. False, naming the
// path, when a path is missing or unreadable or nothing is listed.
bool ListDatasets(const std::string& list, const Shard& shard, std::vector<std::string>* all,
                  std::vector<std::string>* files, std::string* error);

// One report per dataset in the output directory, named after the dataset
// file's stem; false when two stems collide.
bool ReportNames(const std::vector<std::string>& files, const std::string& dir,
                 std::vector<std::string>* reports, std::string* error);

// One dataset's share of a campaign: its report and its row of the summary.
struct CampaignItem {
  std::string report;
  CampaignRow row;
};
using CampaignWork = std::function<CampaignItem(const Dataset&, const std::string& file)>;

// A command's row of the summary, from its result.
CampaignRow IdentifyRow(const IdentifyResult& r);
CampaignRow DiagnoseRow(const DiagnosisResult& r);

// A campaign as the command line asks for it.
struct CampaignRequest {
  ReportKind command = ReportKind::kIdentify;
  std::string datasets;    // --dataset: FILE,DIR,...
  std::string output_dir;  // --output_dir
  std::string shard = "0/1";
  int jobs = 1;
  // The flags that decide the results (NAME=VALUE): a report made under the
  // same from the same dataset bytes is kept, not fitted again, unless `force`.
  std::vector<std::string> options;
  bool force = false;
  // A dataset that fails to load or to fit is a failed row, not the end.
  bool keep_going = false;
  // Applied to each dataset as it is loaded (--fix); false with one line.
  std::function<bool(Dataset*, std::string*)> prepare;
  // The summary's provenance, given its inputs as (flag, path).
  std::function<Provenance(const std::vector<std::pair<std::string, std::string>>&)> provenance;
};

// Runs `work` on every dataset of the request's shard, `jobs` at once, each
// report written as its dataset finishes, then the summary (campaign.json, or
// campaign.I-of-N.json for a shard) and its table on standard output. Every
// input is loaded and checked before anything runs: a bad one, or a dataset
// `model` cannot start on, is exit status 2 with `error` set to one line and
// nothing written (with `keep_going`, a failed row). A dataset whose report
// is already there, made from its bytes under the request's options, is
// kept (resumed). Otherwise 0 when every analysis succeeded, else 1.
int RunCampaign(const CampaignRequest& request, const ModalModel& model,
                const CampaignWork& work, std::string* error);

}  // namespace ringid

#endif  // RINGID_APPS_CAMPAIGN_H_
