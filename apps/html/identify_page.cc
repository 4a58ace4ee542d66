// The page of `ringid identify`: fit summary, modes, parameters, and the
// frequency, MAC and interval figures.
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "apps/html/frf_section.h"
#include "apps/html/pages.h"
#include "apps/html/text.h"
#include "estimation/statistics.h"
#include "model/parameters.h"
#include "model/plausibility.h"

namespace ringid::html {
namespace {

// Intervals wider than this factor are cut at the edge of the figure.
constexpr double kClipFactor = 100;

// The relative 95 % intervals of the free parameters that have a std.
struct Intervals {
  std::vector<std::string> names;
  std::vector<std::pair<double, double>> bounds;  // low, high relative to the value
  std::vector<Identifiability> classes;
  // Where each interval lies when its parameter is classed yes
  // (UncertaintyOptions::PracticalBand, relative to the value).
  std::vector<std::pair<double, double>> yes_bands;
  std::vector<std::string> clipped;      // cut at kClipFactor
  std::vector<std::string> without_std;  // free, not drawn
  std::vector<std::string> not_positive;  // an interval reaching 0 or below: not drawn
};

// The costs of the starts, each as "%.4g (origin)".
Cell StartCostsCell(const IdentifyResult& s) {
  std::vector<std::string> items;
  for (size_t k = 0; k < s.start_costs.size(); ++k) {
    items.push_back(Format(s.start_costs[k]) +
                    (k < s.start_origins.size() ? std::string(" (") + ToString(s.start_origins[k]) + ")"
                                                : ""));
  }
  return ListCell(items);
}

FactRows SummaryFacts(const std::string& dataset, const IdentifyResult& s) {
  const Uncertainty& u = s.uncertainty;
  return {{"dataset", TextCell(dataset)},
          {"method", TextCell(MethodTitle(s.method))},
          {"status", NameCell(s.status.outcome)},
          {"converged", YesNoCell(s.converged)},
          {"solver message", TextCell(s.status.message)},
          {"cost (½ Σ weighted residual²)", NumberCell(s.cost)},
          {"fit (χ² on its degrees of freedom)", TextCell(s.fit.verdict)},
          {"χ²", NumberCell(s.fit.chi_square)},
          {"degrees of freedom", NumberCell(s.fit.degrees_of_freedom, "%.0f")},
          {"p-value", NumberCell(s.fit.p_value, "%.3g")},
          {"evaluations", NumberCell(static_cast<double>(s.evaluations), "%.0f")},
          {"starts", NumberCell(s.starts, "%.0f")},
          {"final cost per start", StartCostsCell(s)},
          {"did the starts agree", TextCell(s.start_agreement.verdict)},
          {"seconds", NumberCell(s.seconds)},
          {"frequency weighting", NameCell(s.frequency_weighting)},
          {"relative error, in-plane (eq. 19)", NumberCell(s.relative_error_in_plane)},
          {"relative error, out-of-plane (eq. 20)", NumberCell(s.relative_error_out_of_plane)},
          {"covariance computed", YesNoCell(u.covariance_ok)},
          {"covariance error", TextCell(u.covariance_error.empty() ? "–" : u.covariance_error)},
          {"rank of the weighted Jacobian", NumberCell(u.rank, "%.0f")},
          {"condition number", NumberCell(u.condition_number)}};
}

// A measured mode as the figures name it: its label, after its condition
// in format-2 data ("drum_6 vertical").
std::string ModeName(const ModeFit& m) {
  return m.condition ? *m.condition + " " + ToString(m.label) : std::string(ToString(m.label));
}

// The other measurements (static stiffnesses) against the fitted model.
void MeasurementsSection(const std::optional<std::vector<MeasurementFit>>& measurements,
                         Page* page) {
  if (!measurements) return;
  std::vector<Row> rows;
  for (const MeasurementFit& m : *measurements) {
    rows.push_back({TextCell(m.condition.value_or("–")), TextCell(m.name),
                    NumberCell(m.measured, "%.5g"), NumberCell(m.sigma, "%.3g"),
                    NumberCell(m.model, "%.5g"), TextCell(m.unit),
                    NumberCell((m.model - m.measured) / m.sigma, "%.3g")});
  }
  page->TableSection("Other measurements", {"condition", "measurement", "measured", "σ",
                                            "model", "unit", "(model − measured) / σ"},
                     rows);
}

// The modes table; the frequencies for the figure.
FrequencyFigureOptions ModesSection(const std::vector<ModeFit>& modes, Page* page) {
  FrequencyFigureOptions figure;
  figure.name = "identify-frequencies";
  figure.reference_title = "measured ± 1σ";
  figure.band_title = "± 1σ of the measurement";
  figure.reference_name = "measured";
  const bool conditions =
      std::any_of(modes.begin(), modes.end(), [](const ModeFit& m) { return m.condition; });
  std::vector<Row> rows;
  for (const ModeFit& m : modes) {
    const double difference = m.model_hz - m.measured_hz;
    std::optional<double> z;
    if (m.measured_sigma_hz > 0) z = difference / m.measured_sigma_hz;
    Row row;
    if (conditions) {
      row.push_back(TextCell(m.condition.value_or("–")));
      row.push_back(NumberCell(m.speed_m_s, "%.3g"));
    }
    for (Cell cell :
         {NameCell(m.label), NameCell(m.model_label), NumberCell(m.measured_hz, "%.3f"),
          NumberCell(m.measured_sigma_hz, "%.3g"), NumberCell(m.model_hz, "%.3f"),
          NumberCell(difference, "%.3g"), NumberCell(z, "%.3g"), NumberCell(m.measured_damping),
          NumberCell(m.model_damping), NumberCell(m.mac, "%.3f")}) {
      row.push_back(cell);
    }
    rows.push_back(row);
    figure.AddMode(ModeName(m), m.measured_hz, m.measured_sigma_hz, m.model_hz);
  }
  std::vector<std::string> head = {"mode",
                                   "model mode",
                                   "measured (Hz)",
                                   "σ (Hz)",
                                   "model (Hz)",
                                   "model − measured (Hz)",
                                   "(model − measured) / σ",
                                   "measured damping ratio",
                                   "model damping ratio",
                                   "MAC"};
  if (conditions) head.insert(head.begin(), {"condition", "speed (m/s)"});
  page->Heading("Modes");
  page->Table(head, rows);
  return figure;
}

// One parameter's row; its interval when it is free and has a std. With
// `priors`, the prior's share and what decided the value.
Row ParameterRow(const ParameterEstimate& q, bool priors, Intervals* intervals) {
  const std::string name = q.key.Text();
  std::string role = q.free ? "free" : "fixed";
  if (q.tied_to) role = std::string("tied to ") + ToString(*q.tied_to);
  // The report's interval, drawn relative to the value where both ends are
  // positive (a log axis); a positive parameter's lower end may underflow to 0.
  const auto& interval = q.interval_95;
  const bool positive = Info(q.param()).domain == Domain::kPositive;
  if (q.free && interval && q.value > 0 && (positive || interval->first > 0)) {
    const double low = interval->first / q.value, high = interval->second / q.value;
    if (low < 1 / kClipFactor || high > kClipFactor) intervals->clipped.push_back(name);
    intervals->names.push_back(name);
    intervals->bounds.push_back({std::max(low, 1 / kClipFactor), std::min(high, kClipFactor)});
    intervals->classes.push_back(q.identifiable);
    const auto [yes_low, yes_high] = UncertaintyOptions().PracticalBand(positive);
    intervals->yes_bands.push_back(
        {std::max(yes_low, 1 / kClipFactor), std::min(yes_high, kClipFactor)});
  } else if (q.free && interval) {
    intervals->not_positive.push_back(name);
  } else if (q.free) {
    intervals->without_std.push_back(name);
  }
  Row row = {TextCell(name),
             NumberCell(q.value),
             TextCell(Info(q.param()).unit),
             TextCell(role),
             NumberCell(q.std),
             IntervalCell(interval),
             NameCell(q.identifiable),
             TextCell(q.Condition().value_or("–")),
             TextCell(q.reason)};
  if (priors) {
    row.push_back(PercentCell(q.prior_share));
    row.push_back(TextCell(q.decided_by ? DecidedByWords(*q.decided_by) : "–"));
    row.push_back(NumberCell(q.prior_z, "%+.1f"));
  }
  return row;
}

// In words, which parameters with a prior the prior decides and which the
// data do (as IdentifyResult::FullReport says it).
std::string PriorSentence(const std::vector<ParameterEstimate>& estimates) {
  std::vector<std::string> by_prior, by_both, by_data;
  for (const ParameterEstimate& q : estimates) {
    if (!q.decided_by) continue;
    (*q.decided_by == DecidedBy::kPrior  ? by_prior
     : *q.decided_by == DecidedBy::kData ? by_data
                                         : by_both)
        .push_back(q.key.Text());
  }
  std::vector<std::string> parts;
  if (!by_prior.empty()) {
    parts.push_back("decided by their priors (posterior variance over " +
                    Format(100 * kPriorDecides, "%g") + " % of the prior variance): " +
                    Join(by_prior, ", "));
  }
  if (!by_both.empty()) {
    parts.push_back("decided by data and priors together: " + Join(by_both, ", "));
  }
  if (!by_data.empty()) {
    parts.push_back("decided by the data despite a prior (under " +
                    Format(100 * kDataDecides, "%g") + " % of the prior variance left): " +
                    Join(by_data, ", "));
  }
  return "Parameters with a prior: " + Join(parts, "; ") +
         ". The column “posterior / prior variance” is the share of the prior variance a "
         "parameter keeps after the fit; parameters without a prior are decided by the data "
         "alone.";
}

Intervals ParametersSection(const IdentifyResult& summary, Page* page) {
  const std::vector<ParameterEstimate>& estimates = summary.estimates;
  const std::string conflicts = summary.PriorConflicts();
  Intervals intervals;
  const bool priors = std::any_of(estimates.begin(), estimates.end(),
                                  [](const ParameterEstimate& q) { return q.prior_share; });
  std::vector<Row> rows;
  for (const ParameterEstimate& q : estimates) rows.push_back(ParameterRow(q, priors, &intervals));
  std::vector<std::string> head = {"parameter", "value", "unit", "role", "std",
                                   "95 % interval", "identifiable",
                                   "holds given (known)", "reason"};
  if (priors) {
    head.insert(head.end(), {"posterior / prior variance (%)", "decided by",
                             "distance from the prior (prior sigma)"});
  }
  page->Heading("Parameters");
  if (priors) page->Note(PriorSentence(estimates));
  if (!conflicts.empty()) page->Note(conflicts);
  if (const std::string bounds = summary.OnBounds(); !bounds.empty()) page->Note("Parameters " + bounds);
  if (std::any_of(estimates.begin(), estimates.end(),
                  [](const ParameterEstimate& q) { return !q.conditional_on.empty(); })) {
    page->Note("A class with “holds given (known)” rests on a known value: the data measure the "
               "combination named, so a wrong known value moves the estimate with it.");
  }
  page->Table(head, rows);
  return intervals;
}

// The plausibility flags (docs/plausibility.md), as a section of their own.
void PlausibilitySection(const std::vector<PlausibilityFlag>& flags, Page* page) {
  std::vector<Row> rows;
  for (const PlausibilityFlag& f : flags) {
    std::vector<std::string> names;
    for (Param p : f.parameters) names.push_back(ToString(p));
    rows.push_back({TextCell(f.rule), ListCell(names), TextCell(f.reason)});
  }
  page->Heading("Plausibility");
  page->Note("The fitted values break " + std::to_string(flags.size()) +
             (flags.size() == 1 ? " rule" : " rules") +
             " of the ranges typical of a tire (docs/plausibility.md): a warning, not an error. "
             "Such a value was usually not determined by the data, or the model lacks "
             "something.");
  page->Table({"rule", "parameters", "reason"}, rows);
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
    map.rows.push_back(ModeName(*m));
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
  double low = 1, high = 1;
  std::map<Identifiability, Series> by_class;
  Series bands;
  for (size_t i = 0; i < intervals.names.size(); ++i) {
    const auto [from, to] = intervals.bounds[i];
    const auto [yes_from, yes_to] = intervals.yes_bands[i];
    low = std::min({low, from, yes_from});
    high = std::max({high, to, yes_to});
    by_class[intervals.classes[i]].Row({static_cast<double>(i), from, to});
    bands.Row({static_cast<double>(i), yes_from, yes_to});
  }
  std::ostringstream g;
  g << "set logscale y\nset format y '%g'\nset yrange [" << low / 1.4 << ":" << high * 1.4 << "]\n"
    << "set y" << LogTics(low / 1.4, high * 1.4).substr(5)
    << "set xrange [-0.7:" << static_cast<double>(intervals.names.size()) - 0.3 << "]\n"
    << CategoryXTics(intervals.names, f->width - 250.0, -35)
    << "set grid ytics\nset ylabel 'interval / value (log scale)'\n"
    << "set key outside right top title 'identifiable' noenhanced\n"
    << HorizontalLine(1, "1", "lc rgb '#bbbbbb'");
  std::vector<std::string> parts = {
      f->AddData(bands) + " using 1:(1):($1-0.4):($1+0.4):2:3 with boxxyerror fs solid 0.3 "
                          "noborder lc rgb '#bbbbbb' title 'yes within'"};
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
  const UncertaintyOptions classed;
  const double t = classed.practical_relative_std;
  f.caption = "95 % interval of each free parameter relative to its value (the report's "
              "interval_95: value × exp(± " + z + " std/value) for a positive parameter, fitted "
              "in its log), on a log axis (dimensionless). "
              "Grey bands: where the interval lies when the parameter is classed yes, its "
              "relative standard deviation at most " + Format(t, "%g") + " (exp(± " + z + " × " +
              Format(t, "%g") + "), a factor " +
              Format(classed.PracticalBand(true).second, "%.2f") +
              " either way, fitted in its log; 1 ± " + Format(kNormal95 * t, "%.2f") +
              " fitted linearly); beyond it a determined parameter is practically_no.";
  if (!intervals.not_positive.empty()) {
    f.caption += " Not drawn, their interval reaching 0 or below (fitted in linear "
                 "coordinates; see the table): " + Join(intervals.not_positive, ", ") + ".";
  }
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

// A mode label's colour in the Campbell figure: the same for its model
// curve and its measured points, in both panels.
const char* LabelColor(ModeLabel label) {
  static constexpr const char* kColors[kNumLabels] = {
      kBlue,     kOrange,   kGreen,    kRed,      "#9467bd",
      "#8c564b", "#e377c2", "#17becf", "#bcbd22", "#555555"};
  const int i = static_cast<int>(label);
  return i >= 0 && i < kNumLabels ? kColors[i] : kGrey;
}

// One curve of the model against speed as rows (speed, value), broken where
// the mode is overdamped (a non-finite value).
Series CurveSeries(const std::vector<double>& speed, const std::vector<double>& value,
                   double* top) {
  Series s;
  bool broken = true;
  for (size_t k = 0; k < std::min(speed.size(), value.size()); ++k) {
    if (!std::isfinite(speed[k])) continue;
    *top = std::max(*top, speed[k]);
    if (std::isfinite(value[k])) {
      s.Row({speed[k], value[k]});
      broken = false;
    } else if (!broken) {
      s.Break();
      broken = true;
    }
  }
  return s;
}

// The plot commands of one panel of the Campbell figure: a line per model
// curve and the measured points in the same colour.
struct CampbellPanel {
  std::vector<std::string> parts;
  // The panel's plot command; an empty panel keeps its axes.
  std::string Plot() const {
    return parts.empty() ? "set yrange [0:1]\nplot -1 notitle\n" : PlotCommand(parts);
  }
};

// The conditions of the measured modes, with their speeds, in first-seen order.
std::vector<std::pair<std::string, double>> MeasuredConditions(const std::vector<ModeFit>& modes) {
  std::vector<std::pair<std::string, double>> out;
  for (const ModeFit& m : modes) {
    if (!m.condition || !m.speed_m_s || !std::isfinite(*m.speed_m_s)) continue;
    const bool seen = std::any_of(out.begin(), out.end(),
                                  [&](const auto& c) { return c.first == *m.condition; });
    if (!seen) out.push_back({*m.condition, *m.speed_m_s});
  }
  return out;
}

std::string CampbellScript(Figure* f, const IdentifyResult& s, bool* drawn) {
  CampbellPanel frequency, damping;
  double top = 0;
  for (const SpeedCurve& c : s.speed_curves) {
    const std::string style =
        " using 1:2 with lines lw 2 lc rgb '" + std::string(LabelColor(c.label)) + "' ";
    const Series fs = CurveSeries(c.speed_m_s, c.frequency_hz, &top);
    const Series ds = CurveSeries(c.speed_m_s, c.damping_ratio, &top);
    if (!fs.empty()) {
      frequency.parts.push_back(f->AddData(fs) + style + "title " +
                                GnuplotString(Pretty(ToString(c.label))));
    }
    if (!ds.empty()) damping.parts.push_back(f->AddData(ds) + style + "notitle");
  }
  std::map<ModeLabel, Series> measured_hz, measured_damping;
  for (const ModeFit& m : s.modes) {
    if (!m.speed_m_s || !std::isfinite(*m.speed_m_s)) continue;
    top = std::max(top, *m.speed_m_s);
    measured_hz[m.label].Row({*m.speed_m_s, m.measured_hz});
    if (m.measured_damping) measured_damping[m.label].Row({*m.speed_m_s, *m.measured_damping});
  }
  const auto points = [f](const std::map<ModeLabel, Series>& by_label, CampbellPanel* panel) {
    for (const auto& [label, series] : by_label) {
      if (series.empty()) continue;
      panel->parts.push_back(f->AddData(series) +
                             " using 1:2 with points pt 7 ps 1.1 lc rgb '" + LabelColor(label) +
                             "' notitle");
    }
  };
  points(measured_hz, &frequency);
  points(measured_damping, &damping);
  *drawn = !frequency.parts.empty() || !damping.parts.empty();
  if (!(top > 0)) top = 1;
  const double h = f->height;
  std::ostringstream g;
  g << "set multiplot\n"
    << "set lmargin at screen 0.09\nset rmargin at screen 0.80\n"
    << "set xrange [" << -0.03 * top << ":" << top << "]\n"
    << "set offsets 0, 0, graph 0.05, graph 0.05\n"
    << "set grid xtics ytics\n";
  int id = 1;
  for (const auto& [name, speed] : MeasuredConditions(s.modes)) {
    const std::string x = Format(speed, "%.12g");
    g << VerticalLine(id, x, kDashedGrey) << "set label " << id << " "
      << GnuplotString(Pretty(name)) << " at first " << x
      << ", graph 0.97 right rotate by 90 offset 1, 0 noenhanced tc rgb '#666666'\n";
    ++id;
  }
  // Top: frequency, the key beside it; bottom: damping ratio.
  g << "set tmargin at screen " << 1 - 20 / h << "\nset bmargin at screen 0.53\n"
    << "set format x ''\nunset xlabel\nset ylabel 'frequency (Hz)'\n"
    << "set key at screen 0.82, screen " << 1 - 20 / h << " left top title 'mode' noenhanced\n"
    << frequency.Plot() << "unset label\nset autoscale y\n"
    << "set tmargin at screen 0.47\nset bmargin at screen " << 55 / h << "\n"
    << "set format x '%g'\nset xlabel 'forward speed (m/s)'\nset ylabel 'damping ratio'\n"
    << "unset key\n"
    << damping.Plot() << "unset multiplot\n";
  return g.str();
}

// Frequency and damping ratio of every mode of the fitted model against
// forward speed, and the measured modes at their conditions' speeds.
void CampbellFigure(const IdentifyResult& s, Page* page) {
  if (s.speed_curves.empty()) return;
  Figure f("identify-campbell", 900, 760);
  bool drawn = false;
  f.script = CampbellScript(&f, s, &drawn);
  if (!drawn) {
    page->Note("No speed figure: the fitted model has no oscillating mode at any speed.");
    return;
  }
  std::vector<std::string> conditions;
  for (const auto& [name, speed] : MeasuredConditions(s.modes)) {
    conditions.push_back(name + " (" + Format(speed, "%.3g") + " m/s)");
  }
  f.caption =
      "Campbell diagram: frequency (Hz, top) and damping ratio (dimensionless, bottom) of each "
      "mode against forward speed (m/s), one colour per mode. Lines: the fitted model (with "
      "the parameter values of the first condition), broken where a mode is overdamped. Dots: the "
      "measured modes, in their mode's colour, at the speed of their condition";
  f.caption += conditions.empty() ? " (no measured mode names a speed)."
                                  : ", marked by dashed lines: " + Join(conditions, ", ") + ".";
  page->AddFigure(std::move(f));
}

}  // namespace

void IdentifyPage(const IdentifyReport& report, Page* page) {
  const IdentifyResult& summary = report.body.result;
  if (!summary.warnings.empty()) {  // the headline, before everything else
    page->Heading("Warnings");
    for (const std::string& w : summary.warnings) page->Note(w);
  }
  page->Summary(SummaryFacts(report.body.dataset, summary));
  if (summary.fit.poor) page->Note(summary.fit.verdict + ".");
  if (!summary.plausibility.empty()) PlausibilitySection(summary.plausibility, page);
  const FrequencyFigureOptions frequencies = ModesSection(summary.modes, page);
  MeasurementsSection(summary.measurements, page);
  FrfTable(summary.frfs, page);
  const Intervals intervals = ParametersSection(summary, page);
  if (summary.plausibility.empty() && !summary.estimates.empty()) {
    page->Note("Plausibility: every value within its plausible range (docs/plausibility.md).");
  }
  page->Heading("Figures");
  if (auto f = FrequencyFigure(frequencies)) {
    f->caption =
        "Frequency of each mode. Left: measured (dot, with ± 1σ bars) and model (cross), in Hz. "
        "Right: model − measured, in Hz, against the ± 1σ of the measurement drawn around 0.";
    page->AddFigure(std::move(*f));
  }
  CampbellFigure(summary, page);
  FrfFigures(summary.frfs, page);
  MacFigure(summary.modes, page);
  IntervalFigure(intervals, page);
}

}  // namespace ringid::html
