// The page of `ringid compare`: Levenberg–Marquardt against the simplex,
// per method and per start; final costs and convergence.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "apps/html/pages.h"
#include "apps/html/text.h"

namespace ringid::html {
namespace {

// A method's colour and point type in the figures.
const char* MethodColor(Method method) {
  return method == Method::kLevenbergMarquardt ? kBlue : kOrange;
}
int MethodPoint(Method method) { return method == Method::kLevenbergMarquardt ? 7 : 5; }
// A method's short name in column heads.
const char* MethodShortName(Method method) {
  return method == Method::kLevenbergMarquardt ? "LM" : "simplex";
}

void SummarySection(const DatasetBody<ComparisonResult>& body, Page* page) {
  const ComparisonResult& r = body.result;
  FactRows facts = {
      {"dataset", TextCell(body.dataset)},
      {"status", NameCell(r.status.outcome)},
      {"message", TextCell(r.status.message)},
      {"starts", NumberCell(r.starts, "%.0f")},
      {"best cost", NumberCell(r.best_cost)},
      {"cost at the dataset's initial values", NumberCell(r.initial_cost)},
      {"initial values: relative error in-plane (eq. 19)", NumberCell(r.initial_error_in_plane)},
      {"initial values: relative error out-of-plane (eq. 20)",
       NumberCell(r.initial_error_out_of_plane)}};
  if (r.paper_reported) {
    facts.push_back({"paper: relative error in-plane (eq. 19)",
                     NumberCell(r.paper_reported->first)});
    facts.push_back({"paper: relative error out-of-plane (eq. 20)",
                     NumberCell(r.paper_reported->second)});
  }
  page->Summary(facts);
}

// The finite costs of `costs` (positive only if asked), sorted; the others
// are counted in `dropped`.
std::vector<double> SortedCosts(const std::vector<double>& costs, bool positive_only,
                                int* dropped = nullptr) {
  std::vector<double> kept;
  for (double cost : costs) {
    if (std::isfinite(cost) && (!positive_only || cost > 0))
      kept.push_back(cost);
    else if (dropped)
      ++*dropped;
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

// The start with the lowest finite final cost, if any.
std::optional<size_t> BestStart(const MethodRun& m) {
  std::optional<size_t> best;
  for (size_t i = 0; i < m.final_costs.size(); ++i) {
    if (std::isfinite(m.final_costs[i]) && (!best || m.final_costs[i] < m.final_costs[*best]))
      best = i;
  }
  return best;
}

// values[i] of the best start, if there is one.
Cell BestStartCell(const std::vector<double>& values, std::optional<size_t> best) {
  return NumberCell(best && *best < values.size() ? std::optional(values[*best]) : std::nullopt);
}

// The methods table; the most starts of a method.
size_t MethodsSection(const ComparisonResult& r, Page* page) {
  std::vector<Row> rows;
  size_t starts = 0;
  for (const MethodRun& m : r.methods) {
    const std::vector<double> costs = SortedCosts(m.final_costs, false);
    starts = std::max(starts, m.final_costs.size());
    std::optional<double> best, median;
    if (!costs.empty()) best = costs.front(), median = costs[costs.size() / 2];
    const std::optional<size_t> best_start = BestStart(m);
    rows.push_back({TextCell(MethodTitle(m.method)),
                    NumberCell(static_cast<double>(m.final_costs.size()), "%.0f"),
                    PercentCell(m.success_rate), NumberCell(best), NumberCell(median),
                    NumberCell(m.median_evaluations, "%.0f"), NumberCell(m.seconds_per_fit),
                    BestStartCell(m.relative_error_in_plane, best_start),
                    BestStartCell(m.relative_error_out_of_plane, best_start)});
  }
  page->Heading("Methods");
  page->Table({"method", "starts", "success rate (%)", "best final cost", "median final cost",
               "median evaluations", "seconds per fit",
               "best start: relative error in-plane (eq. 19)",
               "best start: relative error out-of-plane (eq. 20)"},
              rows);
  return starts;
}

void PerStartSection(const ComparisonResult& r, size_t starts, Page* page) {
  std::vector<std::string> head = {"start"};
  for (const MethodRun& m : r.methods) {
    head.push_back(std::string(MethodShortName(m.method)) + " final cost");
    head.push_back(std::string(MethodShortName(m.method)) + " evaluations");
  }
  std::vector<Row> rows;
  for (size_t i = 0; i < starts; ++i) {
    Row row = {TextCell(std::to_string(i + 1))};
    for (const MethodRun& m : r.methods) {
      row.push_back(
          NumberCell(i < m.final_costs.size() ? std::optional(m.final_costs[i]) : std::nullopt));
      row.push_back(NumberCell(i < m.evaluations.size()
                                   ? std::optional<double>(m.evaluations[i])
                                   : std::nullopt,
                               "%.0f"));
    }
    rows.push_back(row);
  }
  page->Heading("Per start");
  page->Table(head, rows);
}

// The dashed line of the cost at the initial values; widens `high` to it.
std::string InitialCostLine(double cost, double* high) {
  if (!std::isfinite(cost) || cost <= 0) return "";
  *high = std::max(*high, cost);
  std::ostringstream g;
  g << HorizontalLine(1, StreamFormat(cost), kDashedGrey)
    << "set label 1 'cost at the initial values' at graph 0.98, first " << cost
    << " right offset 0, -0.8 tc rgb '#666666'\n";
  return g.str();
}

// Final costs of every start, sorted, per method.
void FinalCostFigure(const ComparisonResult& r, size_t starts, Page* page) {
  Figure f("compare-final-costs", 800, 400);
  std::vector<std::string> parts;
  int dropped = 0;
  double low = INFINITY, high = 0;
  for (const MethodRun& m : r.methods) {
    const auto costs = SortedCosts(m.final_costs, true, &dropped);
    if (costs.empty()) continue;
    Series s;
    for (size_t i = 0; i < costs.size(); ++i) s.Row({static_cast<double>(i + 1), costs[i]});
    low = std::min(low, costs.front()), high = std::max(high, costs.back());
    parts.push_back(f.AddData(s) + " using 1:2 with linespoints pt " +
                    std::to_string(MethodPoint(m.method)) + " ps 1 lw 1.5 lc rgb '" +
                    MethodColor(m.method) + "' title " + GnuplotString(MethodTitle(m.method)));
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
    << (starts <= 30 ? "set xtics 1\n" : "") << InitialCostLine(r.initial_cost, &high);
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
void AddCostPoint(long evaluations, double cost, Series* s, bool* log_x) {
  if (!std::isfinite(cost) || cost <= 0) return;
  *log_x &= evaluations > 0;
  s->Row({static_cast<double>(evaluations), cost});
}

// One method's cost against evaluations: its traces, or its end points.
Series ConvergenceSeries(const MethodRun& m, bool traces, bool* log_x) {
  Series s;
  if (traces) {
    for (const auto& history : m.histories) {
      for (const auto& [evaluations, cost] : history) AddCostPoint(evaluations, cost, &s, log_x);
      s.Break();
    }
    return s;
  }
  for (size_t i = 0; i < std::min(m.evaluations.size(), m.final_costs.size()); ++i)
    AddCostPoint(m.evaluations[i], m.final_costs[i], &s, log_x);
  return s;
}

// Cost against evaluations: the traces when present, else the end points.
void ConvergenceFigure(const ComparisonResult& r, Page* page) {
  Figure f("compare-convergence", 800, 420);
  std::vector<std::string> parts;
  bool traces = false, log_x = true;
  for (const MethodRun& m : r.methods) {
    for (const auto& history : m.histories) traces |= !history.empty();
  }
  for (const MethodRun& m : r.methods) {
    const Series s = ConvergenceSeries(m, traces, &log_x);
    if (s.empty()) continue;
    parts.push_back(f.AddData(s) + " using 1:2 " +
                    (traces ? "with lines lw 1.2"
                            : "with points pt " + std::to_string(MethodPoint(m.method)) +
                                  " ps 1.2") +
                    " lc rgb '" + MethodColor(m.method) + "' title " +
                    GnuplotString(MethodTitle(m.method)));
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

void ComparePage(const CompareReport& report, Page* page) {
  const ComparisonResult& r = report.body.result;
  SummarySection(report.body, page);
  const size_t starts = MethodsSection(r, page);
  PerStartSection(r, starts, page);
  page->Heading("Figures");
  FinalCostFigure(r, starts, page);
  ConvergenceFigure(r, page);
}

}  // namespace ringid::html
