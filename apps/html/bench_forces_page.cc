// The page of `ringid bench --suite=forces`: each method's accuracy and the
// coverage of the intervals, with a figure of the coverage.
#include <sstream>

#include "apps/html/pages.h"
#include "apps/html/text.h"

namespace ringid::html {
namespace {

void CoverageFigure(const ForcesSuite& s, Page* page) {
  const ForcesMethodRow* truth = s.Find(ForcesMethod::kTrueParameters);
  const ForcesMethodRow* fit = s.Find(ForcesMethod::kIdentified);
  if (!truth || !fit || !fit->coverage_total) {
    page->Note("No coverage figure: no intervals were made.");
    return;
  }
  Figure figure("bench-forces-coverage", 900, 400);
  Series total, measurement;
  const auto row = [](Series* series, double x, const std::optional<double>& v) {
    if (v) series->Row({x, 100 * *v});
  };
  row(&total, 0, truth->coverage_total);
  row(&total, 1, fit->coverage_total);
  row(&total, 2, fit->coverage_total_at_resonance);
  row(&measurement, 0, truth->coverage_measurement);
  row(&measurement, 1, fit->coverage_measurement);
  row(&measurement, 2, fit->coverage_measurement_at_resonance);
  const std::vector<std::string> names = {"true parameters", "identified", "identified, on the resonance"};
  std::ostringstream script;
  script << "set grid ytics\nset key outside below center horizontal\nset xrange [-0.5:2.5]\n"
         << "set yrange [" << std::min(80.0, 100 * fit->coverage_measurement.value_or(1) - 3)
         << ":101]\n" << CategoryXTics(names, figure.width - 150.0, 0)
         << "set ylabel 'coverage of the 95 % intervals (%)'\n"
         << HorizontalLine(1, "95", std::string("dt 2 lw 1.5 lc rgb '") + kRed + "'")
         << HorizontalLine(2, Format(100 * s.coverage_range.first, "%g"), kDashedGrey)
         << HorizontalLine(3, Format(100 * s.coverage_range.second, "%g"), kDashedGrey);
  figure.script = script.str() +
                  PlotCommand({figure.AddData(total) + " using 1:2 with points pt 7 ps 2 lc rgb '" +
                                   kBlue + "' title 'std_total'",
                               figure.AddData(measurement) +
                                   " using 1:2 with points pt 5 ps 1.6 lc rgb '" + kOrange +
                                   "' title 'std_measurement'"});
  figure.caption = "Share of the re and im 95 % intervals of every force and order that hold the "
                   "true force, in %: with the true parameters, with the identified ones, and at "
                   "the order on the vertical resonance. Red dashed: 95 %; grey dashed: the range "
                   "the suite requires of std_total.";
  page->AddFigure(std::move(figure));
}

}  // namespace

void BenchForcesPage(const BenchForcesReport& report, Page* page) {
  const ForcesSuite& s = report.body;
  std::vector<std::string> speeds;
  for (double v : s.speeds_m_s) speeds.push_back(Format(v, "%.3g"));
  page->Summary({{"pass", YesNoCell(s.Pass())},
                 {"tire", TextCell(s.tire)},
                 {"speeds (m/s)", ListCell(speeds)},
                 {"order 1 on the vertical mode at (m/s)", NumberCell(s.resonance_speed_m_s, "%.3f")},
                 {"lugs per revolution", NumberCell(s.lugs_per_revolution, "%.0f")},
                 {"orders", NumberCell(s.orders, "%.0f")},
                 {"replicates", NumberCell(s.replicates, "%.0f")},
                 {"response noise (of |Y|, re and im each)", NumberCell(s.response_noise, "%.4f")},
                 {"failed identifications", NumberCell(s.failed_fits, "%.0f")},
                 {"seconds", NumberCell(s.seconds, "%.1f")}});
  page->Facts({{"unbiased with the true parameters", YesNoCell(s.Unbiased())},
               {"std_measurement right with the true parameters", YesNoCell(s.StdIsRight())},
               {"std_total covers with identified parameters", YesNoCell(s.TotalCovers())},
               {"std_measurement alone under-covers", YesNoCell(s.MeasurementUnderCovers())}});
  std::vector<Row> rows;
  for (const ForcesMethodRow& m : s.methods) {
    rows.push_back({NameCell(m.method), NumberCell(static_cast<double>(m.estimates), "%.0f"),
                    PercentCell(m.bias_max), PercentCell(m.rms_error), PercentCell(m.median_error),
                    NumberCell(m.rms_z_measurement, "%.3f"), PercentCell(m.coverage_total),
                    PercentCell(m.coverage_measurement), PercentCell(m.coverage_total_at_resonance),
                    PercentCell(m.coverage_measurement_at_resonance)});
  }
  page->TableSection("Methods",
                     {"method", "estimates", "largest bias (%)", "rms error (%)", "median error (%)",
                      "rms z", "coverage, std_total (%)", "coverage, std_measurement (%)",
                      "on the resonance, std_total (%)", "on the resonance, std_measurement (%)"},
                     rows);
  page->Heading("Figures");
  CoverageFigure(s, page);
}

}  // namespace ringid::html
