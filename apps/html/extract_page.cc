// The page of `ringid extract --report`: the physical poles, and per
// condition its stabilisation diagram, each function's FRAC, the measured
// functions against their LSFD synthesis in small multiples, and those of
// the largest χ² per value in full (apps/html/frf_section.h).
#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>
#include <sstream>

#include "apps/html/frf_section.h"
#include "apps/html/pages.h"
#include "apps/html/text.h"

namespace ringid::html {
namespace {

// Panels per small-multiples figure (rows of kColumns) and the functions of
// the largest χ² per value drawn in full.
constexpr int kColumns = 4;
constexpr int kPanelRows = 8;
constexpr int kFullFigures = 3;

const FrfModelNames kLsfd{"LSFD synthesis", "synthesised"};

std::string ConditionTitle(const ExtractCondition& c) {
  return "condition " + (c.name && !c.name->empty() ? *c.name : std::to_string(c.condition));
}

std::string ShapeText(const ExtractedPole& p) {
  if (!p.label) return "–";
  return p.shape ? "on the model's coordinates" : "none: the outputs do not determine it";
}

void PolesTable(const ExtractBody& b, Page* page) {
  const bool several = b.conditions.size() > 1;
  const bool sigmas = std::any_of(b.poles.begin(), b.poles.end(), [](const ExtractedPole& p) {
    return p.frequency_sigma_hz || p.damping_sigma;
  });
  std::vector<Row> rows;
  for (const ExtractedPole& p : b.poles) {
    Row row;
    if (several) row.push_back(NumberCell(p.condition, "%.0f"));
    row.push_back(NumberCell(p.frequency_hz, "%.3f"));
    if (sigmas) row.push_back(NumberCell(p.frequency_sigma_hz, "%.3g"));
    row.push_back(NumberCell(p.damping_ratio, "%.4f"));
    if (sigmas) row.push_back(NumberCell(p.damping_sigma, "%.3g"));
    row.push_back(NumberCell(p.stable_orders, "%.0f"));
    row.push_back(TextCell(p.label ? LabelName(*p.label) : "not kept"));
    row.push_back(TextCell(ShapeText(p)));
    rows.push_back(row);
  }
  std::vector<std::string> head = {"Hz", "damping ratio", "stable orders", "label", "shape"};
  if (sigmas) {
    head.insert(head.begin() + 1, "σ Hz");
    head.insert(head.begin() + 3, "σ damping ratio");
  }
  if (several) head.insert(head.begin(), "condition");
  page->Heading("Physical poles");
  page->Note("pLSCF's physical poles: clusters of stable poles of the stabilisation diagram, "
             "found at the number of orders given, with positive damping, in the band. The "
             "strongest (as many as the model has modes) are labelled by fit and written to "
             "the modal dataset; a shape where the outputs determine the model's coordinates.");
  page->Table(head, rows);
}

// The diagram's poles in [low, high] by their stability, the physical poles
// as vertical lines, and the sum of the measured |H| on a second axis.
Figure DiagramFigure(const ExtractCondition& c, const ExtractBlock& block,
                     const std::vector<ExtractedPole>& poles, double low, double high,
                     const std::string& name, const std::string& title) {
  Figure fig(name, 900, 560);
  Series stable, frequency, other, physical, sum;
  int lowest = block.diagram.front().order, highest = block.diagram.front().order;
  for (const DiagramOrder& o : block.diagram) {
    lowest = std::min(lowest, o.order);
    highest = std::max(highest, o.order);
    for (const DiagramPole& p : o.poles) {
      if (p.frequency_hz < low || p.frequency_hz > high) continue;
      Series& s = p.stable() ? stable : p.stable_frequency ? frequency : other;
      s.Row({p.frequency_hz, static_cast<double>(o.order)});
    }
  }
  for (const ExtractedPole& p : poles) {
    if (p.condition != c.condition) continue;
    physical.Row({p.frequency_hz, lowest - 0.5});
    physical.Row({p.frequency_hz, highest + 0.5});
    physical.Break();
  }
  const auto in = [](const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
  };
  bool positive = false;
  if (!c.functions.empty()) {
    for (size_t l = 0; l < c.functions.front().frequency_hz.size(); ++l) {
      double total = 0;
      for (const FrfFit& f : c.functions) {
        if (!in(block.inputs, f.input) || !in(block.outputs, f.output)) continue;
        total += std::abs(std::complex<double>(f.measured_re[l], f.measured_im[l]));
      }
      positive |= total > 0;
      sum.Row({c.functions.front().frequency_hz[l],
               total > 0 ? std::optional<double>(total) : std::nullopt});
    }
  }
  std::ostringstream g;
  g << "set xrange [" << Format(low, "%.12g") << ":" << Format(high > low ? high : low + 1, "%.12g")
    << "]\nset yrange [" << lowest - 0.5 << ":" << highest + 0.5 << "]\n"
    << "set xlabel 'frequency (Hz)'\nset ylabel 'model order'\nset grid xtics ytics\n"
    << "set key outside below center horizontal noenhanced\n";
  std::vector<std::string> parts;
  if (positive) {
    g << "set logscale y2\nset y2tics\nset format y2 '%g'\nset ytics nomirror\n"
      << "set y2label 'Σ |H| over the functions of the block (measured)'\n";
    parts.push_back(fig.AddData(sum) + " using 1:2 axes x1y2 with lines lw 1 lc rgb '" + kGrey +
                    "' title 'Σ |H|'");
  }
  if (!physical.empty()) {
    parts.push_back(fig.AddData(physical) + " using 1:2 with lines dt 2 lw 1.5 lc rgb '" + kRed +
                    "' title 'physical pole'");
  }
  const auto points = [&](const Series& s, const std::string& style, const std::string& title) {
    if (!s.empty()) parts.push_back(fig.AddData(s) + " using 1:2 with points " + style + " title '" + title + "'");
  };
  points(other, "pt 1 ps 0.5 lc rgb '" + std::string(kGrey) + "'", "not stable");
  points(frequency, "pt 6 ps 0.6 lc rgb '" + std::string(kBlue) + "'", "stable in frequency");
  points(stable, "pt 7 ps 0.6 lc rgb '" + std::string(kGreen) + "'",
         "stable (frequency, damping, vector)");
  if (parts.empty()) parts.push_back("NaN notitle");  // no pole in the band: the axes alone
  g << PlotCommand(parts);
  fig.script = g.str();
  fig.caption = "Stabilisation diagram, " + title + ": the poles of each model order "
                "of pLSCF in the band (Im λ > 0, damped frequency in Hz) against the order. "
                "Filled: stable against the order below in frequency, damping and participation "
                "vector; open: in frequency only; crosses: neither. Dashed: the condition's "
                "physical poles. Grey, right axis: the sum of the measured |H| over the block's "
                "functions (log).";
  return fig;
}

void FracTable(const ExtractCondition& c, Page* page) {
  std::vector<Row> rows;
  for (const FrfFit& f : c.functions) {
    rows.push_back({TextCell(f.output), TextCell(f.input), NumberCell(f.lines(), "%.0f"),
                    NumberCell(f.values() > 0 ? f.chi2 / f.values() : NAN, "%.3f"),
                    NumberCell(f.frac, "%.6f")});
  }
  page->Table({"output", "input", "lines", "χ² / values", "FRAC"}, rows);
  page->Note("Each measured function against its LSFD synthesis at the physical poles (with the "
             "lower and upper residuals) over the lines pLSCF used. FRAC (frequency response "
             "assurance criterion): |Σ H_measured* H_synthesised|² / (Σ |H_measured|² "
             "Σ |H_synthesised|²), 1 where the two have the same shape over frequency. χ²: the "
             "squared real and imaginary parts of (synthesised − measured) / σ summed over the "
             "lines, two values per line; near 1 per value where the modal model fits within "
             "the noise. A function the structure does not couple (standing: from one plane to "
             "the other, or the top's vertical motion from a tangential blow) is noise alone: "
             "its FRAC is low however good the extraction, and its χ² near 1 per value says so. "
             "The figures after the small multiples draw the " + std::to_string(kFullFigures) +
             " functions of the largest χ² per value in full.");
}

// A round step (1, 2 or 5 times a power of ten) giving at most about five
// tics over `range`: a small panel's axis.
double TicStep(double range) {
  if (!(range > 0) || !std::isfinite(range)) return 1;
  const double raw = range / 5, decade = std::pow(10, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * decade >= raw) return m * decade;
  }
  return 10 * decade;
}

// |H| measured and synthesised of `functions[first, last)`, a panel each.
Figure SmallMultiples(const ExtractCondition& c, size_t first, size_t last,
                      const std::string& name) {
  const int panels = static_cast<int>(last - first);
  const int columns = std::min(panels, kColumns), rows = (panels + columns - 1) / columns;
  Figure fig(name, 240 * columns + 40, 190 * rows + 30);
  std::ostringstream g;
  const std::vector<double>& hz = c.functions[first].frequency_hz;
  const double step = hz.empty() ? 1 : TicStep(hz.back() - hz.front());
  g << "set multiplot layout " << rows << "," << columns << "\n"
    << "set logscale y\nset format y '%.0e'\nset format x '%g'\nset grid xtics ytics\n"
    << "unset key\nset xtics " << Format(step, "%g") << " font ',8'\nset ytics font ',8'\n";
  for (size_t k = first; k < last; ++k) {
    const FrfFit& f = c.functions[k];
    Series measured, model;
    for (size_t l = 0; l < f.frequency_hz.size(); ++l) {
      const auto positive = [](double v) { return v > 0 ? std::optional<double>(v) : std::nullopt; };
      measured.Row({f.frequency_hz[l],
                    positive(std::abs(std::complex<double>(f.measured_re[l], f.measured_im[l])))});
      model.Row({f.frequency_hz[l],
                 positive(std::abs(std::complex<double>(f.model_re[l], f.model_im[l])))});
    }
    if (!f.frequency_hz.empty() && f.frequency_hz.back() > f.frequency_hz.front()) {
      g << "set xrange [" << Format(f.frequency_hz.front(), "%.12g") << ":"
        << Format(f.frequency_hz.back(), "%.12g") << "]\n";
    }
    g << "set title " << GnuplotString(f.output + " / " + f.input + "   FRAC " + Format(f.frac, "%.4f"))
      << " noenhanced font ',9'\n"
      << "plot " << fig.AddData(measured) << " using 1:2 with points pt 7 ps 0.25 lc rgb '"
      << kBlue << "', " << fig.AddData(model) << " using 1:2 with lines lw 1.5 lc rgb '"
      << kOrange << "'\n";
  }
  g << "unset multiplot\n";
  fig.script = g.str();
  fig.caption = "Measured |H| (blue dots) and its LSFD synthesis (orange line) against "
                "frequency (Hz), " + ConditionTitle(c) + ", functions " + std::to_string(first + 1) +
                " to " + std::to_string(last) + " of " + std::to_string(c.functions.size()) +
                " (output / input, FRAC): the output's SI unit per newton, log axis, each panel "
                "its own scale.";
  return fig;
}

void ConditionSection(const ExtractBody& b, const ExtractCondition& c, Page* page) {
  const std::string id = "extract-c" + std::to_string(c.condition);
  page->Heading("Stabilisation diagram, " + ConditionTitle(c));
  if (!c.status.ok()) {
    page->Note("No extraction: " + c.status.message);
    return;
  }
  double low = INFINITY, high = -INFINITY;
  for (const FrfFit& f : c.functions) {
    if (f.frequency_hz.empty()) continue;
    low = std::min(low, f.frequency_hz.front());
    high = std::max(high, f.frequency_hz.back());
  }
  if (c.blocks.size() > 1) {
    page->Note("No output is measured at every input: pLSCF fitted each block of inputs with "
               "the outputs measured at all of them on its own, and LSFD and the refinement "
               "all functions at the poles of all blocks.");
  }
  for (size_t k = 0; k < c.blocks.size(); ++k) {
    const ExtractBlock& block = c.blocks[k];
    std::string title = ConditionTitle(c);
    if (c.blocks.size() > 1) {
      title += ", inputs " + Join(block.inputs, ", ") + " to outputs " + Join(block.outputs, ", ");
    }
    if (!block.diagram.empty() && low <= high) {
      page->AddFigure(DiagramFigure(c, block, b.poles, low, high,
                                    id + "-diagram" + (k > 0 ? "-" + std::to_string(k + 1) : ""), title));
    } else {
      page->Note("No stabilisation diagram, " + title + ": no order or no line.");
    }
  }
  if (c.functions.empty()) return;
  page->Heading("Measured and synthesised FRFs, " + ConditionTitle(c));
  FracTable(c, page);
  const size_t per_figure = kColumns * kPanelRows;
  for (size_t first = 0; first < c.functions.size(); first += per_figure) {
    const size_t last = std::min(c.functions.size(), first + per_figure);
    page->AddFigure(SmallMultiples(c, first, last, id + "-frfs-" + std::to_string(first + 1)));
  }
  // The functions of the largest χ² per value in full: magnitude, phase, residuals.
  std::vector<size_t> order(c.functions.size());
  std::iota(order.begin(), order.end(), 0);
  const auto per_value = [&](size_t k) {
    const FrfFit& f = c.functions[k];
    return f.values() > 0 ? f.chi2 / f.values() : 0.0;
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t d) { return per_value(a) > per_value(d); });
  order.resize(std::min<size_t>(order.size(), kFullFigures));
  for (size_t k : order) {
    if (c.functions[k].frequency_hz.empty()) continue;
    FrfFit f = c.functions[k];
    if (b.conditions.size() > 1) f.condition = ConditionTitle(c);  // in its caption
    page->AddFigure(FrfFigure(f, id + "-frf-" + std::to_string(k + 1), kLsfd));
  }
}

