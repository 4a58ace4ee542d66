#include "apps/merge_command.h"

#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "apps/campaign.h"
#include "apps/flags.h"
#include "apps/html_report.h"
#include "apps/reports.h"

namespace ringid {

int MergeCommand(int argc, char** argv) {
  if (FLAGS_output_dir.empty()) return Usage("merge needs --output_dir=DIR (the campaign's)");
  const std::filesystem::path dir(FLAGS_output_dir);
  CampaignReport merged;
  std::string error;
  std::vector<std::string> paths;
  if (!MergeShards(FLAGS_output_dir, &merged, &error, &paths)) return Usage(error);
  std::vector<std::pair<std::string, std::string>> shards;
  for (const std::string& p : paths) shards.emplace_back("shard", p);
  merged.provenance = MakeProvenance(argc, argv, shards, std::nullopt);
  const std::string text = ReportText(merged);
  std::string html;
  std::vector<HtmlFigure> figures;
  std::vector<std::pair<std::string, std::string>> files = {{(dir / CampaignSummaryName(0, 1)).string(), text}};
  // The summary is written whatever the page: a login node may lack gnuplot.
  if (RenderHtmlReport(Json::parse(text), files[0].first, &html, &error, &figures)) {
    files.emplace_back((dir / "campaign.html").string(), html);
  } else {
    std::fprintf(stderr, "ringid: merge: no page (%s); render it later with ringid report\n",
                 error.c_str());
  }
  if (!WriteFilesAtomically(files, &error)) return Usage(error);
  std::printf("%s\n%zu dataset(s) from %zu shard(s), %d kept from earlier runs, %d failed; "
              "wrote %s%s\n",
              CampaignTable(merged.body).c_str(), merged.body.datasets.size(), shards.size(),
              merged.body.resumed, merged.body.failed, files[0].first.c_str(),
              files.size() > 1 ? (" and " + files[1].first).c_str() : "");
  return kExitOk;
}

}  // namespace ringid
