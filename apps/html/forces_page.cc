// The page of `ringid forces`: the lug forces per condition and order, with
// their 95 % intervals (std_total), and a spectrum per force.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "apps/html/pages.h"
#include "apps/html/text.h"
#include "estimation/statistics.h"

namespace ringid::html {
namespace {

// |F| against frequency, one series per condition, per force: the bars are
// |F| ± kNormal95 std_total; a dashed line where the condition's model range
// ends.
void Spectrum(const ForcesResult& r, LugForce force, Page* page) {
  Figure figure(std::string("forces-") + ToString(force), 900, 380);
  const char* colors[] = {kBlue, kOrange, kGreen, kRed, kGrey};
  std::vector<std::string> parts;
  std::ostringstream limits;
  double right = 0;  // the x range holds every order and every limit
  for (size_t c = 0; c < r.conditions.size(); ++c) {
    const double limit = r.conditions[c].model_valid_below_hz;
    if (std::isfinite(limit)) {
      limits << "set arrow from " << limit << ", graph 0 to " << limit
             << ", graph 1 nohead dt 2 lw 1.5 lc rgb '" << colors[c % 5] << "'\n";
      right = std::max(right, limit);
    }
    Series s;
    for (const OrderForces& of : r.conditions[c].orders) {
      const auto e = of.forces.find(force);
      if (e == of.forces.end()) continue;
      s.Row({of.frequency_hz, std::abs(e->second.value), kNormal95 * e->second.std_total});
      right = std::max(right, of.frequency_hz);
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
         << "graph 0.05, 0\nset xrange [0:" << 1.05 * right << "]\n" << limits.str();
  figure.script = script.str() + PlotCommand(parts);
  figure.caption = std::string("|") + ToString(force) +
                   "| at each lug order against its frequency, per condition; bars: the 95 % "
                   "interval of |F| from std_total (measurement and parameters); dashed: the "
                   "condition's model_valid_below_hz, above which the rigid ring does not "
                   "describe the tire (docs/forces.md §3).";
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
  std::vector<Row> conditions;
  for (const ConditionForces& c : r.conditions) {
    std::vector<std::string> above;
    for (const OrderForces& of : c.orders) {
      if (of.above_model_range) above.push_back(std::to_string(of.order));
    }
    conditions.push_back({TextCell(c.name), NumberCell(c.speed_m_s, "%g"),
                          NumberCell(c.f_lug_hz, "%.4g"), NumberCell(c.model_valid_below_hz, "%.4g"),
                          ListCell(above)});
  }
  page->TableSection("Conditions (the rigid ring holds below model_valid_below_hz: docs/forces.md §3)",
                     {"condition", "speed (m/s)", "f_lug (Hz)", "model valid below (Hz)",
                      "orders above it"},
                     conditions);
  for (LugForce f : {LugForce::kFx, LugForce::kFz, LugForce::kFy}) Spectrum(r, f, page);
  std::vector<Row> rows;
  for (const ConditionForces& c : r.conditions) {
    for (const OrderForces& of : c.orders) {
      const Cell range = TextCell(of.above_model_range ? "above" : "within");
      for (const auto& [force, e] : of.forces) {
        rows.push_back({TextCell(c.name), NumberCell(of.order, "%.0f"),
                        NumberCell(of.frequency_hz, "%.2f"), range, NameCell(force),
                        NumberCell(e.value.real(), "%.4g"), NumberCell(e.value.imag(), "%.4g"),
                        NumberCell(std::abs(e.value), "%.4g"),
                        NumberCell(e.std_measurement, "%.3g"), NumberCell(e.std_total, "%.3g"),
                        NumberCell(of.condition_number, "%.3g"),
                        NumberCell(of.chi_square, "%.3g")});
      }
      for (const auto& [force, u] : of.undetermined) {
        rows.push_back({TextCell(c.name), NumberCell(of.order, "%.0f"),
                        NumberCell(of.frequency_hz, "%.2f"), range, NameCell(force),
                        TextCell("not determined: " + u.why)});
      }
    }
  }
  page->TableSection("Forces by condition and order",
                     {"condition", "order", "Hz", "model range", "force", "re (N)", "im (N)", "|F| (N)",
                      "std measurement", "std total", "condition number", "chi-square"},
                     rows);
}

}  // namespace ringid::html
