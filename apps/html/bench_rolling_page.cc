// The page of `ringid bench --suite=rolling`: the criteria, a row per free
// parameter (classes, coverage, z), and the coverage and classes figures.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

#include "apps/html/pages.h"
#include "apps/html/text.h"
#include "estimation/statistics.h"

namespace ringid::html {
namespace {

std::string Names(const std::vector<Param>& params) {
  std::vector<std::string> names;
  for (Param param : params) names.push_back(ToString(param));
  return names.empty() ? "none" : Join(names, ", ");
}

// What the suite requires and what it measured, one row per criterion.
void CriteriaSection(const RollingSuite& suite, Page* page) {
  std::vector<Row> rows;
  for (Param param : suite.contact) {
    const RollingParameter* r = suite.Find(param);
    std::optional<double> share;
    if (r && suite.replicates > 0) share = static_cast<double>(r->yes) / suite.replicates;
    rows.push_back({TextCell(std::string(ToString(param)) + " classed yes"),
                    TextCell("≥ " + Format(100 * suite.contact_yes_min, "%.1f") +
                             " % of the replicates"),
                    PercentCell(share),
                    YesNoCell(r && suite.replicates > 0 &&
                              r->yes >= suite.contact_yes_min * suite.replicates)});
  }
  int no = 0;
  for (const RollingParameter& r : suite.parameters) no += r.no;
  rows.push_back({TextCell("any parameter classed no"), TextCell("never"),
                  TextCell(std::to_string(no) + " times"), YesNoCell(suite.NeverNo())});
  const auto& [low, high] = suite.coverage_range;
  rows.push_back({TextCell("coverage of all 95 % intervals"),
                  TextCell(Format(100 * low, "%.1f") + " – " + Format(100 * high, "%.1f") + " %"),
                  PercentCell(suite.coverage_95), YesNoCell(suite.CoverageInRange())});
  page->Heading("Criteria");
  page->Table({"criterion", "required", "observed", "met"}, rows);
  page->Note("Each parameter's own coverage is reported below, not a criterion; outside " +
             Format(100 * low, "%.1f") + " – " + Format(100 * high, "%.1f") +
             " %: " + Names(suite.OutsideCoverageRange()) + ".");
}

// The coverage per parameter and the classes per parameter.
struct Coverage {
  CoverageSeries series;
  Series yes, practically_no, no;  // stacked bars of the classes
  int replicates = 0;
};

Coverage ParametersSection(const RollingSuite& suite, Page* page) {
  Coverage coverage;
  coverage.replicates = suite.replicates;
  std::vector<Row> rows;
  for (const RollingParameter& r : suite.parameters) {
    rows.push_back({NameCell(r.param), NumberCell(r.truth), NumberCell(r.yes, "%.0f"),
                    NumberCell(r.practically_no, "%.0f"), NumberCell(r.no, "%.0f"),
                    NumberCell(static_cast<double>(r.intervals), "%.0f"),
                    PercentCell(r.coverage_95), NumberCell(r.mean_z, "%+.3f"),
                    NumberCell(r.rms_z, "%.3f")});
    const double index = static_cast<double>(coverage.series.names.size());
    coverage.series.Add(ToString(r.param), r.coverage_95, r.intervals);
    const double yes = r.yes, practically_no = yes + r.practically_no,
                 no = practically_no + r.no;
    coverage.yes.Row({index, 0, yes});
    coverage.practically_no.Row({index, yes, practically_no});
    coverage.no.Row({index, practically_no, no});
  }
  page->Heading("Parameters");
  page->Table({"parameter", "truth", ToString(Identifiability::kYes),
               ToString(Identifiability::kPracticallyNo), ToString(Identifiability::kNo),
               "intervals", "95 % coverage (%)", "mean z", "rms z"},
              rows);
  page->Note("z = log(estimate / truth) / (std / estimate), the error in units of the "
             "log-space std (linear for a parameter that is not positive): its mean shows a "
             "bias, its rms is 1 when the std is right.");
  return coverage;
}

void CoverageFigure(const RollingSuite& suite, const CoverageSeries& coverage, Page* page) {
  if (coverage.observed.empty()) {
    page->Note("No coverage figure: no parameter has an interval.");
    return;
  }
  Figure figure("bench-rolling-coverage", 900, 420);
  const auto& [low, high] = suite.coverage_range;
  DrawCoverage(coverage, std::min(coverage.low, 100 * low),
               CategoryXTics(coverage.names, figure.width - 150.0, -35) +
                   HorizontalLine(2, Format(100 * low, "%g"), kDashedGrey) +
                   HorizontalLine(3, Format(100 * high, "%g"), kDashedGrey),
               &figure);
  figure.caption =
      "Monte Carlo coverage of the 95 % intervals per free parameter, in %. Grey bars: the "
      "binomial 95 % range of the observed coverage around 95 % for that parameter's number "
      "of intervals; dashed grey lines: the range the suite requires of all intervals "
      "together (" + Format(100 * low, "%g") + " – " + Format(100 * high, "%g") + " %).";
  page->AddFigure(std::move(figure));
}

void ClassFigure(const Coverage& coverage, Page* page) {
  const std::vector<std::string>& names = coverage.series.names;
  if (names.empty()) {
    page->Note("No class figure: the report has no free parameter.");
    return;
  }
  const int count = static_cast<int>(names.size());
  Figure figure("bench-rolling-classes", 760, 110 + 26 * count);
  std::ostringstream script;
  script << "set style fill solid 0.85 noborder\nset grid xtics\n"
         << "set key outside below center horizontal\n"
         << "set yrange [" << count - 0.5 << ":-0.5]\nset xrange [0:"
         << std::max(coverage.replicates, 1) << "]\n"
         << "set ytics noenhanced " << Tics(names) << "\n"
         << "set xlabel 'replicates by identifiability class'\n";
  std::vector<std::string> parts;
  for (auto [series, color, title] :
       {std::tuple<const Series*, const char*, const char*>{&coverage.yes, kBlue, "yes"},
        {&coverage.practically_no, kOrange, "practically_no"},
        {&coverage.no, kGrey, "no"}}) {
    if (!series->empty())
      parts.push_back(HorizontalBars(figure.AddData(*series), color) + " title " +
                      GnuplotString(title));
  }
  figure.script = script.str() + PlotCommand(parts);
  figure.caption =
      "How each free parameter was classed over the replicates: yes, practically_no or no "
      "(a failed fit classes nothing).";
  page->AddFigure(std::move(figure));
}

}  // namespace

void BenchRollingPage(const BenchRollingReport& report, Page* page) {
  const RollingSuite& suite = report.body;
  std::vector<std::string> speeds, ties;
  for (double v : suite.speeds_m_s) speeds.push_back(Format(v, "%g"));
  for (const auto& [tied, to] : suite.ties) {
    ties.push_back(std::string(ToString(tied)) + " → " + ToString(to));
  }
  page->Summary({{"pass", YesNoCell(suite.Pass())},
                 {"95 % coverage, all parameters (%)", PercentCell(suite.coverage_95)},
                 {"intervals", NumberCell(static_cast<double>(suite.intervals), "%.0f")},
                 {"replicates", NumberCell(suite.replicates, "%.0f")},
                 {"failed fits", NumberCell(suite.failed_fits, "%.0f")},
                 {"tire", TextCell(suite.tire)},
                 {"speeds (m/s)", ListCell(speeds)},
                 {"ties", ListCell(ties)},
                 {"frequency noise (relative sd)", NumberCell(suite.frequency_noise)},
                 {"damping noise (relative sd)", NumberCell(suite.damping_noise)},
                 {"shape noise (sd)", NumberCell(suite.shape_noise)},
                 {"seconds", NumberCell(suite.seconds, "%.1f")},
                 {"seconds per fit", NumberCell(suite.seconds_per_fit, "%.3f")}});
  CriteriaSection(suite, page);
  const Coverage coverage = ParametersSection(suite, page);
  page->Heading("Figures");
  CoverageFigure(suite, coverage.series, page);
  ClassFigure(coverage, page);
}

}  // namespace ringid::html
