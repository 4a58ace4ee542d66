// The page of `ringid identifiability`: rank, intervals, combinations and
// advice; the singular values, correlations and profile likelihoods.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "apps/html/pages.h"
#include "apps/html/text.h"
#include "estimation/statistics.h"
#include "model/parameters.h"

namespace ringid::html {
namespace {

// What the profile curves plot, and the unit of the figure's y axis.
constexpr char kProfileUnit[] = "Δχ² = 2 Δcost";

void SummarySection(const DatasetBody<IdentifiabilityResult>& body, Page* page) {
  const IdentifiabilityResult& r = body.result;
  page->Summary({{"dataset", TextCell(body.dataset)},
                 {"status", NameCell(r.status.outcome)},
                 {"message", TextCell(r.status.message)},
                 {"rank", NumberCell(r.rank, "%.0f")},
                 {"weighted residuals", NumberCell(r.num_residuals, "%.0f")},
                 {"condition number", NumberCell(r.condition_number)},
                 {"rank explanation", TextCell(r.rank_explanation)},
                 {"largest identifiable subset (pivoted QR over the parameters with no component "
                  "in a free direction)",
                  r.identifiable_subset.empty() ? TextCell("none") : ListCell(r.identifiable_subset)},
                 {"seconds", NumberCell(r.seconds)}});
}

// As IntervalCell, a side that jumped "jumps to another optimum at x", one
// whose refits failed "failed at x", instead of "open".
Cell ProfileCell(const ProfileInterval& profile) {
  if (!profile.computed) return {"–", true};
  const auto end = [](std::optional<double> x, std::optional<double> jump_at,
                      std::optional<double> failed_at) {
    if (x && std::isfinite(*x)) return Format(*x);
    if (jump_at) return "jumps to another optimum at " + Format(*jump_at);
    return failed_at ? "failed at " + Format(*failed_at) : std::string("open");
  };
  return {"[" + end(profile.lower, profile.lower_jump_at, profile.lower_failed_at) + ", " +
              end(profile.upper, profile.upper_jump_at, profile.upper_failed_at) + "]",
          true};
}

// A collinearity index; a pair is listed only above a finite threshold, so
// one that is not finite (infinite, written as null) is exact collinearity.
Cell CollinearityCell(double index) {
  if (!std::isfinite(index)) return {"∞ (exact)", true};
  return NumberCell(index);
}

void ParametersSection(const IdentifiabilityResult& r, Page* page) {
  std::vector<Row> rows;
  for (const ParameterIdentifiability& q : r.parameters) {
    rows.push_back({TextCell(q.key.Text()), NumberCell(q.value), TextCell(Info(q.param()).unit),
                    NameCell(q.identifiable), NumberCell(q.std), IntervalCell(q.wald_95),
                    ProfileCell(q.profile_95), TextCell(q.reason.empty() ? "–" : q.reason)});
  }
  page->Heading("Parameters");
  page->Table({"parameter", "value", "unit", "identifiable", "std", "Wald 95 %", "profile 95 %",
               "reason"},
              rows);
  if (!r.profiles.computed) page->Note("Profile intervals not computed: " + r.profiles.why + ".");
}

void TableSections(const IdentifiabilityResult& r, Page* page) {
  ParametersSection(r, page);
  std::vector<Row> combinations;
  for (const Combination& c : r.combinations) {
    combinations.push_back({TextCell(c.text), TextCell(c.meaning), NumberCell(c.singular_value)});
  }
  page->TableSection("Free and near-free combinations",
                     {"combination", "meaning", "singular value"}, combinations);
  std::vector<Row> pairs;
  for (const CollinearSubset& c : r.collinear_pairs) {
    pairs.push_back({ListCell(c.names), CollinearityCell(c.index)});
  }
  page->TableSection("Collinear pairs", {"parameters", "collinearity index"}, pairs);
  std::vector<Row> advice;
  for (const Advice& a : r.advice) {
    advice.push_back({TextCell(a.parameter), TextCell(a.observation),
                      NumberCell(a.information_gain), PercentCell(a.relative_std_after),
                      YesNoCell(a.makes_identifiable)});
  }
  page->TableSection("Experiment advice",
                     {"parameter", "extra observation", "information gain (nats)",
                      "relative std with it (%)", "makes it identifiable"},
                     advice);
}

void SingularValueFigure(const IdentifiabilityResult& r, Page* page) {
  Series above, below;
  const long count = r.singular_values.size();
  int shown = 0;
  for (long k = 1; k <= count; ++k) {
    const double s = r.singular_values[k - 1];
    if (!std::isfinite(s) || s <= 0) continue;
    (k > r.rank ? below : above).Row({static_cast<double>(k), s});
    ++shown;
  }
  if (shown == 0) {
    page->Note("No singular value figure: the report has no positive singular value.");
    return;
  }
  Figure f("identifiability-singular-values", 760, 380);
  std::ostringstream g;
  g << "set logscale y\nset format y '10^{%L}'\nset grid\n"
    << "set xrange [0.5:" << static_cast<double>(count) + 0.5 << "]\nset xtics 1\n"
    << "set xlabel 'index (largest first)'\nset ylabel 'singular value'\nset key top right\n"
    << "set label 1 "
    << GnuplotString("rank " + std::to_string(r.rank) + " of " +
                     std::to_string(r.coordinate_names.size()) + " free coordinates")
    << " at graph 0.03, graph 0.06 left\n";
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

void CorrelationFigure(const IdentifiabilityResult& r, Page* page) {
  HeatMapOptions map;
  map.name = "identifiability-correlation";
  map.rows = r.coordinate_names;
  map.columns = map.rows;
  const long n = static_cast<long>(map.rows.size());
  bool any = false;
  if (r.correlation.rows() == n && r.correlation.cols() == n) {
    for (long row = 0; row < n; ++row) {
      map.values.emplace_back();
      for (long column = 0; column < n; ++column) {
        const double value = r.correlation(row, column);
        map.values.back().push_back(std::isfinite(value) ? std::optional(value) : std::nullopt);
        any |= std::isfinite(value);
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

// One panel of the profile figure; "" for a curve of fewer than 2 points.
std::string ProfilePanel(Figure* f, const ParameterIdentifiability& q, int column) {
  Series s;
  bool positive = true;
  double low = INFINITY, high = -INFINITY;
  int points = 0;
  for (const auto& [value, delta_chi2] : q.profile_95.curve) {
    if (!std::isfinite(value) || !std::isfinite(delta_chi2)) continue;
    s.Row({value, delta_chi2});
    positive &= value > 0;
    low = std::min(low, value), high = std::max(high, value);
    ++points;
  }
  if (points < 2) return "";
  std::ostringstream g;
  g << "set title " << GnuplotString(q.key.Text()) << " noenhanced\n"
    << (positive ? "set logscale x\n" : "unset logscale x\n")
    << (positive && high > low ? LogTics(low, high) : "set xtics autofreq\n")
    << (column == 0 ? "set ylabel " + GnuplotString(kProfileUnit) + "\n" : "unset ylabel\n");
  if (std::isfinite(q.value)) {
    g << VerticalLine(2, Format(q.value, "%.12g"), "dt 3 lc rgb '#888888'");
  } else {
    g << "unset arrow 2\n";
  }
  g << "plot " << f->AddData(s) << " using 1:2 with linespoints pt 7 ps 0.45 lw 1.5 lc rgb '"
    << kBlue << "' notitle\n";
  return g.str();
}

// Profile likelihood, one panel per parameter, four to a row; the curves
// are in Δχ², so the 95 % threshold is the chi-square(1) point.
void ProfileFigure(const std::vector<ParameterIdentifiability>& parameters, Page* page) {
  const double threshold = kChiSquare1Dof95;
  Figure f("identifiability-profiles");
  std::string panels;
  int n = 0;
  for (const ParameterIdentifiability& q : parameters) {
    const std::string panel = ProfilePanel(&f, q, n % 4);
    if (!panel.empty()) panels += panel, ++n;
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
  f.caption = std::string("Profile likelihood of each parameter: the increase of the misfit, in ") +
              kProfileUnit +
              " (the other parameters re-optimised), against the parameter's value in its unit "
              "(log axis where positive). Red dashed line: the 95 % threshold " +
              Format(threshold, "%.2f") + "; dotted line: the fitted value. Curves beyond " +
              Format(3 * threshold, "%.3g") + " are cut at the top.";
  page->AddFigure(std::move(f));
}

}  // namespace

void IdentifiabilityPage(const IdentifiabilityReport& report, Page* page) {
  const IdentifiabilityResult& r = report.body.result;
  SummarySection(report.body, page);
  TableSections(r, page);
  page->Heading("Figures");
  SingularValueFigure(r, page);
  CorrelationFigure(r, page);
  ProfileFigure(r.parameters, page);
}

}  // namespace ringid::html
