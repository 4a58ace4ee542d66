// The page of a campaign (a command over a directory of datasets): one row
// per dataset; for diagnoses, the gap of each before and after.
#include <algorithm>
#include <cmath>
#include <map>
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
  f.caption = std::string("The gap of each dataset before and after adding the effect of its "
                          "verdict. ") + kCampaignGapMeaning + ".";
  page->AddFigure(std::move(f));
}

// The distribution of each fitted parameter over the datasets, one panel each.
void ParameterHistograms(const std::vector<CampaignRow>& datasets, Page* page) {
  std::map<Param, std::vector<double>> values;
  for (const CampaignRow& d : datasets) {
    for (const auto& [q, v] : d.parameters.value_or(std::map<Param, double>{})) {
      if (std::isfinite(v)) values[q].push_back(v);
    }
  }
  if (values.empty()) {
    page->Note("No parameter histograms: no dataset was fitted.");
    return;
  }
  const int panels = static_cast<int>(values.size()), columns = std::min(panels, 4);
  const int rows = (panels + columns - 1) / columns;
  Figure f("campaign-parameters", 280 * columns + 60, 220 * rows + 40);
  std::ostringstream g;
  g << "set style fill solid 0.85 noborder\nset grid ytics\nset key off\n"
    << "set multiplot layout " << rows << "," << columns << "\n";
  for (const auto& [q, v] : values) {
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    int bins = std::clamp(static_cast<int>(std::sqrt(v.size())), 1, 20);
    double width = (*hi - *lo) / bins;
    if (!(width > 0) || !std::isfinite(width) || !std::isfinite(*lo + (bins + 1) * width)) {
      bins = 1;  // one value, or a range no double spacing can split
      width = std::isfinite(*lo) && *lo != 0 ? std::abs(*lo) * 0.1 : 1;
    }
    std::vector<int> count(bins, 0);
    for (double x : v) {
      const double at = (x - *lo) / width;
      ++count[std::isfinite(at) ? std::clamp(static_cast<int>(std::min(at, 1e9)), 0, bins - 1) : 0];
    }
    Series series;
    for (int b = 0; b < bins; ++b) series.Row({*lo + (b + 0.5) * width, static_cast<double>(count[b])});
    const std::string data = f.AddData(series);
    g << "set title " << GnuplotString(std::string(ParamName(q)) + " (" + Info(q).unit + ")")
      << " noenhanced\nset boxwidth " << width * 0.9 << "\nset format x '%.3g'\n"
      << "set xtics rotate by -30\nset yrange [0:*]\nset xrange [" << *lo - width << ":"
      << *lo + (bins + 1) * width << "]\n"
      << "plot " << data << " using 1:2 with boxes lc rgb '" << kBlue << "'\n";
  }
  g << "unset multiplot\n";
  f.script = g.str();
  f.caption = "The fitted value of each free parameter over the datasets fitted (counts per "
              "bin; a panel per parameter, in its unit; a per-condition one at its first "
              "condition).";
  page->AddFigure(std::move(f));
}

// How many datasets each verdict has (none, an effect, or failed).
void VerdictFigure(const std::vector<CampaignRow>& datasets, Page* page) {
  std::map<std::string, int> counts;
  for (const CampaignRow& d : datasets) {
    ++counts[!d.status.ok() ? "failed" : d.verdict && *d.verdict ? EffectName(*d.verdict) : "none"];
  }
  std::vector<std::string> names;
  Series series;
  for (const auto& [name, n] : counts) {
    series.Row({static_cast<double>(names.size()), static_cast<double>(n)});
    names.push_back(name);
  }
  const int n = static_cast<int>(names.size());
  Figure f("campaign-verdicts", std::clamp(300 + 90 * n, 600, 1600), 380);
  const std::string data = f.AddData(series);
  std::ostringstream g;
  g << "set style fill solid 0.85 noborder\nset boxwidth 0.6\nset grid ytics\nset key off\n"
    << "set xrange [-0.6:" << n - 0.4 << "]\nset yrange [0:*]\n"
    << CategoryXTics(Pretty(names), f.width - 150.0, -30) << "set ylabel 'datasets'\n"
    << "plot " << data << " using 1:2 with boxes lc rgb '" << kOrange << "', " << data
    << " using 1:2:(sprintf('%d', $2)) with labels offset 0, 0.7\n";
  f.script = g.str();
  f.caption = "The datasets by verdict: the effect that explains each one's gap, none, or failed.";
  page->AddFigure(std::move(f));
}

}  // namespace

void CampaignPage(const CampaignReport& report, Page* page) {
  const CampaignBody& campaign = report.body;
  page->Summary({{"command", NameCell(campaign.command)},
                 {"shard", OptionalTextCell(campaign.shard)},
                 {"jobs", NumberCell(campaign.jobs, "%.0f")},
                 {"seconds", NumberCell(campaign.seconds)},
                 {"datasets", NumberCell(static_cast<double>(campaign.datasets.size()), "%.0f")},
                 {"kept from an earlier run", NumberCell(campaign.resumed, "%.0f")},
                 {"failed", NumberCell(campaign.failed, "%.0f")}});
  if (campaign.command == ReportKind::kDiagnose) {
    DiagnoseTable(campaign.datasets, page);
    GapFigure(campaign.datasets, page);
    VerdictFigure(campaign.datasets, page);
  } else {
    IdentifyTable(campaign.datasets, page);
    page->Heading("Figures");
    ParameterHistograms(campaign.datasets, page);
  }
}

}  // namespace ringid::html
