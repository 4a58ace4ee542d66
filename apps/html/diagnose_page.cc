// The page of `ringid diagnose`: the verdict, the effects ranked, the misfit
// per mode before and after; misfit, ranking and shrink figures.
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "apps/html/pages.h"
#include "apps/html/text.h"

namespace ringid::html {
namespace {

const std::vector<FactSpec> kSummary = {
    {"dataset"}, {"success"}, {"message"}, {"verdict/effect", "verdict"},
    {"verdict/explanation", "explanation"}, {"verdict/indistinguishable", "indistinguishable from"},
    {"gap_before/chi2", "gap before: χ²"}, {"gap_before/dof", "gap before: degrees of freedom"},
    {"gap_before/excess", "gap before: χ² in excess of its dof"},
    {"gap_before/p_value", "gap before: p-value"}, {"gap_before/significant", "gap significant"},
    {"absorbed", "absorbed by re-calibration"}, {"seconds"}};

// One mode's misfit, in σ of its measurement.
struct Misfit {
  std::optional<double> frequency, damping, shape, chi2, shrink;
};

// The misfit per mode label.
struct Misfits {
  std::vector<std::string> labels;  // in report order, before then after
  std::map<std::string, Misfit> before, after;
  bool has_after = false;

  Misfit Before(const std::string& label) const { return Find(before, label); }
  Misfit After(const std::string& label) const { return Find(after, label); }

