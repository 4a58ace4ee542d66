// The page of a campaign (a command over a directory of datasets): one row
// per dataset; for diagnoses, the gap of each before and after.
#include <algorithm>
#include <filesystem>
#include <sstream>

#include "apps/html/pages.h"

namespace ringid::html {
namespace {

// "–" for an empty text.
Cell OptionalTextCell(const std::string& text) { return TextCell(text.empty() ? "–" : text); }

// One row per dataset of an identify campaign.
void IdentifyTable(const std::vector<CampaignRow>& datasets, Page* page) {
  std::vector<Row> rows;
  for (const CampaignRow& d : datasets) {
    rows.push_back({TextCell(d.dataset), NameCell(d.status.outcome),
                    OptionalTextCell(d.status.message), YesNoCell(d.converged.value_or(false)),
                    NumberCell(d.cost), NumberCell(d.relative_error_in_plane_eq19),
                    NumberCell(d.relative_error_out_of_plane_eq20),
                    NumberCell(d.seconds), TextCell(d.report_file)});
  }
  page->TableSection("Datasets",
                     {"dataset", "status", "message", "converged", "cost",
                      "relative error, in-plane (eq. 19)", "relative error, out-of-plane (eq. 20)",
                      "seconds", "report file"},
                     rows);
}

// One row per dataset of a diagnose campaign.
void DiagnoseTable(const std::vector<CampaignRow>& datasets, Page* page) {
  std::vector<Row> rows;
  for (const CampaignRow& d : datasets) {
    rows.push_back({TextCell(d.dataset), NameCell(d.status.outcome),
                    OptionalTextCell(d.status.message), TextCell(d.verdict ? EffectName(*d.verdict) : "–"),
                    ListCell(EffectNames(d.indistinguishable.value_or(std::vector<const Effect*>{}))), NumberCell(d.gap_before),
                    NumberCell(d.gap_after), PercentCell(d.shrink), NumberCell(d.seconds),
                    TextCell(d.report_file)});
  }
  page->TableSection("Datasets",
                     {"dataset", "status", "message", "verdict", "indistinguishable", "gap before",
                      "gap after", "shrink (%)", "seconds", "report file"},
                     rows);
}

// The gap of each dataset before and after, one bar pair each.
void GapFigure(const std::vector<CampaignRow>& datasets, Page* page) {
  Series series;
  std::vector<std::string> names;
  for (const CampaignRow& d : datasets) {
    if (!d.gap_before && !d.gap_after) continue;
    series.Row({static_cast<double>(names.size()), d.gap_before, d.gap_after});
    names.push_back(std::filesystem::path(d.dataset).stem().string());
  }
  page->Heading("Figures");
  if (series.empty()) {
    page->Note("No gap figure: no dataset has a gap.");
    return;
  }
  const int n = static_cast<int>(names.size());
  Figure f("campaign-gaps", std::clamp(300 + 28 * n, 700, 2400), 420);
  const std::string data = f.AddData(series);
  std::ostringstream g;
  g << "set style fill solid 0.85 noborder\nset boxwidth 0.38\nset grid ytics\n"
    << "set key outside top center horizontal\n"
    << "set xrange [-0.6:" << n - 0.4 << "]\n"
    << CategoryXTics(names, f.width - 150.0, -60) << "set ylabel 'gap: χ² in excess of its dof'\n"
    << HorizontalLine(1, "0", kAxisLine) << "plot " << data
    << " using ($1-0.2):2 with boxes lc rgb '" << kBlue << "' title 'before (baseline)', " << data
    << " using ($1+0.2):3 with boxes lc rgb '" << kOrange << "' title 'after (with the verdict)'";
  if (n <= 20) {  // the values over the bars
    for (const auto& [column, shift] : {std::pair<int, double>{2, -0.2}, {3, 0.2}}) {
      g << ", " << data << " using ($1" << (shift < 0 ? "" : "+") << shift << "):" << column
        << ":(sprintf('%.4g', $" << column << ")) with labels offset 0, 0.6 font ',8' notitle";
    }
  }
  g << "\n";
  f.script = g.str();
  f.caption =
      "The gap of each dataset before and after adding the effect of its verdict, as χ² in "
      "excess of its degrees of freedom (0 is a fit as good as the noise).";
  page->AddFigure(std::move(f));
}

}  // namespace

void CampaignPage(const CampaignReport& report, Page* page) {
  const CampaignBody& campaign = report.body;
  page->Summary({{"command", NameCell(campaign.command)},
                 {"shard", OptionalTextCell(campaign.shard)},
                 {"jobs", NumberCell(campaign.jobs, "%.0f")},
                 {"seconds", NumberCell(campaign.seconds)},
                 {"datasets", NumberCell(static_cast<double>(campaign.datasets.size()), "%.0f")}});
  if (campaign.command == ReportKind::kDiagnose) {
    DiagnoseTable(campaign.datasets, page);
    GapFigure(campaign.datasets, page);
  } else {
    IdentifyTable(campaign.datasets, page);
  }
}

}  // namespace ringid::html
