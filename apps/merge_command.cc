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
  if (!MergeShards(FLAGS_output_dir, &merged, &error)) return Usage(error);
  std::vector<std::pair<std::string, std::string>> shards;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::filesystem::path& entry = it->path();
    const std::string name = entry.filename().string();
    if (name.rfind("campaign.", 0) == 0 && name.find("-of-") != std::string::npos) {
      shards.emplace_back("shard", entry.string());
    }
  }
  merged.provenance = MakeProvenance(argc, argv, shards, std::nullopt);
  const std::string text = ReportText(merged);
  Json json = Json::parse(text);
  std::string html;
  std::vector<HtmlFigure> figures;
  if (!RenderHtmlReport(json, (dir / "campaign.json").string(), &html, &error, &figures)) {
    std::fprintf(stderr, "ringid: merge: %s\n", error.c_str());
    return kExitFailure;
  }
  const std::string summary = (dir / "campaign.json").string(), page = (dir / "campaign.html").string();
  if (!WriteFilesAtomically({{summary, text}, {page, html}}, &error)) return Usage(error);
  std::printf("%s\n%zu dataset(s) from %zu shard(s), %d kept from earlier runs, %d failed; "
              "wrote %s and %s\n",
              CampaignTable(merged.body).c_str(), merged.body.datasets.size(), shards.size(),
              merged.body.resumed, merged.body.failed, summary.c_str(), page.c_str());
  return kExitOk;
}

}  // namespace ringid
