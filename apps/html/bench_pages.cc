// The pages of `ringid bench`, one per suite: paper, synthetic,
// conditioning and diagnosis.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

#include "apps/html/pages.h"
#include "apps/html/text.h"

namespace ringid::html {
namespace {

// ------------------------------------------------------------------ paper

// Table 3 of the paper against the model; the frequencies for the figure.
FrequencyFigureOptions Table3Section(const json& report, Page* page) {
  std::vector<Row> rows;
  FrequencyFigureOptions figure;
  figure.name = "bench-paper-table3";
  figure.reference_title = "paper (Table 3)";
  figure.band_title = "± 0.05 Hz, the paper's rounding";
  figure.reference_name = "paper";
  for (const json& m : List(report, "table3")) {
    const auto paper = Num(m, "paper_hz"), model = Num(m, "model_hz");
    std::optional<double> diff, relative;
    if (paper && model) diff = *model - *paper;
    if (diff && *paper != 0) relative = 100 * *diff / *paper;
    rows.push_back({ValueCell(Get(m, "label")), NumberCell(paper, "%.1f"),
                    NumberCell(model, "%.3f"), NumberCell(diff, "%.3f"),
                    NumberCell(relative, "%.2f")});
    figure.AddMode(Str(m, "label"), paper, 0.05, model);
  }
  page->Heading("Table 3 reproduced");
  page->Table({"mode", "paper (Hz)", "model (Hz)", "model − paper (Hz)", "model − paper (%)"},
              rows);
  return figure;
}

// ------------------------------------------------------------- synthetic

// The coverage per tire and the binomial band expected around 95 %.
struct Coverage {
  std::vector<std::string> tires;
  Series observed, band;
  double low = 90;
};

Coverage TiresSection(const json& report, Page* page) {
  Coverage coverage;
  std::vector<Row> rows;
  for (const json& t : List(report, "tires")) {
    const auto c = Num(t, "coverage_95"), n = Num(t, "intervals");
    rows.push_back({ValueCell(Get(t, "tire")), NumberCell(Num(t, "scale")),
                    ValueCell(Get(t, "replicates")), ValueCell(Get(t, "intervals")), PercentCell(c),
                    NumberCell(Num(t, "median_error_over_std"), "%.3f"),
                    ValueCell(Get(t, "failed_fits"))});
    const double i = static_cast<double>(coverage.tires.size());
    coverage.tires.push_back(Str(t, "tire"));
    if (c) coverage.observed.Row({i, 100 * *c}), coverage.low = std::min(coverage.low, 100 * *c);
    if (n && *n > 0) {
      const double half = 100 * 1.96 * std::sqrt(0.95 * 0.05 / *n);
      coverage.band.Row({i, std::max(0.0, 95 - half), std::min(100.0, 95 + half)});
      coverage.low = std::min(coverage.low, 95 - half);
    }
  }
  page->Heading("Tires");
  page->Table({"tire", "scale", "replicates", "intervals", "95 % coverage (%)",
               "median |error| / std", "failed fits"},
              rows);
  return coverage;
}

void CoverageFigure(const Coverage& coverage, Page* page) {
  if (coverage.observed.empty()) {
    page->Note("No coverage figure: no tire has a coverage.");
    return;
  }
  Figure f("bench-synthetic-coverage", 760, 380);
  const std::string red = "lc rgb '" + std::string(kRed) + "'";
  std::ostringstream g;
  g << "set grid ytics\nset key outside below center horizontal\n"
    << "set xrange [-0.5:" << coverage.tires.size() - 0.5 << "]\nset yrange ["
    << std::floor(coverage.low - 2) << ":101]\n"
    << "set xtics noenhanced " << Tics(coverage.tires) << "\n"
    << "set ylabel 'coverage of the 95 % intervals (%)'\n"
    << HorizontalLine(1, "95", "dt 2 lw 1.5 " + red)
    << "set label 1 'nominal 95 %' at graph 0.01, first 95 left offset 0, 0.7 tc rgb '" << kRed
    << "'\n";
  std::vector<std::string> parts;
  if (!coverage.band.empty()) {
    parts.push_back(f.AddData(coverage.band) +
                    " using 1:2:(0):($3-$2) with vectors nohead lw 10 lc rgb '#cfcfcf' "
                    "title 'expected spread if the intervals are right (95 %)'");
  }
  parts.push_back(f.AddData(coverage.observed) + " using 1:2 with points pt 7 ps 1.6 lc rgb '" +
                  kBlue + "' title 'observed coverage'");
  f.script = g.str() + PlotCommand(parts);
  f.caption =
      "Monte Carlo coverage of the 95 % intervals per tire, in %. Grey bars: the binomial 95 % "
      "range of the observed coverage around 95 % for that tire's number of intervals.";
  page->AddFigure(std::move(f));
}

// ----------------------------------------------------------- conditioning

// Rank and identifiability classes per data variant.
struct Conditioning {
  std::vector<std::string> variants;
  std::vector<std::pair<double, double>> rank;  // a bar from 0 to the rank
  Series yes, practically_no, no;               // stacked bars of the classes
  int free_max = 0;
};

Conditioning VariantsSection(const json& report, Page* page) {
  Conditioning out;
  std::vector<Row> rows;
  for (const json& v : List(report, "variants")) {
    int counts[3] = {0, 0, 0}, n = 0;
    if (const json& classes = Get(v, "classes"); classes.is_object()) {
      for (const auto& [name, c] : classes.items()) {
        ++n;
        const std::string s = Str(c);
        ++counts[s == "yes" ? 0 : s == "practically_no" ? 1 : 2];
      }
    }
    out.free_max = std::max(out.free_max, n);
    const double i = static_cast<double>(out.variants.size());
    rows.push_back({ValueCell(Get(v, "data")), ValueCell(Get(v, "residuals")),
                    ValueCell(Get(v, "rank")), NumberCell(counts[0], "%.0f"),
                    NumberCell(counts[1], "%.0f"), NumberCell(counts[2], "%.0f"),
                    NumberCell(Num(v, "condition_number")),
                    ValueCell(Get(v, "identifiable_subset"))});
    out.variants.push_back(Str(v, "data"));
    const auto k = Num(v, "rank");
    out.rank.push_back({0, k ? *k : NAN});
    if (n) {
      out.yes.Row({i, 0, counts[0]});
      out.practically_no.Row({i, counts[0], counts[0] + counts[1]});
      out.no.Row({i, counts[0] + counts[1], n});
    }
  }
  page->Heading("Data variants");
  page->Table({"data", "residuals", "rank", "yes", "practically_no", "no", "condition number",
               "identifiable subset"},
              rows);
  return out;
}

// The right panel: how many parameters fall in each class.
std::string ClassPanel(Figure* f, const Conditioning& c) {
  std::ostringstream g;
  g << "set key at screen 0.795, screen 1 center top horizontal\n"
    << "set lmargin at screen 0.62\nset rmargin at screen 0.97\n"
    << "set ytics " << Tics(c.variants, true) << "\n"
    << "set xlabel 'parameters by class'\n";
  std::vector<std::string> parts;
  for (auto [s, color, title] :
       {std::tuple<const Series*, const char*, const char*>{&c.yes, kBlue, "yes"},
        {&c.practically_no, kOrange, "practically_no"},
        {&c.no, kGrey, "no"}}) {
    if (!s->empty())
      parts.push_back(HorizontalBars(f->AddData(*s), color) + " title " + GnuplotString(title));
  }
  return g.str() + PlotCommand(parts);
}

void ConditioningFigure(const Conditioning& c, Page* page) {
  if (c.variants.empty()) {
    page->Note("No conditioning figure: the report has no variant.");
    return;
  }
  const int n = static_cast<int>(c.variants.size());
  Figure f("bench-conditioning-rank", 920, 130 + 44 * n);
  std::ostringstream g;
  g << "set multiplot\nset style fill solid 0.85 noborder\nset grid xtics\n"
    << ScreenMargins(f, 40, 55) << "set yrange [" << n - 0.5
    << ":-0.5]\nset xrange [0:" << std::max(c.free_max, 1) + 1 << "]\n"
    << "unset key\n";
  if (c.free_max) {
    const std::string at = std::to_string(c.free_max);
    g << VerticalLine(1, at, "dt 2 lw 1.5 lc rgb '" + std::string(kRed) + "'") << "set label 1 "
      << GnuplotString(at + " free") << " at " << at << ", graph 1 center offset 0, 0.8 tc rgb '"
      << kRed << "'\n";
  }
  BarPanelOptions rank;
  rank.labels = c.variants;
  rank.bars = c.rank;
  rank.highlight = std::vector<bool>(n, true);
  rank.x_label = "rank of the weighted Jacobian";
  rank.highlight_color = kBlue;
  g << BarPanel(&f, rank);
  g << "unset arrow 1\nunset label 1\n" << ClassPanel(&f, c) << "unset multiplot\n";
  f.script = g.str();
  f.caption =
      "What each kind of data determines. Left: rank of the weighted Jacobian per data "
      "variant, against the number of free parameters (dashed). Right: how many parameters "
      "fall in each identifiability class.";
  page->AddFigure(std::move(f));
}

// -------------------------------------------------------------- diagnosis

// The confusion matrix's rows (truths, "none" first) and columns (verdicts:
// "none", then the diagonal, then any other).
void ConfusionLabels(const json& confusion, std::vector<std::string>* truths,
                     std::vector<std::string>* verdicts) {
  if (!confusion.is_object()) return;
  if (confusion.contains("none")) truths->push_back("none");
  for (const auto& [t, row] : confusion.items()) {
    if (t != "none") truths->push_back(t);
  }
  for (const std::string& t : *truths) {
    if (Get(Get(confusion, t.c_str()), "none").is_number()) AppendOnce(verdicts, "none");
  }
  for (const std::string& t : *truths) {
    if (Get(Get(confusion, t.c_str()), t.c_str()).is_number()) AppendOnce(verdicts, t);
  }
  for (const std::string& t : *truths) {
    if (!Get(confusion, t.c_str()).is_object()) continue;
    for (const auto& [v, count] : Get(confusion, t.c_str()).items()) AppendOnce(verdicts, v);
  }
}

// The confusion table; the heat map's cells.
HeatMapOptions ConfusionSection(const json& report, Page* page) {
  const json& confusion = Get(report, "confusion");
  HeatMapOptions map;
  ConfusionLabels(confusion, &map.rows, &map.columns);
  std::vector<Row> rows;
  for (const std::string& t : map.rows) {
    map.values.emplace_back();
    rows.push_back({TextCell(t)});
    for (const std::string& v : map.columns) {
      const auto count = Num(Get(confusion, t.c_str()), v.c_str());
      map.values.back().push_back(count);
      rows.back().push_back(NumberCell(count, "%.0f"));
      if (count) map.high = std::max(map.high, *count);
    }
  }
  std::vector<std::string> head = {"truth \\ verdict"};
  head.insert(head.end(), map.columns.begin(), map.columns.end());
  page->Heading("Confusion");
  page->Table(head, rows);
  return map;
}

void CasesSection(const json& report, Page* page) {
  page->Heading("Cases");
  page->Table({"case", "truth", "shift", "value", "verdict", "indistinguishable", "gap p-value",
               "correct", "absorbed and explained", "seconds"},
              RowsOf(List(report, "cases"), [](const json& c) -> Row {
                return {ValueCell(Get(c, "case")), ValueCell(Get(c, "truth")),
                        NumberCell(Num(c, "shift")), NumberCell(Num(c, "value")),
                        ValueCell(Get(c, "verdict")), ValueCell(Get(c, "indistinguishable")),
                        NumberCell(Num(c, "gap_p_value"), "%.3g"), ValueCell(Get(c, "correct")),
                        ValueCell(Get(c, "absorbed_explained")),
                        NumberCell(Num(c, "seconds"), "%.2f")};
              }));
}

}  // namespace

void BenchPaperPage(const json& report, Page* page) {
  std::vector<Row> rows;
  for (const auto& [key, title] : kMethods) {
    const json& m = Get(Get(report, "identify"), key);
    if (!m.is_object()) continue;
    rows.push_back({TextCell(title), NumberCell(Num(m, "eq19")), NumberCell(Num(m, "eq20")),
                    ValueCell(Get(m, "evaluations")), ValueCell(Get(m, "rank")),
                    NumberCell(Num(m, "seconds"))});
  }
  page->Heading("Table 1 identified");
  page->Table({"method", "relative error in-plane (eq. 19)", "relative error out-of-plane (eq. 20)",
               "evaluations", "rank", "seconds"},
              rows);
  const FrequencyFigureOptions frequencies = Table3Section(report, page);
  page->Heading("Figures");
  if (auto f = FrequencyFigure(frequencies)) {
    f->caption =
        "Table 3 of the paper reproduced from its Table 2 parameters. Left: the paper's and the "
        "model's frequency per mode, in Hz. Right: model − paper, in Hz, against ± 0.05 Hz, "
        "the rounding of the paper's table.";
    page->AddFigure(std::move(*f));
  }
}

void BenchSyntheticPage(const json& report, Page* page) {
  page->Summary(FactsOf(report, {{"coverage_95", "95 % coverage, all tires"},
                                 {"free", "free parameters"},
                                 {"noise/frequency_relative", "frequency noise (relative sd)"},
                                 {"noise/damping_relative", "damping noise (relative sd)"},
                                 {"noise/shape", "shape noise (sd)"}}));
  const Coverage coverage = TiresSection(report, page);
  page->Heading("Figures");
  CoverageFigure(coverage, page);
}

void BenchConditioningPage(const json& report, Page* page) {
  const Conditioning conditioning = VariantsSection(report, page);
  page->Heading("Figures");
  ConditioningFigure(conditioning, page);
}

void BenchDiagnosisPage(const json& report, Page* page) {
  FactRows facts;
  if (!List(report, "cases").empty())
    facts.push_back({"cases", TextCell(std::to_string(List(report, "cases").size()))});
  const FactRows more =
      FactsOf(report, {{"accuracy"}, {"false_alarms"}, {"no_effect_cases", "no-effect cases"},
                       {"named"}, {"absorbed_and_explained"}, {"mean_shrink_when_named"},
                       {"seconds_per_diagnosis"}});
  facts.insert(facts.end(), more.begin(), more.end());
  page->Summary(facts);
  HeatMapOptions map = ConfusionSection(report, page);
  CasesSection(report, page);
  page->Heading("Figures");
  if (map.rows.empty() || map.columns.empty()) {
    page->Note("No confusion figure: the report has no confusion matrix.");
    return;
  }
  map.name = "bench-diagnosis-confusion";
  map.cell_format = "%.0f";
  map.x_label = "verdict";
  map.y_label = "withheld effect (truth)";
  map.color_label = "cases";
  Figure f = HeatMap(map);
  f.caption =
      "Confusion matrix of the withheld-effect validation: number of cases per withheld "
      "effect (row) and verdict (column); the diagonal is a named effect.";
  page->AddFigure(std::move(f));
}

}  // namespace ringid::html