 private:
  static Misfit Find(const std::map<std::string, Misfit>& set, const std::string& label) {
    const auto it = set.find(label);
    return it == set.end() ? Misfit() : it->second;
  }
};

std::map<std::string, Misfit> ReadMisfits(const json& where, std::vector<std::string>* order) {
  std::map<std::string, Misfit> out;
  for (const json& w : where) {
    const std::string label = Str(w, "label");
    Misfit m;
    m.frequency = Num(w, "frequency_sigma");
    m.damping = Num(w, "damping_sigma");
    if (const auto s = Num(w, "shape_chi2"); s && *s >= 0) m.shape = std::sqrt(*s);
    m.chi2 = Num(w, "chi2");
    m.shrink = Num(w, "shrink");
    if (order) AppendOnce(order, label);
    out[label] = m;
  }
  return out;
}

Misfits ReadMisfits(const json& report) {
  Misfits misfits;
  const json& after = Get(Get(report, "verdict"), "where_after");
  misfits.has_after = after.is_array() && !after.empty();
  misfits.before = ReadMisfits(List(report, "where"), &misfits.labels);
  misfits.after = ReadMisfits(List(Get(report, "verdict"), "where_after"),
                              misfits.has_after ? &misfits.labels : nullptr);
  return misfits;
}

void EffectsSection(const json& report, Page* page) {
  page->Heading("Effects, best first");
  page->Table({"effect", "fitted", "gap after", "shrink (%)", "likelihood ratio", "p",
               "extra parameters", "AIC", "BIC", "supported", "values"},
              RowsOf(List(report, "ranking"), [](const json& f) -> Row {
                const json& ev = Get(f, "evidence");
                return {ValueCell(Get(f, "effect")), ValueCell(Get(f, "fitted")),
                        NumberCell(Num(f, "gap_after")), PercentCell(Num(f, "shrink")),
                        NumberCell(Num(ev, "likelihood_ratio")),
                        NumberCell(Num(ev, "lrt_p_value")), ValueCell(Get(ev, "extra_parameters")),
                        NumberCell(Num(ev, "aic")), NumberCell(Num(ev, "bic")),
                        ValueCell(Get(f, "supported")),
                        ValueCell(Has(f, "values") ? Get(f, "values") : Get(f, "note"))};
              }));
}

void WhereSection(const Misfits& misfits, Page* page) {
  std::vector<Row> rows;
  for (const std::string& label : misfits.labels) {
    const Misfit b = misfits.Before(label);
    Row row = {TextCell(label)};
    std::vector<std::optional<double>> values = {b.frequency, b.damping, b.shape, b.chi2};
    if (misfits.has_after) {
      const Misfit a = misfits.After(label);
      values.insert(values.end(), {a.frequency, a.damping, a.shape, a.chi2});
    }
    for (const auto& v : values) row.push_back(NumberCell(v, "%.3g"));
    row.push_back(PercentCell(b.shrink));
    rows.push_back(row);
  }
  std::vector<std::string> head = {"mode", "frequency (σ)", "damping (σ)", "√ shape χ²", "χ²"};
  if (misfits.has_after) {
    for (const char* h :
         {"after: frequency (σ)", "after: damping (σ)", "after: √ shape χ²", "after: χ²"}) {
      head.push_back(h);
    }
  }
  head.push_back("shrink (%)");
  page->Heading("Where: misfit per mode");
  page->Table(head, rows);
}

// The misfit bars of one set; widens [low, high] to its values.
Series MisfitSeries(const Misfits& misfits, bool after, double* low, double* high) {
  Series s;
  for (size_t i = 0; i < misfits.labels.size(); ++i) {
    const std::string& label = misfits.labels[i];
    const Misfit m = after ? misfits.After(label) : misfits.Before(label);
    s.Row({static_cast<double>(i), m.frequency, m.damping, m.shape});
    for (const auto& v : {m.frequency, m.damping, m.shape}) {
      if (v) *low = std::min(*low, *v), *high = std::max(*high, *v);
    }
  }
  return s;
}

// Misfit per mode and observable, before and after.
void MisfitFigure(const Misfits& misfits, const std::string& effect, Page* page) {
  if (misfits.labels.empty()) return;
  const int n = static_cast<int>(misfits.labels.size());
  Figure f("diagnose-misfit", 920, misfits.has_after ? 620 : 360);
  double low = -2.5, high = 2.5;
  std::vector<std::string> vars = {f.AddData(MisfitSeries(misfits, false, &low, &high))};
  if (misfits.has_after) vars.push_back(f.AddData(MisfitSeries(misfits, true, &low, &high)));
  const double pad = 0.08 * (high - low);
  std::ostringstream g;
  g << (misfits.has_after ? "set multiplot layout 2,1\n" : "")
    << "set style fill solid 0.85 noborder\nset boxwidth 0.25\nset grid ytics\n"
    << "set xrange [-0.6:" << n - 0.4 << "]\nset yrange [" << low - pad << ":" << high + pad
    << "]\n"
    << CategoryXTics(Pretty(misfits.labels), 560.0, -25)
    << "set ylabel 'misfit (σ)'\nset key outside right top\n"
    << "set lmargin 9\nset rmargin 26\n"
    << HorizontalLine(1, "2", kDashedGrey) << HorizontalLine(2, "-2", kDashedGrey)
    << HorizontalLine(3, "0", kAxisLine);
  for (size_t k = 0; k < vars.size(); ++k) {
    const std::string& d = vars[k];
    g << (k == 1 ? "unset key\n" : "") << "set title "
      << GnuplotString(k == 0 ? "before: the calibrated baseline" : "after: with " + effect)
      << " noenhanced\n"
      << "plot " << d << " using ($1-0.26):2 with boxes lc rgb '" << kBlue
      << "' title 'frequency (σ)', " << d << " using 1:3 with boxes lc rgb '" << kOrange
      << "' title 'damping ratio (σ)', " << d << " using ($1+0.26):4 with boxes lc rgb '" << kGreen
      << "' title '√(shape χ²)'\n";
  }
  if (misfits.has_after) g << "unset multiplot\n";
  f.script = g.str();
  f.caption =
      "Misfit of each mode in units of its measurement σ: frequency and damping ratio "
      "(model − measured, signed) and the square root of the mode shape's χ². " +
      std::string(misfits.has_after ? "Top: the calibrated baseline; bottom: with " + effect + ". "
                                    : "The baseline only (the verdict adds no effect). ") +
      "Dashed lines: ± 2σ.";
  page->AddFigure(std::move(f));
}

// The effects that were fitted: shrink and likelihood ratio bars.
struct Ranking {
  std::vector<std::string> effects;
  std::vector<std::pair<double, double>> shrink, likelihood_ratio;
  std::vector<bool> supported;
  Series thresholds;  // the LR at p = 1e-3 per effect
  double lr_min = 1, shrink_low = 0, shrink_high = 100;
};

Ranking ReadRanking(const json& report) {
  // The LR test's threshold at p = 1e-3 (χ² quantile) for 1 to 6 extra parameters.
  static const double kLrAt1e3[] = {10.828, 13.816, 16.266, 18.467, 20.515, 22.458};
  Ranking out;
  for (const json& q : List(report, "ranking")) {
    const auto s = Num(q, "shrink");
    const auto l = Num(Get(q, "evidence"), "likelihood_ratio");
    if (!s && !l) continue;
    out.effects.push_back(Str(q, "effect"));
    out.shrink.push_back(s ? std::make_pair(std::min(0.0, 100 * *s), std::max(0.0, 100 * *s))
                           : std::make_pair(double(NAN), double(NAN)));
    out.likelihood_ratio.push_back({NAN, l && *l > 0 ? *l : NAN});
    if (s) {
      out.shrink_low = std::min(out.shrink_low, 100 * *s);
      out.shrink_high = std::max(out.shrink_high, 100 * *s);
    }
    if (l && *l > 0) out.lr_min = std::min(out.lr_min, *l);
    out.supported.push_back(IsTrue(q, "supported"));
    const double k = Num(Get(q, "evidence"), "extra_parameters").value_or(0);
    if (k >= 1 && k <= 6 && k == std::floor(k)) {
      out.thresholds.Row(
          {static_cast<double>(out.effects.size() - 1), kLrAt1e3[static_cast<int>(k) - 1]});
    }
  }
  return out;
}

// A panel of bars per effect, green when supported.
BarPanelOptions RankingPanel(const Ranking& ranking,
                             const std::vector<std::pair<double, double>>& bars) {
  BarPanelOptions panel;
  panel.labels = ranking.effects;
  panel.bars = bars;
  panel.highlight = ranking.supported;
  return panel;
}

// The likelihood-ratio panel, with the thresholds marked in red.
std::string LikelihoodRatioPanel(Figure* f, const Ranking& ranking) {
  BarPanelOptions options = RankingPanel(ranking, ranking.likelihood_ratio);
  options.left = 0.62;
  options.right = 0.97;
  options.x_label = "likelihood ratio (log scale)";
  options.show_labels = false;
  options.log_x = true;
  std::string panel = BarPanel(f, options);
  if (!ranking.thresholds.empty() && panel.find("plot ") != std::string::npos) {
    panel.pop_back();
    panel += ", " + f->AddData(ranking.thresholds) +
             " using 2:($1-0.45):(0):(0.9) with vectors nohead lw 2.5 lc rgb '" + kRed + "'\n";
  }
  return panel;
}

void RankingFigure(const json& report, Page* page) {
  Ranking ranking = ReadRanking(report);
  if (ranking.effects.empty()) {
    page->Note("No ranking figure: no effect was fitted.");
    return;
  }
  const double floor = std::pow(10, std::floor(std::log10(ranking.lr_min)));
  for (auto& bar : ranking.likelihood_ratio) bar.first = floor;
  const int n = static_cast<int>(ranking.effects.size());
  Figure f("diagnose-ranking", 920, 110 + 36 * n);
  BarPanelOptions shrink = RankingPanel(ranking, ranking.shrink);
  shrink.x_label = "share of the gap removed (shrink, %)";
  std::ostringstream g;
  g << "set multiplot\nset style fill solid 0.85 noborder\nset grid xtics\nunset key\n"
    << ScreenMargins(f, 20, 55) << "set yrange [" << n - 0.5 << ":-0.5]\nset xrange ["
    << ranking.shrink_low - 5 << ":" << ranking.shrink_high + 5 << "]\n"
    << BarPanel(&f, shrink) << "set xrange [" << floor << ":*]\nset format x '10^{%L}'\n";
  g << LikelihoodRatioPanel(&f, ranking) << "unset multiplot\n";
  f.script = g.str();
  f.caption =
      "Each catalogue effect refitted: left, the share of the gap it removes (%); right, "
      "its likelihood ratio against the baseline (log axis). Green: supported (LR test "
      "p < 10⁻³); grey: not supported. Red marks: the likelihood ratio that gives p = 10⁻³ for "
      "the "
      "effect's number of extra parameters.";
  page->AddFigure(std::move(f));
}

// The shrink per mode.
void ShrinkFigure(const Misfits& misfits, const std::string& effect, Page* page) {
  Series s;
  double low = 0, high = 100;
  for (size_t i = 0; i < misfits.labels.size(); ++i) {
    const auto it = misfits.before.find(misfits.labels[i]);
    if (it == misfits.before.end() || !it->second.shrink) continue;
    const double v = 100 * *it->second.shrink;
    s.Row({static_cast<double>(i), v});
    low = std::min(low, v), high = std::max(high, v);
  }
  if (s.empty()) {
    page->Note("No shrink figure: the report gives no shrink per mode.");
    return;
  }
  Figure f("diagnose-shrink", 900, 340);
  const int n = static_cast<int>(misfits.labels.size());
  std::ostringstream g;
  g << "set style fill solid 0.85 noborder\nset boxwidth 0.6\nset grid ytics\nunset key\n"
    << "set xrange [-0.6:" << n - 0.4 << "]\nset yrange [" << low - 5 << ":" << high + 5 << "]\n"
    << CategoryXTics(Pretty(misfits.labels), 700.0, -25)
    << "set ylabel 'share of the χ² removed (%)'\n"
    << HorizontalLine(1, "0", kAxisLine) << "plot " << f.AddData(s)
    << " using 1:2 with boxes lc rgb '" << kBlue << "'\n";
  f.script = g.str();
  f.caption = "Share of each mode's misfit χ² removed by " +
              (effect.empty() ? "the verdict" : effect) + ", in %; below 0 the mode fits worse.";
  page->AddFigure(std::move(f));
}

}  // namespace

void DiagnosePage(const json& report, Page* page) {
  page->Summary(FactsOf(report, kSummary));
  EffectsSection(report, page);
  const Misfits misfits = ReadMisfits(report);
  WhereSection(misfits, page);
  const std::string effect = Str(Get(report, "verdict"), "effect");
  page->Heading("Figures");
  MisfitFigure(misfits, effect, page);
  RankingFigure(report, page);
  ShrinkFigure(misfits, effect, page);
}

}  // namespace ringid::html
