// The page of `ringid identify`: fit summary, modes, parameters, and the
// frequency, MAC and interval figures.
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "apps/html/pages.h"
#include "apps/html/text.h"
#include "estimation/statistics.h"
#include "model/parameters.h"

namespace ringid::html {
namespace {

// Intervals wider than this factor are cut at the edge of the figure.
constexpr double kClipFactor = 100;

// The relative 95 % intervals of the free parameters that have a std.
struct Intervals {
  std::vector<std::string> names;
  std::vector<std::pair<double, double>> bounds;  // low, high relative to the value
  std::vector<Identifiability> classes;
  std::vector<std::string> clipped;      // cut at kClipFactor
  std::vector<std::string> without_std;  // free, not drawn
};

// The costs of the starts, each as "%.4g".
Cell StartCostsCell(const std::vector<double>& costs) {
  std::vector<std::string> items;
  for (double cost : costs) items.push_back(Format(cost));
  return ListCell(items);
}

FactRows SummaryFacts(const std::string& dataset, const IdentifySummary& s) {
  const Uncertainty& u = s.uncertainty;
  return {{"dataset", TextCell(dataset)},
          {"method", TextCell(MethodTitle(s.method))},
          {"status", NameCell(s.status.outcome)},
          {"converged", YesNoCell(s.converged)},
          {"solver message", TextCell(s.status.message)},
          {"cost (½ Σ weighted residual²)", NumberCell(s.cost)},
          {"evaluations", NumberCell(static_cast<double>(s.evaluations), "%.0f")},
          {"starts", NumberCell(s.starts, "%.0f")},
          {"final cost per start", StartCostsCell(s.start_costs)},
          {"seconds", NumberCell(s.seconds)},
          {"frequency weighting", NameCell(s.frequency_weighting)},
          {"relative error, in-plane (eq. 19)", NumberCell(s.relative_error_in_plane)},
          {"relative error, out-of-plane (eq. 20)", NumberCell(s.relative_error_out_of_plane)},
          {"covariance computed", YesNoCell(u.covariance_ok)},
          {"covariance error", TextCell(u.covariance_error.empty() ? "–" : u.covariance_error)},
          {"rank of the weighted Jacobian", NumberCell(u.rank, "%.0f")},
          {"condition number", NumberCell(u.condition_number)}};
}

// The modes table; the frequencies for the figure.
FrequencyFigureOptions ModesSection(const std::vector<ModeFit>& modes, Page* page) {
  FrequencyFigureOptions figure;
  figure.name = "identify-frequencies";
  figure.reference_title = "measured ± 1σ";
  figure.band_title = "± 1σ of the measurement";
  figure.reference_name = "measured";
  std::vector<Row> rows;
  for (const ModeFit& m : modes) {
    const double difference = m.model_hz - m.measured_hz;
    std::optional<double> z;
    if (m.measured_sigma_hz > 0) z = difference / m.measured_sigma_hz;
    rows.push_back({NameCell(m.label), NameCell(m.model_label), NumberCell(m.measured_hz, "%.3f"),
                    NumberCell(m.measured_sigma_hz, "%.3g"), NumberCell(m.model_hz, "%.3f"),
                    NumberCell(difference, "%.3g"), NumberCell(z, "%.3g"),
                    NumberCell(m.measured_damping), NumberCell(m.model_damping),
                    NumberCell(m.mac, "%.3f")});
    figure.AddMode(ToString(m.label), m.measured_hz, m.measured_sigma_hz, m.model_hz);
  }
  page->Heading("Modes");
  page->Table(
      {"mode", "model mode", "measured (Hz)", "σ (Hz)", "model (Hz)", "model − measured (Hz)",
       "(model − measured) / σ", "measured damping ratio", "model damping ratio", "MAC"},
      rows);
  return figure;
}

Cell FactorCell(std::optional<double> factor) {
  if (!factor) return {"–", true};
  return {*factor > 1e6 ? "> 10⁶" : "× ÷ " + Format(*factor, "%.3g"), true};
}

// One parameter's row; its interval when it is free and has a std.
Row ParameterRow(const ParameterEstimate& q, Intervals* intervals) {
  const std::string name = q.key.Text();
  std::string role = q.free ? "free" : "fixed";
  if (q.tied_to) role = std::string("tied to ") + ToString(*q.tied_to);
  const bool has_std = q.std && std::isfinite(*q.std);
  std::optional<double> factor;
  if (q.free && has_std && std::isfinite(q.value) && q.value != 0) {
    double z = kNormal95 * std::fabs(*q.std / q.value);
    factor = std::exp(std::min(z, 700.0));
    if (z > std::log(kClipFactor)) {
      z = std::log(kClipFactor);
      intervals->clipped.push_back(name);
    }
    intervals->names.push_back(name);
    intervals->bounds.push_back({std::exp(-z), std::exp(z)});
    intervals->classes.push_back(q.identifiable);
  } else if (q.free) {
    intervals->without_std.push_back(name);
  }
  return {TextCell(name),
          NumberCell(q.value),
          TextCell(Info(q.param()).unit),
          TextCell(role),
          NumberCell(q.std),
          FactorCell(factor),
          NameCell(q.identifiable),
          TextCell(q.reason)};
}

Intervals ParametersSection(const std::vector<ParameterEstimate>& estimates, Page* page) {
  Intervals intervals;
  std::vector<Row> rows;
  for (const ParameterEstimate& q : estimates) rows.push_back(ParameterRow(q, &intervals));
  page->Heading("Parameters");
  page->Table({"parameter", "value", "unit", "role", "std", "95 % interval (factor)",
               "identifiable", "reason"},
              rows);
  return intervals;
}

// MAC of the measured shapes against every model shape.
void MacFigure(const std::vector<ModeFit>& modes, Page* page) {
  HeatMapOptions map;
  map.name = "identify-mac";
  map.x_label = "model mode";
  map.y_label = "measured mode";
  map.color_label = "MAC";
  std::vector<const ModeFit*> measured;  // the modes with a measured shape
  for (const ModeFit& m : modes) {
    if (!m.mac_all.empty()) measured.push_back(&m);
  }
  if (measured.empty()) {
    page->Note("No MAC figure: the dataset gives no measured mode shape (no mode has a MAC "
               "against the model modes).");
    return;
  }
  // Columns: the paired model modes first, then any other the MACs name.
  std::vector<ModeLabel> columns;
  const auto append_once = [&columns](ModeLabel label) {
    if (std::find(columns.begin(), columns.end(), label) == columns.end()) columns.push_back(label);
  };
  for (const ModeFit& m : modes) append_once(m.model_label);
  for (const ModeFit* m : measured) {
    for (const auto& [label, mac] : m->mac_all) append_once(label);
  }
  for (const ModeFit* m : measured) {
    map.rows.push_back(ToString(m->label));
    map.values.emplace_back();
    for (ModeLabel column : columns) {
      const auto it = m->mac_all.find(column);
      map.values.back().push_back(it == m->mac_all.end() ? std::nullopt
                                                         : std::optional<double>(it->second));
    }
  }
  for (ModeLabel column : columns) map.columns.push_back(ToString(column));
  map.rows = Pretty(map.rows);
  map.columns = Pretty(map.columns);
  Figure f = HeatMap(map);
  f.caption =
      "Modal assurance criterion (MAC, 0 to 1) of each measured mode shape against every "
      "model mode shape; 1 means the same shape.";
  page->AddFigure(std::move(f));
}

std::string IntervalScript(Figure* f, const Intervals& intervals) {
  double low = 0.5, high = 2;
  std::map<Identifiability, Series> by_class;
  for (size_t i = 0; i < intervals.names.size(); ++i) {
    const auto [from, to] = intervals.bounds[i];
    low = std::min(low, from);
    high = std::max(high, to);
    by_class[intervals.classes[i]].Row({static_cast<double>(i), from, to});
  }
  std::ostringstream g;
  g << "set logscale y\nset format y '%g'\nset yrange [" << low / 1.4 << ":" << high * 1.4 << "]\n"
    << "set xrange [-0.7:" << static_cast<double>(intervals.names.size()) - 0.3 << "]\n"
    << CategoryXTics(intervals.names, f->width - 250.0, -35)
    << "set grid ytics\nset ylabel 'interval / value (log scale)'\n"
    << "set key outside right top title 'identifiable' noenhanced\n"
    << HorizontalLine(1, "2", kDashedGrey) << HorizontalLine(2, "0.5", kDashedGrey)
    << HorizontalLine(3, "1", "lc rgb '#bbbbbb'");
  std::vector<std::string> parts;
  for (auto [identifiable, color] :
       {std::pair<Identifiability, const char*>{Identifiability::kYes, kBlue},
        {Identifiability::kPracticallyNo, kOrange},
        {Identifiability::kNo, kGrey}}) {
    const auto it = by_class.find(identifiable);
    if (it == by_class.end()) continue;
    parts.push_back(f->AddData(it->second) +
                    " using 1:(1):2:3 with yerrorbars pt 7 ps 0.7 lw 2 lc rgb '" + color +
                    "' title " + GnuplotString(ToString(identifiable)));
  }
  return g.str() + "plot " + Join(parts, ", ") + "\n";
}

void IntervalFigure(const Intervals& intervals, Page* page) {
  const std::vector<std::string>& without = intervals.without_std;
  if (intervals.names.empty()) {
    page->Note("No interval figure: no free parameter has a standard deviation" +
               std::string(without.empty() ? "." : " (" + Join(without, ", ") + ")."));
    return;
  }
  Figure f("identify-parameters",
           std::clamp(300 + 45 * static_cast<int>(intervals.names.size()), 600, 1000), 420);
  f.script = IntervalScript(&f, intervals);
  const std::string z = Format(kNormal95, "%.2f");
  f.caption = "95 % interval of each free parameter relative to its value, [exp(−" + z +
              " std/value), exp(+" + z +
              " std/value)], on a log axis (dimensionless). "
              "Dashed lines: a factor 2 either way, beyond which a parameter is practically "
              "not identifiable.";
  if (!intervals.clipped.empty()) {
    f.caption += " Cut at a factor " + Format(kClipFactor, "%.0f") +
                 ", beyond the axis: " + Join(intervals.clipped, ", ") + ".";
  }
  page->AddFigure(std::move(f));
  if (!without.empty()) {
    page->Note("Free parameters without a standard deviation (not drawn): " + Join(without, ", ") +
               ".");
  }
}

}  // namespace

void IdentifyPage(const IdentifyReport& report, Page* page) {
  const IdentifySummary& summary = report.body.result;
  page->Summary(SummaryFacts(report.body.dataset, summary));
  const FrequencyFigureOptions frequencies = ModesSection(summary.modes, page);
  const Intervals intervals = ParametersSection(summary.estimates, page);
  page->Heading("Figures");
  if (auto f = FrequencyFigure(frequencies)) {
    f->caption =
        "Frequency of each mode. Left: measured (dot, with ± 1σ bars) and model (cross), in Hz. "
        "Right: model − measured, in Hz, against the ± 1σ of the measurement drawn around 0.";
    page->AddFigure(std::move(*f));
  }
  MacFigure(summary.modes, page);
  IntervalFigure(intervals, page);
}

}  // namespace ringid::html
