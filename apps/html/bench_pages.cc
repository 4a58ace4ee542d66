// The pages of `ringid bench`, one per suite: paper, synthetic,
// conditioning and diagnosis.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

#include "apps/html/pages.h"
#include "apps/html/text.h"
#include "estimation/statistics.h"

namespace ringid::html {
namespace {

// ------------------------------------------------------------------ paper

// Table 1 identified by each method, and the error the paper reports.
void Table1Section(const PaperSuite& suite, Page* page) {
  std::vector<Row> rows;
  for (const Table1Fit& fit : suite.identify) {
    rows.push_back({TextCell(MethodTitle(fit.method)), NumberCell(fit.relative_error_in_plane_eq19),
                    NumberCell(fit.relative_error_out_of_plane_eq20),
                    NumberCell(static_cast<double>(fit.evaluations), "%.0f"),
                    NumberCell(fit.rank, "%.0f"), NumberCell(fit.seconds)});
  }
  const auto& [paper_in_plane, paper_out_of_plane] = suite.paper_reported_eq19_eq20;
  rows.push_back({TextCell("paper (Downhill Simplex)"), NumberCell(paper_in_plane),
                  NumberCell(paper_out_of_plane), NumberCell(std::nullopt),
                  NumberCell(std::nullopt), NumberCell(std::nullopt)});
  page->Heading("Table 1 identified");
  page->Table({"method", "relative error in-plane (eq. 19)", "relative error out-of-plane (eq. 20)",
               "evaluations", "rank", "seconds"},
              rows);
}

// Table 3 of the paper against the model; the frequencies for the figure.
FrequencyFigureOptions Table3Section(const PaperSuite& suite, Page* page) {
  std::vector<Row> rows;
  FrequencyFigureOptions figure;
  figure.name = "bench-paper-table3";
  figure.reference_title = "paper (Table 3)";
  figure.band_title = "± 0.05 Hz, the paper's rounding";
  figure.reference_name = "paper";
  for (const Table3Row& mode : suite.table3) {
    const double difference = mode.model_hz - mode.paper_hz;
    std::optional<double> relative;
    if (mode.paper_hz != 0) relative = 100 * difference / mode.paper_hz;
    rows.push_back({NameCell(mode.label), NumberCell(mode.paper_hz, "%.1f"),
                    NumberCell(mode.model_hz, "%.3f"), NumberCell(difference, "%.3f"),
                    NumberCell(relative, "%.2f")});
    figure.AddMode(ToString(mode.label), mode.paper_hz, 0.05, mode.model_hz);
  }
  page->Heading("Table 3 reproduced");
  page->Table({"mode", "paper (Hz)", "model (Hz)", "model − paper (Hz)", "model − paper (%)"},
              rows);
  return figure;
}

// ------------------------------------------------------------- synthetic

CoverageSeries TiresSection(const SyntheticSuite& suite, Page* page) {
  CoverageSeries coverage;
  std::vector<Row> rows;
  for (const TireCoverage& tire : suite.tires) {
    rows.push_back(
        {TextCell(tire.tire), NumberCell(tire.scale), NumberCell(tire.replicates, "%.0f"),
         NumberCell(static_cast<double>(tire.intervals), "%.0f"), PercentCell(tire.coverage_95),
         NumberCell(tire.median_error_over_std, "%.3f"), NumberCell(tire.failed_fits, "%.0f")});
    coverage.Add(tire.tire, tire.coverage_95, tire.intervals);
  }
  page->Heading("Tires");
  page->Table({"tire", "scale", "replicates", "intervals", "95 % coverage (%)",
               "median |error| / std", "failed fits"},
              rows);
  return coverage;
}

void CoverageFigure(const CoverageSeries& coverage, Page* page) {
  if (coverage.observed.empty()) {
    page->Note("No coverage figure: no tire has a coverage.");
    return;
  }
  Figure figure("bench-synthetic-coverage", 760, 380);
  DrawCoverage(coverage, coverage.low, "set xtics noenhanced " + Tics(coverage.names) + "\n",
               &figure);
  figure.caption =
      "Monte Carlo coverage of the 95 % intervals per tire, in %. Grey bars: the binomial 95 % "
      "range of the observed coverage around 95 % for that tire's number of intervals.";
  page->AddFigure(std::move(figure));
}

// ----------------------------------------------------------- conditioning

// Rank and identifiability classes per data variant.
struct Conditioning {
  std::vector<std::string> variants;
  std::vector<std::pair<double, double>> rank;  // a bar from 0 to the rank
  Series yes, practically_no, no;               // stacked bars of the classes
  int free_max = 0;
};

Conditioning VariantsSection(const ConditioningSuite& suite, Page* page) {
  Conditioning out;
  std::vector<Row> rows;
  for (const ConditioningVariant& variant : suite.variants) {
    const int yes = variant.Count(Identifiability::kYes);
    const int practically_no = variant.Count(Identifiability::kPracticallyNo);
    const int free_count = static_cast<int>(variant.classes.size());
    out.free_max = std::max(out.free_max, free_count);
    const double index = static_cast<double>(out.variants.size());
    rows.push_back({TextCell(variant.data), NumberCell(variant.residuals, "%.0f"),
                    NumberCell(variant.rank, "%.0f"), NumberCell(yes, "%.0f"),
                    NumberCell(practically_no, "%.0f"),
                    NumberCell(variant.Count(Identifiability::kNo), "%.0f"),
                    NumberCell(variant.condition_number), ListCell(variant.identifiable_subset)});
    out.variants.push_back(variant.data);
    out.rank.push_back({0, variant.rank});
    if (free_count) {
      out.yes.Row({index, 0, yes});
      out.practically_no.Row({index, yes, yes + practically_no});
      out.no.Row({index, yes + practically_no, free_count});
    }
  }
  page->Heading("Data variants");
  page->Table({"data", "residuals", "rank", ToString(Identifiability::kYes),
               ToString(Identifiability::kPracticallyNo), ToString(Identifiability::kNo),
               "condition number", "identifiable subset"},
              rows);
  return out;
}

// The right panel: how many parameters fall in each class.
std::string ClassPanel(Figure* figure, const Conditioning& conditioning) {
  std::ostringstream script;
  script << "set key at screen 0.795, screen 1 center top horizontal\n"
         << "set lmargin at screen 0.62\nset rmargin at screen 0.97\n"
         << "set ytics " << Tics(conditioning.variants, true) << "\n"
         << "set xlabel 'parameters by class'\n";
  std::vector<std::string> parts;
  for (auto [series, color, title] :
       {std::tuple<const Series*, const char*, const char*>{&conditioning.yes, kBlue, "yes"},
        {&conditioning.practically_no, kOrange, "practically_no"},
        {&conditioning.no, kGrey, "no"}}) {
    if (!series->empty())
      parts.push_back(HorizontalBars(figure->AddData(*series), color) + " title " +
                      GnuplotString(title));
  }
  return script.str() + PlotCommand(parts);
}

void ConditioningFigure(const Conditioning& conditioning, Page* page) {
  if (conditioning.variants.empty()) {
    page->Note("No conditioning figure: the report has no variant.");
    return;
  }
  const int count = static_cast<int>(conditioning.variants.size());
  Figure figure("bench-conditioning-rank", 920, 130 + 44 * count);
  std::ostringstream script;
  script << "set multiplot\nset style fill solid 0.85 noborder\nset grid xtics\n"
         << ScreenMargins(figure, 40, 55) << "set yrange [" << count - 0.5
         << ":-0.5]\nset xrange [0:" << std::max(conditioning.free_max, 1) + 1 << "]\n"
         << "unset key\n";
  if (conditioning.free_max) {
    const std::string at = std::to_string(conditioning.free_max);
    script << VerticalLine(1, at, "dt 2 lw 1.5 lc rgb '" + std::string(kRed) + "'")
           << "set label 1 " << GnuplotString(at + " free") << " at " << at
           << ", graph 1 center offset 0, 0.8 tc rgb '" << kRed << "'\n";
  }
  BarPanelOptions rank;
  rank.labels = conditioning.variants;
  rank.bars = conditioning.rank;
  rank.highlight = std::vector<bool>(count, true);
  rank.x_label = "rank of the weighted Jacobian";
  rank.highlight_color = kBlue;
  script << BarPanel(&figure, rank);
  script << "unset arrow 1\nunset label 1\n"
         << ClassPanel(&figure, conditioning) << "unset multiplot\n";
  figure.script = script.str();
  figure.caption =
      "What each kind of data determines. Left: rank of the weighted Jacobian per data "
      "variant, against the number of free parameters (dashed). Right: how many parameters "
      "fall in each identifiability class.";
  page->AddFigure(std::move(figure));
}

// -------------------------------------------------------------- diagnosis

// The confusion matrix's rows (truths) and columns (verdicts): the suite's
// effects in order, "none" first, then any other name the matrix holds.
void ConfusionLabels(const DiagnosisSuite& suite, std::vector<std::string>* truths,
                     std::vector<std::string>* verdicts) {
  for (const std::string& effect : suite.effects) {
    AppendOnce(truths, effect);
    AppendOnce(verdicts, effect);
  }
  for (const auto& [truth, counts] : suite.confusion) {
    AppendOnce(truths, truth);
    for (const auto& [verdict, count] : counts) AppendOnce(verdicts, verdict);
  }
}

// How many cases of `truth` got `verdict`: 0 when the matrix has no entry.
int CaseCount(const DiagnosisSuite& suite, const std::string& truth, const std::string& verdict) {
  const auto row = suite.confusion.find(truth);
  if (row == suite.confusion.end()) return 0;
  const auto cell = row->second.find(verdict);
  return cell == row->second.end() ? 0 : cell->second;
}

// The confusion table; the heat map's cells.
HeatMapOptions ConfusionSection(const DiagnosisSuite& suite, Page* page) {
  HeatMapOptions map;
  ConfusionLabels(suite, &map.rows, &map.columns);
  std::vector<Row> rows;
  for (const std::string& truth : map.rows) {
    map.values.emplace_back();
    rows.push_back({TextCell(truth)});
    for (const std::string& verdict : map.columns) {
      const int count = CaseCount(suite, truth, verdict);
      map.values.back().push_back(count);
      rows.back().push_back(NumberCell(count, "%.0f"));
      map.high = std::max(map.high, static_cast<double>(count));
    }
  }
  std::vector<std::string> head = {"truth \\ verdict"};
  head.insert(head.end(), map.columns.begin(), map.columns.end());
  page->Heading("Confusion");
  page->Table(head, rows);
  return map;
}

void CasesSection(const DiagnosisSuite& suite, Page* page) {
  std::vector<Row> rows;
  for (const DiagnosisCase& diagnosis_case : suite.cases) {
    std::vector<std::string> speeds;
    for (double v : diagnosis_case.speeds_m_s) speeds.push_back(Format(v, "%g"));
    rows.push_back({TextCell(diagnosis_case.name), TextCell(diagnosis_case.truth),
                    ListCell(speeds), NumberCell(diagnosis_case.shift),
                    NumberCell(diagnosis_case.value), TextCell(diagnosis_case.verdict),
                    ListCell(diagnosis_case.indistinguishable),
                    TextCell(diagnosis_case.verdict_from_truth),
                    YesNoCell(diagnosis_case.same_as_from_truth),
                    NumberCell(diagnosis_case.gap_p_value, "%.3g"),
                    YesNoCell(diagnosis_case.correct), YesNoCell(diagnosis_case.absorbed_explained),
                    NumberCell(diagnosis_case.seconds, "%.2f")});
  }
  page->Heading("Cases");
  page->Note("Each case diagnosed from initial values scattered within a factor " +
             Format(suite.start_factor, "%g") + " of the truth, and again from the truth.");
  page->Table({"case", "truth", "speeds (m/s)", "shift", "value", "verdict", "indistinguishable",
               "verdict from the truth", "same", "gap p-value", "correct",
               "absorbed and explained", "seconds"},
              rows);
}

}  // namespace

void BenchPaperPage(const BenchPaperReport& report, Page* page) {
  Table1Section(report.body, page);
  const FrequencyFigureOptions frequencies = Table3Section(report.body, page);
  page->Heading("Figures");
  if (auto figure = FrequencyFigure(frequencies)) {
    figure->caption =
        "Table 3 of the paper reproduced from its Table 2 parameters. Left: the paper's and the "
        "model's frequency per mode, in Hz. Right: model − paper, in Hz, against ± 0.05 Hz, "
        "the rounding of the paper's table.";
    page->AddFigure(std::move(*figure));
  }
}

void BenchSyntheticPage(const BenchSyntheticReport& report, Page* page) {
  const SyntheticSuite& suite = report.body;
  std::vector<std::string> free_names;
  for (Param param : suite.free) free_names.push_back(ToString(param));
  page->Summary({{"95 % coverage, all tires (%)", PercentCell(suite.coverage_95)},
                 {"free parameters", ListCell(free_names)},
                 {"frequency noise (relative sd)", NumberCell(suite.frequency_noise)},
                 {"damping noise (relative sd)", NumberCell(suite.damping_noise)},
                 {"shape noise (sd)", NumberCell(suite.shape_noise)}});
  const CoverageSeries coverage = TiresSection(suite, page);
  page->Heading("Figures");
  CoverageFigure(coverage, page);
}

void BenchConditioningPage(const BenchConditioningReport& report, Page* page) {
  const Conditioning conditioning = VariantsSection(report.body, page);
  page->Heading("Figures");
  ConditioningFigure(conditioning, page);
}

void BenchDiagnosisPage(const BenchDiagnosisReport& report, Page* page) {
  const DiagnosisSuite& suite = report.body;
  page->Summary({{"cases", NumberCell(static_cast<double>(suite.cases.size()), "%.0f")},
                 {"accuracy (%)", PercentCell(suite.accuracy)},
                 {"wrong", NumberCell(suite.wrong, "%.0f")},
                 {"initial values within a factor of the truth", NumberCell(suite.start_factor, "%g")},
                 {"verdicts that differ from those started at the truth",
                  NumberCell(suite.differ_from_truth_start, "%.0f")},
                 {"false alarms", NumberCell(suite.false_alarms, "%.0f")},
                 {"no-effect cases", NumberCell(suite.no_effect_cases, "%.0f")},
                 {"named", NumberCell(suite.named, "%.0f")},
                 {"absorbed and explained", NumberCell(suite.absorbed_and_explained, "%.0f")},
                 {"mean shrink when named (%)", PercentCell(suite.mean_shrink_when_named)},
                 {"seconds per diagnosis", NumberCell(suite.seconds_per_diagnosis)}});
  HeatMapOptions map = ConfusionSection(suite, page);
  CasesSection(suite, page);
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
  Figure figure = HeatMap(map);
  figure.caption =
      "Confusion matrix of the withheld-effect validation: number of cases per withheld "
      "effect (row) and verdict (column); the diagonal is a named effect.";
  page->AddFigure(std::move(figure));
}

void CoverageSeries::Add(const std::string& name, double coverage_95, long intervals) {
  const double index = static_cast<double>(names.size());
  names.push_back(name);
  const double percent = 100 * coverage_95;
  if (std::isfinite(percent)) {
    observed.Row({index, percent});
    low = std::min(low, percent);
  }
  if (intervals > 0) {
    const double half = 100 * kNormal95 * std::sqrt(0.95 * 0.05 / static_cast<double>(intervals));
    band.Row({index, std::max(0.0, 95 - half), std::min(100.0, 95 + half)});
    low = std::min(low, 95 - half);
  }
}

void DrawCoverage(const CoverageSeries& coverage, double y_low, const std::string& extra,
                  Figure* figure) {
  const std::string red = "lc rgb '" + std::string(kRed) + "'";
  std::ostringstream script;
  script << "set grid ytics\nset key outside below center horizontal\n"
         << "set xrange [-0.5:" << static_cast<double>(coverage.names.size()) - 0.5
         << "]\nset yrange [" << std::floor(y_low - 2) << ":101]\n" << extra
         << "set ylabel 'coverage of the 95 % intervals (%)'\n"
         << HorizontalLine(1, "95", "dt 2 lw 1.5 " + red)
         << "set label 1 'nominal 95 %' at graph 0.01, first 95 left offset 0, 0.7 tc rgb '" << kRed
         << "'\n";
  std::vector<std::string> parts;
  if (!coverage.band.empty()) {
    parts.push_back(figure->AddData(coverage.band) +
                    " using 1:2:(0):($3-$2) with vectors nohead lw 10 lc rgb '#cfcfcf' "
                    "title 'expected spread if the intervals are right (95 %)'");
  }
  parts.push_back(figure->AddData(coverage.observed) +
                  " using 1:2 with points pt 7 ps 1.6 lc rgb '" + kBlue +
                  "' title 'observed coverage'");
  figure->script = script.str() + PlotCommand(parts);
}

}  // namespace ringid::html
