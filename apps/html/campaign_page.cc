// The page of a campaign (a command over a directory of datasets): one row
// per dataset; for diagnoses, the gap of each before and after.
#include <algorithm>
#include <filesystem>
#include <sstream>

#include "apps/html/pages.h"

namespace ringid::html {
namespace {

// The table's columns: the report's, else the first dataset's keys; always
// the report file.
std::vector<std::string> Columns(const json& report, const json& datasets) {
  std::vector<std::string> columns;
  for (const json& c : List(report, "columns")) {
    if (c.is_string()) columns.push_back(c.get<std::string>());
  }
  if (columns.empty() && !datasets.empty() && datasets[0].is_object()) {
    for (const auto& [key, value] : datasets[0].items()) columns.push_back(key);
  }
  if (std::find(columns.begin(), columns.end(), "report_file") == columns.end()) {
    columns.push_back("report_file");
  }
  return columns;
}

// The gap of each dataset before and after, one bar pair each.
void GapFigure(const json& datasets, Page* page) {
  Series s;
  std::vector<std::string> names;
  for (const json& d : datasets) {
    const auto before = Num(d, "gap_before"), after = Num(d, "gap_after");
    if (!before && !after) continue;
    s.Row({static_cast<double>(names.size()), before, after});
    names.push_back(std::filesystem::path(Str(d, "dataset")).stem().string());
  }
  page->Heading("Figures");
  if (s.empty()) {
    page->Note("No gap figure: no dataset has a gap.");
    return;
  }
  const int n = static_cast<int>(names.size());
  Figure f("campaign-gaps", std::clamp(300 + 28 * n, 700, 2400), 420);
  const std::string d = f.AddData(s);
  std::ostringstream g;
  g << "set style fill solid 0.85 noborder\nset boxwidth 0.38\nset grid ytics\n"
    << "set key outside top center horizontal\n"
    << "set xrange [-0.6:" << n - 0.4 << "]\n"
    << CategoryXTics(names, f.width - 150.0, -60) << "set ylabel 'gap: χ² in excess of its dof'\n"
    << HorizontalLine(1, "0", kAxisLine) << "plot " << d << " using ($1-0.2):2 with boxes lc rgb '"
    << kBlue << "' title 'before (baseline)', " << d << " using ($1+0.2):3 with boxes lc rgb '"
    << kOrange << "' title 'after (with the verdict)'";
  if (n <= 20) {  // the values over the bars
    for (const auto& [column, shift] : {std::pair<int, double>{2, -0.2}, {3, 0.2}}) {
      g << ", " << d << " using ($1" << (shift < 0 ? "" : "+") << shift << "):" << column
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

void CampaignPage(const json& report, Page* page) {
  const json& datasets = List(report, "datasets");
  FactRows facts = FactsOf(report, {{"command"}, {"shard"}, {"jobs"}, {"seconds"}});
  facts.push_back({"datasets", NumberCell(static_cast<double>(datasets.size()), "%.0f")});
  page->Summary(facts);
  const std::vector<std::string> columns = Columns(report, datasets);
  page->Heading("Datasets");
  page->Table(columns, RowsOf(datasets, [&](const json& d) {
                Row row;
                for (const std::string& c : columns) row.push_back(ValueCell(Get(d, c.c_str())));
                return row;
              }));
  if (Str(report, "command") == "diagnose") GapFigure(datasets, page);
}

}  // namespace ringid::html