// The direct and the modal route, per parameter both determine.
void RoutesTable(const ExtractBody& b, Page* page) {
  if (b.routes.empty()) return;
  std::vector<Row> rows;
  for (const RouteRow& r : b.routes) {
    rows.push_back({TextCell(r.parameter), NumberCell(r.direct, "%.5g"), NumberCell(r.direct_std, "%.3g"),
                    NumberCell(r.modal, "%.5g"), NumberCell(r.modal_std, "%.3g"),
                    NumberCell(r.DifferenceSd(), "%.2f"), NumberCell(r.StdRatio(), "%.2g")});
  }
  page->Heading("The two routes");
  page->Note("identify on the FRFs (the direct route) and on the extracted modes with the masses "
             "known at their initial values (the modal route), for the parameters both class "
             "identifiable: their difference in combined standard errors, and how many times "
             "wider the modal route's standard error is.");
  page->Table({"parameter", "direct", "σ", "modal", "σ", "difference (σ)", "σ ratio"}, rows);
}

}  // namespace

void ExtractPage(const ExtractReport& report, Page* page) {
  const ExtractBody& b = report.body;
  page->Summary({{"dataset", TextCell(b.dataset)},
                 {"status", TextCell(ToString(b.status.outcome))},
                 {"message", TextCell(b.status.message)},
                 {"conditions with FRFs", NumberCell(b.conditions.size(), "%.0f")},
                 {"physical poles", NumberCell(b.poles.size(), "%.0f")}});
  for (const std::string& note : b.notes) page->Note("Note: " + note);
  PolesTable(b, page);
  RoutesTable(b, page);
  for (const ExtractCondition& c : b.conditions) ConditionSection(b, c, page);
}

