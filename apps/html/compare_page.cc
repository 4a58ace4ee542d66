// The page of `ringid compare`: Levenberg–Marquardt against the simplex,
// per method and per start; final costs and convergence.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "apps/html/pages.h"
#include "apps/html/text.h"

namespace ringid::html {
namespace {

const std::vector<FactSpec> kSummary = {
    {"dataset"}, {"success"}, {"message"}, {"starts"}, {"best_cost"},
    {"initial/cost", "cost at the dataset's initial values"},
    {"initial/relative_error_in_plane_eq19", "initial values: relative error in-plane (eq. 19)"},
    {"initial/relative_error_out_of_plane_eq20",
     "initial values: relative error out-of-plane (eq. 20)"},
    {"paper_reported/relative_error_in_plane_eq19", "paper: relative error in-plane (eq. 19)"},
    {"paper_reported/relative_error_out_of_plane_eq20",
     "paper: relative error out-of-plane (eq. 20)"}};

const char* const kColors[] = {kBlue, kOrange};
const int kPoints[] = {7, 5};

// The costs of `list` that are numbers (positive only if asked), sorted.
std::vector<double> SortedCosts(const json& list, bool positive_only, int* dropped = nullptr) {
  std::vector<double> costs;
  for (const json& c : list) {
    const auto v = Num(c);
    if (v && (!positive_only || *v > 0))
      costs.push_back(*v);
    else if (dropped)
      ++*dropped;
  }
  std::sort(costs.begin(), costs.end());
  return costs;
}

// The methods table; the most starts of a method.
size_t MethodsSection(const json& report, Page* page) {
  std::vector<Row> rows;
  size_t starts = 0;
  for (const auto& [key, title] : kMethods) {
    const json& m = Get(report, key);
    if (!m.is_object()) continue;
    const std::vector<double> costs = SortedCosts(List(m, "final_costs"), false);
    starts = std::max(starts, List(m, "final_costs").size());
    std::optional<double> best, median;
    if (!costs.empty()) best = costs.front(), median = costs[costs.size() / 2];
    rows.push_back({TextCell(title), ValueCell(Get(m, "starts")),
                    NumberCell(Num(m, "success_rate")), NumberCell(best), NumberCell(median),
                    NumberCell(Num(m, "median_evaluations"), "%.0f"),
                    NumberCell(Num(m, "seconds_per_fit"))});
  }
  page->Heading("Methods");
  page->Table({"method", "starts", "success rate", "best final cost", "median final cost",
               "median evaluations", "seconds per fit"},
              rows);
  return starts;
}

void PerStartSection(const json& report, size_t starts, Page* page) {
  std::vector<Row> rows;
  for (size_t i = 0; i < starts; ++i) {
    Row row = {TextCell(std::to_string(i + 1))};
    for (const auto& [key, title] : kMethods) {
      const json& costs = List(Get(report, key), "final_costs");
      const json& evaluations = List(Get(report, key), "evaluations");
      row.push_back(NumberCell(i < costs.size() ? Num(costs[i]) : std::nullopt));
      row.push_back(
          NumberCell(i < evaluations.size() ? Num(evaluations[i]) : std::nullopt, "%.0f"));
    }
    rows.push_back(row);
  }
  page->Heading("Per start");
  page->Table(
      {"start", "LM final cost", "LM evaluations", "simplex final cost", "simplex evaluations"},
      rows);
}

// The dashed line of the cost at the initial values; widens `high` to it.
std::string InitialCostLine(const json& report, double* high) {
  const auto c = Num(Get(report, "initial"), "cost");
  if (!c || *c <= 0) return "";
  *high = std::max(*high, *c);
  std::ostringstream g;
  g << HorizontalLine(1, StreamFormat(*c), kDashedGrey)
    << "set label 1 'cost at the initial values' at graph 0.98, first " << *c
    << " right offset 0, -0.8 tc rgb '#666666'\n";
  return g.str();
}

// Final costs of every start, sorted, per method.
void FinalCostFigure(const json& report, size_t starts, Page* page) {
  Figure f("compare-final-costs", 800, 400);
  std::vector<std::string> parts;
  int dropped = 0;
  double low = INFINITY, high = 0;
  for (int k = 0; k < 2; ++k) {
    const auto costs =
        SortedCosts(List(Get(report, kMethods[k].key), "final_costs"), true, &dropped);
    if (costs.empty()) continue;
    Series s;
    for (size_t i = 0; i < costs.size(); ++i) s.Row({i + 1.0, costs[i]});
    low = std::min(low, costs.front()), high = std::max(high, costs.back());
    parts.push_back(f.AddData(s) + " using 1:2 with linespoints pt " + std::to_string(kPoints[k]) +
                    " ps 1 lw 1.5 lc rgb '" + kColors[k] + "' title " +
                    GnuplotString(kMethods[k].title));
  }
  if (parts.empty()) {
    page->Note("No final-cost figure: the report has no positive final cost.");
    return;
  }
  std::ostringstream g;
  g << "set logscale y\nset format y '10^{%L}'\nset grid\nset key left center\n"
    << "set xlabel 'start, sorted by final cost'\nset ylabel 'final cost (½ Σ weighted "
       "residual²)'\n"
    << "set offsets 0.3, 0.3, 0, 0\n"
    << (starts <= 30 ? "set xtics 1\n" : "") << InitialCostLine(report, &high);
  g << "set yrange [" << low / 5 << ":" << high * 20 << "]\n" << PlotCommand(parts);
  f.script = g.str();
  f.caption =
      "Final cost of every start, sorted, per method, on a log axis (cost = ½ Σ weighted "
      "residual², dimensionless). The dashed line is the cost at the dataset's initial values.";
  if (dropped)
    f.caption += " " + std::to_string(dropped) + " zero or missing cost(s) are not drawn.";
  page->AddFigure(std::move(f));
}

// Adds a point (evaluations, cost) with a positive cost; x stays logarithmic
// while every evaluation count is positive.
void AddCostPoint(const json& evaluations, const json& cost, Series* s, bool* log_x) {
  const auto e = Num(evaluations), c = Num(cost);
  if (!e || !c || *c <= 0) return;
  *log_x &= *e > 0;
  s->Row({e, c});
}

// One method's cost against evaluations: its traces, or its end points.
Series ConvergenceSeries(const json& m, bool traces, bool* log_x) {
  Series s;
  if (traces) {
    for (const json& h : List(m, "histories")) {
      if (!h.is_array()) continue;
      for (const json& point : h) {
        if (point.is_array() && point.size() == 2) AddCostPoint(point[0], point[1], &s, log_x);
      }
      s.Break();
    }
    return s;
  }
  const json& evaluations = List(m, "evaluations");
  const json& costs = List(m, "final_costs");
  for (size_t i = 0; i < std::min(evaluations.size(), costs.size()); ++i)
    AddCostPoint(evaluations[i], costs[i], &s, log_x);
  return s;
}

// Cost against evaluations: the traces when present, else the end points.
void ConvergenceFigure(const json& report, Page* page) {
  Figure f("compare-convergence", 800, 420);
  std::vector<std::string> parts;
  bool traces = false, log_x = true;
  for (const auto& [key, title] : kMethods) traces |= !List(Get(report, key), "histories").empty();
  for (int k = 0; k < 2; ++k) {
    const Series s = ConvergenceSeries(Get(report, kMethods[k].key), traces, &log_x);
    if (s.empty()) continue;
    parts.push_back(f.AddData(s) + " using 1:2 " +
                    (traces ? "with lines lw 1.2"
                            : "with points pt " + std::to_string(kPoints[k]) + " ps 1.2") +
                    " lc rgb '" + kColors[k] + "' title " + GnuplotString(kMethods[k].title));
  }
  if (parts.empty()) {
    page->Note("No convergence figure: the report has no evaluations with a positive cost.");
    return;
  }
  std::ostringstream g;
  g << "set logscale y\nset format y '10^{%L}'\n"
    << (log_x ? "set logscale x\n" : "") << "set grid\nset key bottom left opaque box\n"
    << "set xlabel 'model evaluations" << (log_x ? " (log scale)" : "") << "'\n"
    << "set ylabel 'cost (½ Σ weighted residual²)'\n"
    << PlotCommand(parts);
  f.script = g.str();
  f.caption = traces ? "Cost against the number of model evaluations, one line per start, on log "
                       "axes (cost = ½ Σ weighted residual², dimensionless)."
                     : "Final cost against the number of model evaluations, one point per start, "
                       "on log axes (cost = ½ Σ weighted residual², dimensionless).";
  page->AddFigure(std::move(f));
}

}  // namespace

void ComparePage(const json& report, Page* page) {
  page->Summary(FactsOf(report, kSummary));
  const size_t starts = MethodsSection(report, page);
  PerStartSection(report, starts, page);
  page->Heading("Figures");
  FinalCostFigure(report, starts, page);
  ConvergenceFigure(report, page);
}

}  // namespace ringid::html
