// The page of `ringid forces`: the lug forces per condition and order, with
// their 95 % intervals (std_total), and a spectrum per force.
#include <cmath>
#include <sstream>

#include "apps/html/pages.h"
#include "apps/html/text.h"

namespace ringid::html {
namespace {

// |F| against frequency, one series per condition, per force: the bars are
// |F| ± 1.96 std_total.
void Spectrum(const ForcesResult& r, LugForce force, Page* page) {
  Figure figure(std::string("forces-") + ToString(force), 900, 380);
  const char* colors[] = {kBlue, kOrange, kGreen, kRed, kGrey};
  std::vector<std::string> parts;
  for (size_t c = 0; c < r.conditions.size(); ++c) {
    Series s;
    for (const OrderForces& of : r.conditions[c].orders) {
      const auto e = of.forces.find(force);
      if (e == of.forces.end()) continue;
      s.Row({of.frequency_hz, std::abs(e->second.value), 1.96 * e->second.std_total});
    }
    if (s.empty()) continue;
    parts.push_back(figure.AddData(s) + " using 1:2:3 with yerrorbars pt 7 ps 1.2 lc rgb '" +
                    colors[c % 5] + "' title " +
                    GnuplotString(r.conditions[c].name + " (" +
                                  Format(r.conditions[c].speed_m_s, "%g") + " m/s)"));
  }
  if (parts.empty()) return;
  std::ostringstream script;
  script << "set grid\nset key outside below center horizontal\nset xlabel 'frequency (Hz)'\n"
         << "set ylabel '|" << ToString(force) << "| (N)'\nset offsets graph 0.03, graph 0.03, "
         << "graph 0.05, 0\n";
  figure.script = script.str() + PlotCommand(parts);
  figure.caption = std::string("|") + ToString(force) +
                   "| at each lug order against its frequency, per condition; bars: the 95 % "
                   "interval of |F| from std_total (measurement and parameters).";
  page->AddFigure(std::move(figure));
}

}  // namespace

void ForcesPage(const ForcesReport& report, Page* page) {
  const ForcesResult& r = report.body.result;
  page->Summary({{"status", NameCell(r.status.outcome)},
                 {"message", TextCell(r.status.message)},
                 {"lugs per revolution", NumberCell(r.lugs_per_revolution, "%.0f")},
                 {"parameters", TextCell(r.parameters)},
                 {"condition number limit (a force beyond it is not determined)", NumberCell(r.max_condition_number, "%.3g")}});
  for (LugForce f : {LugForce::kFx, LugForce::kFz, LugForce::kFy}) Spectrum(r, f, page);
  std::vector<Row> rows;
  for (const ConditionForces& c : r.conditions) {
    for (const OrderForces& of : c.orders) {
      for (const auto& [force, e] : of.forces) {
        rows.push_back({TextCell(c.name), NumberCell(of.order, "%.0f"),
                        NumberCell(of.frequency_hz, "%.2f"), NameCell(force),
                        NumberCell(e.value.real(), "%.4g"), NumberCell(e.value.imag(), "%.4g"),
                        NumberCell(std::abs(e.value), "%.4g"),
                        NumberCell(e.std_measurement, "%.3g"), NumberCell(e.std_total, "%.3g"),
                        NumberCell(of.condition_number, "%.3g"),
                        NumberCell(of.chi_square, "%.3g")});
      }
      for (const auto& [force, why] : of.undetermined) {
        rows.push_back({TextCell(c.name), NumberCell(of.order, "%.0f"),
                        NumberCell(of.frequency_hz, "%.2f"), NameCell(force),
                        TextCell("not determined: " + why)});
      }
    }
  }
  page->TableSection("Forces by condition and order",
                     {"condition", "order", "Hz", "force", "re (N)", "im (N)", "|F| (N)",
                      "std measurement", "std total", "condition number", "chi-square"},
                     rows);
}

}  // namespace ringid::html
