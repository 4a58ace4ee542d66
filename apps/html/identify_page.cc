// The page of `ringid identify`: fit summary, modes, parameters, and the
// frequency, MAC and interval figures.
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "apps/html/pages.h"
#include "apps/html/text.h"

namespace ringid::html {
namespace {

const std::vector<FactSpec> kSummary = {
    {"dataset"}, {"method"}, {"success"}, {"converged"}, {"message", "solver message"},
    {"cost", "cost (½ Σ weighted residual²)"}, {"evaluations"}, {"starts"},
    {"start_costs", "final cost per start"}, {"seconds"}, {"frequency_weighting"},
    {"relative_error/in_plane_eq19", "relative error, in-plane (eq. 19)"},
    {"relative_error/out_of_plane_eq20", "relative error, out-of-plane (eq. 20)"},
    {"covariance/computed", "covariance computed"}, {"covariance/error", "covariance error"},
    {"covariance/rank", "rank of the weighted Jacobian"},
    {"covariance/condition_number", "condition number"}};

// Intervals wider than this factor are cut at the edge of the figure.
constexpr double kClipFactor = 100;

// The relative 95 % intervals of the free parameters that have a std.
struct Intervals {
  std::vector<std::string> names;
  std::vector<std::pair<double, double>> bounds;  // low, high relative to the value
  std::vector<std::string> classes;               // identifiable: yes, ...
  std::vector<std::string> clipped;               // cut at kClipFactor
  std::vector<std::string> without_std;           // free, not drawn
};

// The modes table; the frequencies for the figure.
FrequencyFigureOptions ModesSection(const json& modes, Page* page) {
  FrequencyFigureOptions figure;
  figure.name = "identify-frequencies";
  figure.reference_title = "measured ± 1σ";
  figure.band_title = "± 1σ of the measurement";
  figure.reference_name = "measured";
  std::vector<Row> rows;
  for (const json& m : modes) {
    const auto measured = Num(m, "measured_hz"), sigma = Num(m, "measured_sigma_hz"),
               model = Num(m, "model_hz");
    std::optional<double> diff, z;
    if (measured && model) diff = *model - *measured;
    if (diff && sigma && *sigma > 0) z = *diff / *sigma;
    rows.push_back({ValueCell(Get(m, "label")), ValueCell(Get(m, "model_label")),
                    NumberCell(measured, "%.3f"), NumberCell(sigma, "%.3g"),
                    NumberCell(model, "%.3f"), NumberCell(diff, "%.3g"), NumberCell(z, "%.3g"),
                    NumberCell(Num(m, "measured_damping_ratio")),
                    NumberCell(Num(m, "model_damping_ratio")), NumberCell(Num(m, "mac"), "%.3f")});
    figure.AddMode(Str(m, "label"), measured, sigma, model);
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
Row ParameterRow(const std::string& name, const json& q, Intervals* intervals) {
  const auto value = Num(q, "value"), sd = Num(q, "std");
  const bool free = IsTrue(q, "free");
  std::string role = free ? "free" : "fixed";
  if (!Str(q, "tied_to").empty()) role = "tied to " + Str(q, "tied_to");
  std::optional<double> factor;
  if (free && value && sd && *value != 0) {
    double z = 1.96 * std::fabs(*sd / *value);
    factor = std::exp(std::min(z, 700.0));
    if (z > std::log(kClipFactor)) z = std::log(kClipFactor), intervals->clipped.push_back(name);
    intervals->names.push_back(name);
    intervals->bounds.push_back({std::exp(-z), std::exp(z)});
    intervals->classes.push_back(Str(q, "identifiable"));
  } else if (free) {
    intervals->without_std.push_back(name);
  }
  return {TextCell(name),
          NumberCell(value),
          ValueCell(Get(q, "unit")),
          TextCell(role),
          NumberCell(sd),
          FactorCell(factor),
          ValueCell(Get(q, "identifiable")),
          ValueCell(Get(q, "reason"))};
}

Intervals ParametersSection(const json& parameters, Page* page) {
  Intervals intervals;
  std::vector<Row> rows;
  if (parameters.is_object()) {
    for (const auto& [name, q] : parameters.items())
      rows.push_back(ParameterRow(name, q, &intervals));
  }
  page->Heading("Parameters");
  page->Table({"parameter", "value", "unit", "role", "std", "95 % interval (factor)",
               "identifiable", "reason"},
              rows);
  return intervals;
}

// MAC of the measured shapes against every model shape.
void MacFigure(const json& modes, Page* page) {
  HeatMapOptions map;
  map.name = "identify-mac";
  map.x_label = "model mode";
  map.y_label = "measured mode";
  map.color_label = "MAC";
  std::vector<const json*> macs;
  for (const json& m : modes) {
    const json& mac = Get(m, "mac_all");
    if (!mac.is_object() || mac.empty()) continue;
    map.rows.push_back(Str(m, "label"));
    macs.push_back(&mac);
  }
  if (macs.empty()) {
    page->Note("No MAC figure: the dataset gives no measured mode shape (no mode has mac_all).");
    return;
  }
  for (const json& m : modes) {
    if (const std::string label = Str(m, "model_label"); !label.empty())
      AppendOnce(&map.columns, label);
  }
  for (const json* mac : macs) {
    for (const auto& [label, value] : mac->items()) AppendOnce(&map.columns, label);
  }
  for (const json* mac : macs) {
    map.values.emplace_back();
    for (const std::string& c : map.columns) map.values.back().push_back(Num(*mac, c.c_str()));
  }
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
  std::map<std::string, Series> by_class;
  for (size_t i = 0; i < intervals.names.size(); ++i) {
    const auto [from, to] = intervals.bounds[i];
    low = std::min(low, from);
    high = std::max(high, to);
    const std::string& c = intervals.classes[i];
    by_class[c == "yes" || c == "practically_no" ? c : "other"].Row(
        {static_cast<double>(i), from, to});
  }
  std::ostringstream g;
  g << "set logscale y\nset format y '%g'\nset yrange [" << low / 1.4 << ":" << high * 1.4 << "]\n"
    << "set xrange [-0.7:" << intervals.names.size() - 0.3 << "]\n"
    << CategoryXTics(intervals.names, f->width - 250.0, -35)
    << "set grid ytics\nset ylabel 'interval / value (log scale)'\n"
    << "set key outside right top title 'identifiable' noenhanced\n"
    << HorizontalLine(1, "2", kDashedGrey) << HorizontalLine(2, "0.5", kDashedGrey)
    << HorizontalLine(3, "1", "lc rgb '#bbbbbb'");
  std::vector<std::string> parts;
  for (auto [c, color] : {std::pair<std::string, const char*>{"yes", kBlue},
                          {"practically_no", kOrange},
                          {"other", kGrey}}) {
    if (!by_class.count(c)) continue;
    parts.push_back(f->AddData(by_class[c]) +
                    " using 1:(1):2:3 with yerrorbars pt 7 ps 0.7 lw 2 lc rgb '" + color +
                    "' title " + GnuplotString(c));
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
  f.caption =
      "95 % interval of each free parameter relative to its value, "
      "[exp(−1.96 std/value), exp(+1.96 std/value)], on a log axis (dimensionless). "
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

void IdentifyPage(const json& report, Page* page) {
  page->Summary(FactsOf(report, kSummary));
  const json& modes = List(report, "modes");
  const FrequencyFigureOptions frequencies = ModesSection(modes, page);
  const Intervals intervals = ParametersSection(Get(report, "parameters"), page);
  page->Heading("Figures");
  if (auto f = FrequencyFigure(frequencies)) {
    f->caption =
        "Frequency of each mode. Left: measured (dot, with ± 1σ bars) and model (cross), in Hz. "
        "Right: model − measured, in Hz, against the ± 1σ of the measurement drawn around 0.";
    page->AddFigure(std::move(*f));
  }
  MacFigure(modes, page);
  IntervalFigure(intervals, page);
}

}  // namespace ringid::html