// `ringid poles --report`: the poles with their standard errors, then each
// condition's diagram and synthesis as extract's.
void PolesPage(const PolesReport& report, Page* page) {
  const PolesBody& b = report.body;
  page->Summary({{"file", TextCell(b.dataset)},
                 {"status", TextCell(ToString(b.status.outcome))},
                 {"message", TextCell(b.status.message)},
                 {"physical poles", NumberCell(b.poles.poles.size(), "%.0f")}});
  for (const std::string& note : b.poles.notes) page->Note("Note: " + note);
  std::vector<Row> rows;
  ExtractBody lines;  // the poles as the diagrams mark them
  for (const FoundPole& p : b.poles.poles) {
    if (p.condition < 0 || p.condition >= static_cast<int>(b.poles.conditions.size())) continue;
    const PolesCondition& c = b.poles.conditions[p.condition];
    rows.push_back({TextCell(c.name), NumberCell(p.frequency_hz, "%.4f"),
                    NumberCell(p.frequency_sigma_hz, "%.3g"), NumberCell(p.damping_ratio, "%.5f"),
                    NumberCell(p.damping_sigma, "%.3g"), NumberCell(p.stable_orders, "%.0f")});
    ExtractedPole marked;
    marked.condition = p.condition;
    marked.frequency_hz = p.frequency_hz;
    lines.poles.push_back(marked);
  }
  page->Heading("Physical poles");
  page->Note("Clusters of stable poles of pLSCF's stabilisation diagram, refined by maximum "
             "likelihood with their standard errors (σ); the noise of each condition is the "
             "file's (coherence) or estimated from the residuals of the fit, as its line below says.");
  page->Table({"condition", "Hz", "σ Hz", "damping ratio", "σ damping ratio", "stable orders"}, rows);
  for (const PolesCondition& c : b.poles.conditions) {
    page->Note(c.name + ": " + std::to_string(c.functions) + " FRFs, " + std::to_string(c.lines) +
               " lines, orders 1-" + std::to_string(c.max_order) + ", noise " + c.noise +
               ", residues in " + c.units + ".");
  }
  lines.conditions = b.conditions;
  for (const ExtractCondition& c : b.conditions) ConditionSection(lines, c, page);
}

}  // namespace ringid::html
