// The page of `ringid predict`: the modes of a parameter set; with
// --speeds, the Campbell diagram with the lug orders and the critical speeds.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "apps/html/pages.h"
#include "apps/html/text.h"

namespace ringid::html {
namespace {

void Campbell(const PredictBody& r, Page* page) {
  if (!r.speeds || r.speeds->size() < 2) return;
  Figure figure("predict-campbell", 900, 460);
  const char* colors[] = {kBlue, kOrange, kGreen, kRed, "#9467bd", "#8c564b", "#e377c2"};
  std::vector<std::string> parts;
  double top = 0, fastest = 0;
  int color = 0;
  for (const PredictedMode& m : r.modes) {
    Series s;
    for (const SpeedModes& at : *r.speeds) {
      const auto it = at.modes.find(m.label);
      if (it == at.modes.end()) continue;
      s.Row({at.speed_m_s, it->second.first});
      top = std::max(top, it->second.first);
      fastest = std::max(fastest, at.speed_m_s);
    }
    if (s.empty()) continue;
    parts.push_back(figure.AddData(s) + " using 1:2 with linespoints pt 7 ps 0.6 lw 2 lc rgb '" +
                    colors[color++ % 7] + "' title " + GnuplotString(Pretty(ToString(m.label))));
  }
  if (parts.empty()) return;
  top *= 1.15;
  if (r.lugs_per_revolution && r.r_e0) {
    // The orders that meet a mode (at least the first) as lines through the
    // origin, up to the top of the graph.
    int highest = 1;
    for (const CriticalSpeed& c : r.critical_speeds.value_or(std::vector<CriticalSpeed>{})) {
      highest = std::max(highest, c.order);
    }
    Series orders;
    for (int k = 1; k <= std::min(highest, 50); ++k) {
      const double slope = LugOrderHz(k, *r.lugs_per_revolution, *r.r_e0, 1.0);
      if (!(slope > 0)) break;
      const double v_top = std::min(fastest, top / slope);
      orders.Row({0.0, 0.0});
      orders.Row({v_top, slope * v_top});
      orders.Break();
    }
    parts.push_back(figure.AddData(orders) + " using 1:2 with lines dt 2 lc rgb '#888888' "
                    "title 'lug orders'");
    Series critical;
    for (const CriticalSpeed& c : r.critical_speeds.value_or(std::vector<CriticalSpeed>{})) {
      critical.Row({c.speed_m_s, c.frequency_hz});
    }
    if (!critical.empty()) {
      parts.push_back(figure.AddData(critical) +
                      " using 1:2 with points pt 6 ps 1.8 lw 2 lc rgb '#000000' title 'critical speeds'");
    }
  }
  std::ostringstream script;
  script << "set grid\nset key outside below center horizontal\nset xlabel 'speed (m/s)'\n"
         << "set ylabel 'frequency (Hz)'\nset xrange [0:" << fastest << "]\nset yrange [0:" << top
         << "]\n";
  figure.script = script.str() + PlotCommand(parts);
  figure.caption = "Campbell diagram: each mode's damped frequency against the drum speed" +
                   std::string(r.lugs_per_revolution
                                   ? "; dashed, the lug orders k lugs V / (2 pi r_e0) (" +
                                         std::to_string(*r.lugs_per_revolution) +
                                         " lugs); circles, the critical speeds where an order "
                                         "meets a mode"
                                   : "") +
                   ".";
  page->AddFigure(std::move(figure));
}

}  // namespace

void PredictPage(const PredictReport& report, Page* page) {
  const PredictBody& r = report.body;
  std::vector<std::string> overdamped;
  for (ModeLabel label : r.overdamped) overdamped.push_back(ToString(label));
  page->Summary({{"status", NameCell(r.status.outcome)},
                 {"message", TextCell(r.status.message)},
                 {"overdamped (no oscillating mode)", ListCell(overdamped)}});
  std::vector<Row> rows;
  for (const PredictedMode& m : r.modes) {
    rows.push_back({NameCell(m.label), NameCell(LabelPlane(m.label)), NumberCell(m.model_hz, "%.3f"),
                    NumberCell(m.damping_ratio), NumberCell(m.label_energy_share, "%.3f")});
  }
  if (r.parameter_notes && !r.parameter_notes->empty()) {
    page->Heading("Where the parameters came from");
    for (const std::string& note : *r.parameter_notes) page->Note(note);
  }
  page->TableSection(
      "Modes",
      {"mode", "plane", "frequency (Hz)", "damping ratio", "energy share of the label's element"},
      rows);
  if (r.conditions) {
    std::vector<Row> by_condition;
    for (const SpeedModes& c : *r.conditions) {
      for (const auto& [label, mode] : c.modes) {
        by_condition.push_back({TextCell(c.condition.value_or("")), NumberCell(c.speed_m_s, "%.3g"),
                                NameCell(label), NumberCell(mode.first, "%.3f"),
                                NumberCell(mode.second)});
      }
    }
    page->TableSection("Modes by condition",
                       {"condition", "speed (m/s)", "mode", "frequency (Hz)", "damping ratio"},
                       by_condition);
  }
  Campbell(r, page);
  std::vector<Row> critical;
  for (const CriticalSpeed& c : r.critical_speeds.value_or(std::vector<CriticalSpeed>{})) {
    critical.push_back({NumberCell(c.order, "%.0f"), NameCell(c.label),
                        NumberCell(c.speed_m_s, "%.3f"), NumberCell(c.frequency_hz, "%.2f"),
                        NumberCell(c.damping_ratio, "%.4f")});
  }
  page->TableSection("Critical speeds: where a lug order meets a mode",
                     {"order", "mode", "speed (m/s)", "frequency (Hz)", "damping ratio there"},
                     critical);
  if (r.lug_excitation) {
    page->Heading("Lug excitation");
    if (r.lug_profile) {
      const ObstacleProfileFields& l = *r.lug_profile;
      page->Facts({{"lug height (m)", NumberCell(l.height_m, "%.4g")},
                   {"lug length (m)", NumberCell(l.length_m, "%.4g")},
                   {"pitch (m)", NumberCell(l.pitch_m, "%.4g")},
                   {"tread width (m)", NumberCell(l.width_m, "%.4g")},
                   {"angle (deg)", NumberCell(l.angle_deg, "%.4g")},
                   {"pattern", TextCell(l.pattern ? ToString(*l.pattern) : "")}});
    }
    std::vector<std::string> head = {"speed (m/s)", "order", "frequency (Hz)", "|F_x| (N)",
                                     "|F_z| (N)", "|F_y| (N)"};
    for (int c = 0; c < kNumTimeOutputs; ++c) head.push_back(std::string("|") + TimeOutputName(c) + "|");
    std::vector<Row> means, rows;
    for (const LugExcitation& e : *r.lug_excitation) {
      const std::array<double, 3> mean = ShownMeans(e);
      means.push_back({NumberCell(e.speed_m_s, "%.3g"), NumberCell(mean[0], "%.4g"),
                       NumberCell(mean[1], "%.4g"), NumberCell(mean[2], "%.4g")});
      const auto shown = ShownAmplitudes(e);
      for (size_t k = 0; k < e.orders.size(); ++k) {
        Row row = {NumberCell(e.speed_m_s, "%.3g"), NumberCell(e.orders[k].order, "%.0f"),
                   NumberCell(e.orders[k].frequency_hz, "%.2f")};
        for (double a : shown[k]) row.push_back(NumberCell(a, "%.4g"));
        rows.push_back(std::move(row));
      }
    }
    page->TableSection("Mean forces: a static offset, apart from the orders",
                       {"speed (m/s)", "F_x (N)", "F_z (N)", "F_y (N)"}, means);
    page->TableSection("The forces of each lug order on the ring, and the axle's response (N, "
                       "N m; rim_speed rad/s; below 1e-9 of a column's largest: 0, round-off)",
                       head, rows);
  }
}

void ProvenanceSection(const Provenance& p, Page* page) {
  std::string command;
  for (const std::string& arg : p.command_line) command += (command.empty() ? "" : " ") + arg;
  page->Heading("Provenance");
  page->Facts({{"ringid version", TextCell(p.ringid_version)},
               {"command line", TextCell(command)},
               {"seed", NumberCell(p.seed ? std::optional<double>(*p.seed) : std::nullopt, "%.0f")},
               {"derivatives", TextCell(ToString(p.derivatives))}});
  std::vector<Row> rows;
  for (const InputFile& f : p.inputs) {
    rows.push_back({TextCell(f.role), TextCell(f.path), TextCell(f.sha256.empty() ? "–" : f.sha256)});
  }
  page->Table({"input", "path", "SHA-256"}, rows);
}

}  // namespace ringid::html
