// The page of `ringid bench --suite=speed`: issue 13's targets, a row per
// case with numeric and analytic derivatives side by side, and the times on
// one log axis.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "apps/html/pages.h"
#include "apps/html/text.h"

namespace ringid::html {
namespace {

// A time per call in the unit that reads best: µs below 0.1 ms, ms below 1 s.
Cell TimeCell(std::optional<double> seconds) {
  if (!seconds || !std::isfinite(*seconds)) return NumberCell(std::nullopt);
  if (*seconds < 1e-4) return {Format(1e6 * *seconds, "%#.3g") + " µs", true};
  if (*seconds < 1) return {Format(1e3 * *seconds, "%#.3g") + " ms", true};
  return {Format(*seconds, "%#.3g") + " s", true};
}

Cell TimesCell(std::optional<double> ratio) { return NumberCell(ratio, "%.2f×"); }

Cell MetCell(std::optional<bool> met) { return met ? YesNoCell(*met) : TextCell("–"); }

// Each target: what it bounds, the limit, the figure measured, met.
void TargetsSection(const SpeedSuite& suite, Page* page) {
  std::vector<Row> rows;
  for (const SpeedRow& r : suite.rows) {
    std::optional<double> value;
    double limit = 0;
    if (!suite.Target(r.name, &value, &limit)) continue;
    const bool seconds = r.name == SpeedCase::kIdentifyInPlane;
    rows.push_back({TextCell(SpeedCaseText(r.name)), TextCell(r.target),
                    seconds ? TimeCell(value) : TimesCell(value), MetCell(r.met)});
  }
  page->TableSection("Targets (issue 13)", {"case", "target", "measured", "met"}, rows);
}

void CasesSection(const SpeedSuite& suite, Page* page) {
  std::vector<Row> rows;
  for (const SpeedRow& r : suite.rows) {
    std::optional<double> speedup;
    if (r.numeric_seconds && r.analytic_seconds && *r.analytic_seconds > 0) {
      speedup = *r.numeric_seconds / *r.analytic_seconds;
    }
    rows.push_back({NameCell(r.name), TextCell(SpeedCaseText(r.name)),
                    TimeCell(r.numeric_seconds), TimeCell(r.analytic_seconds),
                    TimesCell(speedup), TextCell(r.target.empty() ? "–" : r.target),
                    MetCell(r.met)});
  }
  page->Heading("Cases");
  page->Table({"case", "what", "numeric", "analytic", "numeric / analytic", "target", "met"},
              rows);
  page->Note("Median time per call over " + std::to_string(suite.batches) +
             " batches, each case and mode about " + Format(suite.seconds_per_case, "%g") +
             " s in all. numeric: central-difference Jacobians (a model evaluation: without "
             "derivatives; the bare solve: Eigen alone); analytic: exact Jacobians (a model "
             "evaluation: with every mode's derivatives). Always both: the provenance's "
             "derivative mode is the flag's, which this suite does not use.");
}

// Numeric and analytic time per case on one log axis, in µs.
void TimesFigure(const SpeedSuite& suite, Page* page) {
  Series numeric, analytic;
  std::vector<std::string> names;
  double low = INFINITY, high = 0;
  for (const SpeedRow& r : suite.rows) {
    const double index = static_cast<double>(names.size());
    names.push_back(Pretty(ToString(r.name)));
    for (auto [seconds, series] : {std::pair{r.numeric_seconds, &numeric},
                                   std::pair{r.analytic_seconds, &analytic}}) {
      if (!seconds || !(*seconds > 0) || !std::isfinite(*seconds)) continue;
      series->Row({1e6 * *seconds, index});
      low = std::min(low, 1e6 * *seconds);
      high = std::max(high, 1e6 * *seconds);
    }
  }
  if (numeric.empty() && analytic.empty()) {
    page->Note("No figure: the report has no time.");
    return;
  }
  low /= 1.5;
  high *= 1.5;
  const int count = static_cast<int>(names.size());
  Figure figure("bench-speed-times", 900, 120 + 34 * count);
  std::ostringstream script;
  script << "set grid xtics\nset key outside below center horizontal\n"
         << "set logscale x\nset xrange [" << low << ":" << high << "]\n"
         << LogTics(low, high) << "set yrange [" << count - 0.5 << ":-0.5]\n"
         << "set ytics noenhanced " << Tics(names) << "\n"
         << "set xlabel 'median time per call (µs, log scale)'\n";
  std::vector<std::string> parts;
  if (!numeric.empty()) {
    parts.push_back(figure.AddData(numeric) + " using 1:2 with points pt 7 ps 1.5 lc rgb '" +
                    kBlue + "' title 'numeric'");
  }
  if (!analytic.empty()) {
    parts.push_back(figure.AddData(analytic) + " using 1:2 with points pt 9 ps 1.6 lc rgb '" +
                    kOrange + "' title 'analytic'");
  }
  figure.script = script.str() + PlotCommand(parts);
  figure.caption =
      "Median time per call of each case, in µs on a log axis: numeric derivatives (for a "
      "model evaluation: none; for the bare solve: Eigen alone) and analytic ones (for a model "
      "evaluation: every mode's derivatives).";
  page->AddFigure(std::move(figure));
}

}  // namespace

void BenchSpeedPage(const BenchSpeedReport& report, Page* page) {
  const SpeedSuite& suite = report.body;
  int targets = 0, met = 0;
  for (const SpeedRow& r : suite.rows) {
    targets += r.met.has_value();
    met += r.met.value_or(false);
  }
  page->Summary(
      {{"targets met", TextCell(std::to_string(met) + " of " + std::to_string(targets))},
       {"model evaluation / bare solve", TimesCell(suite.EvaluationOverBareSolve())},
       {"model evaluation / bare eigenvalues", TimesCell(suite.EvaluationOverBareEigenvalues())},
       {"evaluation with derivatives / without", TimesCell(suite.DerivativesOverEvaluation())},
       {"joint fit, three conditions / standing, numeric",
        TimesCell(suite.JointFitOverStanding(Derivatives::kNumeric))},
       {"joint fit, three conditions / standing, analytic",
        TimesCell(suite.JointFitOverStanding(Derivatives::kAnalytic))},
       {"batches per case and mode", NumberCell(suite.batches, "%.0f")},
       {"seconds per case and mode", NumberCell(suite.seconds_per_case, "%g")},
       {"seconds", NumberCell(suite.seconds, "%.1f")}});
  TargetsSection(suite, page);
  CasesSection(suite, page);
  page->Heading("Figures");
  TimesFigure(suite, page);
}

}  // namespace ringid::html
