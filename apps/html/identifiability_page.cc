// The page of `ringid identifiability`: rank, intervals, combinations and
// advice; the singular values, correlations and profile likelihoods.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "apps/html/pages.h"
#include "apps/html/text.h"

namespace ringid::html {
namespace {

const std::vector<FactSpec> kSummary = {
    {"dataset"}, {"success"}, {"message"}, {"rank"}, {"num_residuals", "weighted residuals"},
    {"condition_number"}, {"rank_explanation"},
    {"identifiable_subset", "largest identifiable subset"}, {"seconds"}};

// "[a, b]" of a two-element list, an end that is not a number "open".
Cell IntervalCell(const json& interval) {
  if (!interval.is_array() || interval.size() != 2) return TextCell("–");
  const auto a = Num(interval[0]), b = Num(interval[1]);
  return {"[" + (a ? Format(*a) : "open") + ", " + (b ? Format(*b) : "open") + "]", true};
}

void TableSections(const json& report, Page* page) {
  const json& parameters = Get(report, "parameters");
  std::vector<Row> rows;
  if (parameters.is_object()) {
    for (const auto& [name, q] : parameters.items()) {
      rows.push_back({TextCell(name), NumberCell(Num(q, "value")),
                      ValueCell(Get(q, "identifiable")), NumberCell(Num(q, "std")),
                      IntervalCell(Get(q, "wald_95")), IntervalCell(Get(q, "profile_95")),
                      ValueCell(Get(q, "reason"))});
    }
  }
  page->Heading("Parameters");
  page->Table({"parameter", "value", "identifiable", "std", "Wald 95 %", "profile 95 %", "reason"},
              rows);
  page->TableSection("Free and near-free combinations",
                     {"combination", "meaning", "singular value"},
                     RowsOf(List(report, "combinations"), [](const json& c) -> Row {
                       return {ValueCell(Get(c, "text")), ValueCell(Get(c, "meaning")),
                               NumberCell(Num(c, "singular_value"))};
                     }));
  page->TableSection(
      "Collinear pairs", {"parameters", "collinearity index"},
      RowsOf(List(report, "collinear_pairs"), [](const json& c) -> Row {
        return {ValueCell(Get(c, "parameters")), NumberCell(Num(c, "collinearity_index"))};
      }));
  page->TableSection(
      "Experiment advice",
      {"parameter", "extra observation", "information gain", "makes it identifiable"},
      RowsOf(List(report, "advice"), [](const json& a) -> Row {
        return {ValueCell(Get(a, "parameter")), ValueCell(Get(a, "observation")),
                NumberCell(Num(a, "information_gain")), ValueCell(Get(a, "makes_identifiable"))};
      }));
}

void SingularValueFigure(const json& report, Page* page) {
  Series above, below;
  const auto rank = Num(report, "rank");
  int k = 0, shown = 0;
  for (const json& v : List(report, "singular_values")) {
    ++k;
    const auto s = Num(v);
    if (!s || *s <= 0) continue;
    (rank && k > *rank ? below : above).Row({k, s});
    ++shown;
  }
  if (shown == 0) {
    page->Note("No singular value figure: the report has no positive singular value.");
    return;
  }
  Figure f("identifiability-singular-values", 760, 380);
  std::ostringstream g;
  g << "set logscale y\nset format y '10^{%L}'\nset grid\n"
    << "set xrange [0.5:" << k + 0.5 << "]\nset xtics 1\n"
    << "set xlabel 'index (largest first)'\nset ylabel 'singular value'\nset key top right\n";
  if (rank) {
    g << "set label 1 "
      << GnuplotString("rank " + Text(Get(report, "rank")) + " of " +
                       std::to_string(List(report, "coordinates").size()) + " free coordinates")
      << " at graph 0.03, graph 0.06 left\n";
  }
  std::vector<std::string> parts;
  if (!above.empty()) {
    parts.push_back(f.AddData(above) + " using 1:2 with linespoints pt 7 ps 1 lw 1.5 lc rgb '" +
                    kBlue + "' title 'within the rank'");
  }
  if (!below.empty()) {
    parts.push_back(f.AddData(below) + " using 1:2 with points pt 6 ps 1.2 lc rgb '" + kGrey +
                    "' title 'below the rank tolerance'");
  }
  f.script = g.str() + "plot " + Join(parts, ", ") + "\n";
  f.caption =
      "Singular values of the weighted Jacobian (log coordinates for positive parameters; "
      "dimensionless), largest first, on a log axis. Free coordinates beyond the listed "
      "values change no residual.";
  page->AddFigure(std::move(f));
}

void CorrelationFigure(const json& report, Page* page) {
  HeatMapOptions map;
  map.name = "identifiability-correlation";
  for (const json& c : List(report, "coordinates")) map.rows.push_back(Text(c));
  map.columns = map.rows;
  const size_t n = map.rows.size();
  const json& correlation = Get(report, "correlation");
  bool any = false;
  if (correlation.is_array() && correlation.size() == n) {
    for (const json& row : correlation) {
      map.values.emplace_back();
      for (size_t c = 0; c < n; ++c) {
        map.values.back().push_back(row.is_array() && c < row.size() ? Num(row[c]) : std::nullopt);
        any |= map.values.back().back().has_value();
      }
    }
  }
  if (!any) {
    page->Note(
        "No correlation figure: no correlation is defined (the covariance does not exist where "
        "the data leave directions free).");
    return;
  }
  map.low = -1;
  map.palette = "(-1 '#b2182b', 0 '#ffffff', 1 '#2166ac')";
  map.color_label = "correlation";
  map.print_values = n <= 16;
  Figure f = HeatMap(map);
  f.caption =
      "Correlation of the fitted coordinates (−1 red to +1 blue); grey cells are undefined.";
  page->AddFigure(std::move(f));
}

// A profile's points (value, increase of the misfit) that are numbers.
std::vector<std::pair<double, double>> ProfileCurve(const json& q) {
  std::vector<std::pair<double, double>> curve;
  for (const json& point : List(q, "profile_curve")) {
    if (!point.is_array() || point.size() != 2) continue;
    const auto v = Num(point[0]), d = Num(point[1]);
    if (v && d) curve.push_back({*v, *d});
  }
  return curve;
}

// The misfit at `end` on the sorted `curve`, interpolated in √ and in log
// of the value where positive; none outside the curve.
std::optional<double> MisfitAt(const std::vector<std::pair<double, double>>& curve, double end) {
  for (size_t i = 0; i + 1 < curve.size(); ++i) {
    const auto [a, da] = curve[i];
    const auto [b, db] = curve[i + 1];
    if (!(a <= end && end <= b) || a == b) continue;
    const bool logs = a > 0 && b > 0;
    const double t = logs ? std::log(end / a) / std::log(b / a) : (end - a) / (b - a);
    const double root = std::sqrt(da) + t * (std::sqrt(db) - std::sqrt(da));
    return root * root;
  }
  return std::nullopt;
}

// The profile's 95 % threshold and the unit of its curves: ringid writes
// Δχ² = 2 Δcost (threshold 3.84); curves in cost units would cross 1.92 at
// the reported interval ends.
std::pair<double, std::string> ProfileThreshold(const json& parameters) {
  int chi2 = 0, cost = 0;
  if (parameters.is_object()) {
    for (const auto& [name, q] : parameters.items()) {
      auto curve = ProfileCurve(q);
      std::sort(curve.begin(), curve.end());
      for (const json& end : List(q, "profile_95")) {
        const auto e = Num(end);
        if (!e) continue;
        const auto d = MisfitAt(curve, *e);
        if (d && *d > 0)
          (std::fabs(std::log(*d / 3.84)) < std::fabs(std::log(*d / 1.92)) ? chi2 : cost)++;
      }
    }
  }
  if (cost > chi2) return {1.92, "Δcost"};
  return {3.84, "Δχ² = 2 Δcost"};
}

// One panel of the profile figure; "" for a curve of fewer than 2 points.
std::string ProfilePanel(Figure* f, const std::string& name, const json& q, int column,
                         const std::string& unit) {
  Series s;
  bool positive = true;
  double low = INFINITY, high = -INFINITY;
  const auto curve = ProfileCurve(q);
  for (const auto& [v, d] : curve) {
    s.Row({v, d});
    positive &= v > 0;
    low = std::min(low, v), high = std::max(high, v);
  }
  if (curve.size() < 2) return "";
  std::ostringstream g;
  g << "set title " << GnuplotString(name) << " noenhanced\n"
    << (positive ? "set logscale x\n" : "unset logscale x\n")
    << (positive && high > low ? LogTics(low, high) : "set xtics autofreq\n")
    << (column == 0 ? "set ylabel " + GnuplotString(unit) + "\n" : "unset ylabel\n");
  if (const auto v = Num(q, "value")) {
    g << VerticalLine(2, Format(*v, "%.12g"), "dt 3 lc rgb '#888888'");
  } else {
    g << "unset arrow 2\n";
  }
  g << "plot " << f->AddData(s) << " using 1:2 with linespoints pt 7 ps 0.45 lw 1.5 lc rgb '"
    << kBlue << "' notitle\n";
  return g.str();
}

// Profile likelihood, one panel per parameter, four to a row.
void ProfileFigure(const json& parameters, Page* page) {
  const auto [threshold, unit] = ProfileThreshold(parameters);
  Figure f("identifiability-profiles");
  std::string panels;
  int n = 0;
  if (parameters.is_object()) {
    for (const auto& [name, q] : parameters.items()) {
      const std::string panel = ProfilePanel(&f, name, q, n % 4, unit);
      if (!panel.empty()) panels += panel, ++n;
    }
  }
  if (n == 0) {
    page->Note("No profile figure: the report has no profile curve.");
    return;
  }
  const int columns = std::min(n, 4), rows = (n + columns - 1) / columns;
  f.width = 1000;
  f.height = 40 + 210 * rows;
  std::ostringstream g;
  g << "set multiplot layout " << rows << "," << columns << " margins 0.07, 0.955, "
    << 45.0 / f.height << ", " << 1 - 30.0 / f.height << " spacing 0.06, " << 75.0 / f.height
    << "\n"
    << "set grid\nset yrange [0:" << 3 * threshold << "]\nset format x '%.3g'\n"
    << "set xtics rotate by -30 left font ',8'\nset ytics font ',8'\nset mxtics default\n"
    << "set autoscale xfix\nset offsets graph 0.04, graph 0.04, 0, 0\n"
    << HorizontalLine(1, StreamFormat(threshold), "dt 2 lw 1.5 lc rgb '" + std::string(kRed) + "'")
    << panels << "unset multiplot\n";
  f.script = g.str();
  f.caption = "Profile likelihood of each parameter: the increase of the misfit, in " + unit +
              " (the other parameters re-optimised), against the parameter's value (log axis "
              "where positive). Red dashed line: the 95 % threshold " +
              Format(threshold, "%.2f") + "; dotted line: the fitted value. Curves beyond " +
              Format(3 * threshold, "%.3g") + " are cut at the top.";
  page->AddFigure(std::move(f));
}

}  // namespace

void IdentifiabilityPage(const json& report, Page* page) {
  page->Summary(FactsOf(report, kSummary));
  TableSections(report, page);
  page->Heading("Figures");
  SingularValueFigure(report, page);
  CorrelationFigure(report, page);
  ProfileFigure(Get(report, "parameters"), page);
}

}  // namespace ringid::html
