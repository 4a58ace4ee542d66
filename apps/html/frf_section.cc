// The measured FRFs of an identify page (estimation/frf_fits.h): a table of
// each function's chi-square and FRAC, and per function its measured and
// fitted magnitude and phase and its normalised residuals over frequency.
#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>
#include <sstream>

#include "apps/html/frf_section.h"
#include "apps/html/text.h"

namespace ringid::html {
namespace {

// At most this many functions are drawn (those furthest from the model, by
// chi-square per value); the table lists all.
constexpr int kMostFrfFigures = 32;
constexpr double kDegrees = 180 / M_PI;

std::string FunctionName(const FrfFit& f) {
  return (f.condition ? *f.condition + " " : "") + f.output + "/" + f.input;
}

// The panels' series: magnitude and phase of measured (points) and model
// (a line broken where the phase wraps), residuals re and im in sigma.
struct FrfSeries {
  Series measured_magnitude, model_magnitude, measured_phase, model_phase, residual_re,
      residual_im;
  bool positive = false;  // some magnitude > 0: the log axis has something to show
};

FrfSeries SeriesOf(const FrfFit& f) {
  FrfSeries s;
  std::optional<double> last_phase;
  for (size_t l = 0; l < f.frequency_hz.size(); ++l) {
    const std::complex<double> m(f.measured_re[l], f.measured_im[l]);
    const std::complex<double> x(f.model_re[l], f.model_im[l]);
    const double hz = f.frequency_hz[l];
    const auto magnitude = [&s](double v) {
      s.positive |= v > 0;
      return v > 0 ? std::optional<double>(v) : std::nullopt;
    };
    s.measured_magnitude.Row({hz, magnitude(std::abs(m))});
    s.model_magnitude.Row({hz, magnitude(std::abs(x))});
    // The phase of 0 is not defined: not drawn (a function the model does
    // not couple is 0 at every line).
    const auto phase = [](std::complex<double> v) {
      return std::abs(v) > 0 ? std::optional<double>(std::arg(v) * kDegrees) : std::nullopt;
    };
    s.measured_phase.Row({hz, phase(m)});
    const std::optional<double> model_phase = phase(x);
    if (last_phase && model_phase && std::abs(*model_phase - *last_phase) > 180) {
      s.model_phase.Break();  // wrapped at ±180°: no line across the graph
    }
    s.model_phase.Row({hz, model_phase});
    last_phase = model_phase;
    const std::complex<double> z = (x - m) / f.sigma[l];  // the fit's rows
    s.residual_re.Row({hz, z.real()});
    s.residual_im.Row({hz, z.imag()});
  }
  return s;
}

std::string FrfScript(Figure* fig, const FrfFit& f, const FrfModelNames& names) {
  const FrfSeries s = SeriesOf(f);
  const double h = fig->height;
  const double low = f.frequency_hz.front(), high = f.frequency_hz.back();
  const std::string points = " using 1:2 with points pt 7 ps 0.5 lc rgb '";
  std::ostringstream g;
  g << "set multiplot\n"
    << "set lmargin at screen 0.11\nset rmargin at screen 0.80\n"
    << "set xrange [" << Format(low, "%.12g") << ":"
    << Format(high > low ? high : low + 1, "%.12g") << "]\n"
    << "set grid xtics ytics\nset format x ''\nunset xlabel\n"
    << "set key at screen 0.82, screen " << 1 - 20 / h << " left top noenhanced\n";
  // Top: |H| on a log axis.
  g << ScreenMargins(*fig, 20, 0.66 * h);
  if (s.positive) g << "set logscale y\nset format y '%g'\n";
  g << "set ylabel '|H| (per N)'\n"
    << "plot " << fig->AddData(s.measured_magnitude) << points << kBlue
    << "' title 'measured', " << fig->AddData(s.model_magnitude)
    << " using 1:2 with lines lw 2 lc rgb '" << kOrange << "' title "
    << GnuplotString(names.curve) << "\n"
    << "unset logscale y\nunset key\n";
  // Middle: phase in degrees.
  g << ScreenMargins(*fig, 0.36 * h, 0.38 * h)
    << "set yrange [-180:180]\nset ytics 90\nset ylabel 'phase (°)'\n"
    << "plot " << fig->AddData(s.measured_phase) << points << kBlue << "' notitle, "
    << fig->AddData(s.model_phase) << " using 1:2 with lines lw 2 lc rgb '" << kOrange
    << "' notitle\n"
    << "set autoscale y\nset ytics autofreq\n";
  // Bottom: the residuals in sigma, with the key of their own.
  g << ScreenMargins(*fig, 0.64 * h, 55) << "set format x '%g'\nset xlabel 'frequency (Hz)'\n"
    << "set ylabel " << GnuplotString("(" + names.residual + " − measured) / σ") << "\n"
    << HorizontalLine(1, "0", kAxisLine) << HorizontalLine(2, "2", kDashedGrey)
    << HorizontalLine(3, "-2", kDashedGrey)
    << "set key at screen 0.82, screen " << 0.36 << " left top noenhanced\n"
    << "plot " << fig->AddData(s.residual_re) << points << kBlue << "' title 'real part', "
    << fig->AddData(s.residual_im) << points << kOrange << "' title 'imaginary part'\n"
    << "unset multiplot\n";
  return g.str();
}

}  // namespace

void FrfTable(const std::optional<std::vector<FrfFit>>& frfs, Page* page) {
  if (!frfs) return;
  const bool conditions =
      std::any_of(frfs->begin(), frfs->end(), [](const FrfFit& f) { return f.condition; });
  std::vector<Row> rows;
  for (const FrfFit& f : *frfs) {
    Row row;
    if (conditions) row.push_back(TextCell(f.condition.value_or("–")));
    for (Cell cell : {TextCell(f.output), TextCell(f.input),
                      NumberCell(f.lines(), "%.0f"), NumberCell(f.chi2),
                      NumberCell(f.values(), "%.0f"), NumberCell(f.chi2 / f.values(), "%.3f"),
                      NumberCell(f.frac, "%.4f")}) {
      row.push_back(cell);
    }
    rows.push_back(row);
  }
  std::vector<std::string> head = {"output", "input", "lines", "χ²", "values", "χ² / values",
                                   "FRAC"};
  if (conditions) head.insert(head.begin(), "condition");
  page->Heading("Frequency response functions");
  page->Note(
      "Each measured function against the fitted model over the lines fitted (the band). χ²: "
      "its share of the fit's, the squared real and imaginary parts of (fitted − measured) / σ "
      "summed over its lines, two values per line; near 1 per value where the model fits within "
      "the noise. FRAC (frequency response assurance criterion, Heylen & Lammens 1996): "
      "|Σ H_measured* H_fitted|² / (Σ |H_measured|² Σ |H_fitted|²) over the lines, 1 where the "
      "two have the same shape over frequency; symmetric, and blind to a complex factor (a "
      "fitted function twice the measured has FRAC 1), which χ² sees. “–” where the fitted "
      "function is zero at every line (standing, from one plane to the other), where FRAC is "
      "not defined and χ² measures the noise alone.");
  page->Table(head, rows);
}

void FrfFigures(const std::optional<std::vector<FrfFit>>& frfs, Page* page) {
  if (!frfs) return;
  std::vector<size_t> order(frfs->size());
  std::iota(order.begin(), order.end(), 0);
  const auto per_value = [&](size_t k) {
    const FrfFit& f = (*frfs)[k];
    return f.values() > 0 ? f.chi2 / f.values() : 0.0;
  };
  std::vector<size_t> drawn = order;
  if (static_cast<int>(drawn.size()) > kMostFrfFigures) {  // the worst, in report order
    std::stable_sort(drawn.begin(), drawn.end(),
                     [&](size_t a, size_t b) { return per_value(a) > per_value(b); });
    drawn.resize(kMostFrfFigures);
    std::sort(drawn.begin(), drawn.end());
    page->Note("FRF figures: the " + std::to_string(kMostFrfFigures) + " of " +
               std::to_string(frfs->size()) +
               " functions with the largest χ² per value; the table lists every one.");
  }
  for (size_t k : drawn) {
    const FrfFit& f = (*frfs)[k];
    if (f.frequency_hz.empty()) continue;
    page->AddFigure(FrfFigure(f, "identify-frf-" + std::to_string(k + 1)));
  }
}

Figure FrfFigure(const FrfFit& f, const std::string& name, const FrfModelNames& names) {
  Figure fig(name, 900, 640);
  fig.script = FrfScript(&fig, f, names);
  const std::string frac = std::isfinite(f.frac) ? "FRAC " + Format(f.frac, "%.4f")
                                                 : "FRAC not defined: the " + names.residual +
                                                       " function is 0";
  fig.caption = "FRF " + FunctionName(f) + " (χ² " + Format(f.chi2) + " on " +
                std::to_string(f.values()) + " values, " + frac + "): measured (dots) and " +
                names.curve + " (line) against frequency (Hz). Top: magnitude |H|, the "
                "output's SI unit per newton (m/s² per N for an accelerometer), log axis; "
                "middle: phase (degrees); bottom: the residuals the fit weighs, real and "
                "imaginary parts of (" + names.residual + " − measured) / σ, dashed at ± 2.";
  return fig;
}

}  // namespace ringid::html
