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

// `value` when finite (a null in the JSON reads as NaN), else none.
std::optional<double> Finite(double value) {
  return std::isfinite(value) ? std::optional<double>(value) : std::nullopt;
}

// The ranking entry of the verdict's effect, if any.
const EffectFit* VerdictFit(const DiagnosisResult& report) {
  for (const EffectFit& fit : report.ranking) {
    if (fit.effect == report.verdict) return &fit;
  }
  return nullptr;
}

FactRows SummaryFacts(const DiagnoseReport& report) {
  const DiagnosisResult& r = report.body.result;
  return {{"dataset", TextCell(report.body.dataset)},
          {"status", NameCell(r.status.outcome)},
          {"message", TextCell(r.status.message)},
          {"verdict", TextCell(EffectName(r.verdict))},
          {"explanation", TextCell(r.explanation)},
          {"indistinguishable from", ListCell(EffectNames(r.indistinguishable))},
          {"how the group is decided",
           TextCell("every fitted effect whose χ² differs from the verdict's by less than the χ² "
                    "significant at the level below, on as many degrees of freedom as their numbers "
                    "of parameters differ (at least 1): a likelihood-ratio threshold")},
          {"significance level (effects and group)", NumberCell(r.level)},
          {"gap before: χ²", NumberCell(r.chi2_before)},
          {"gap before: degrees of freedom", NumberCell(r.dof, "%.0f")},
          {"gap before: χ² in excess of its dof", NumberCell(r.gap_before)},
          {"gap before: p-value", NumberCell(r.p_value)},
          {"gap significant", YesNoCell(r.significant)},
          {"absorbed by re-calibration", ListCell(r.absorbed)},
          {"seconds", NumberCell(r.seconds)}};
}

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

// The misfits of `where`; `shrink` per mode, aligned with it (may be empty).
std::map<std::string, Misfit> ReadMisfits(const std::vector<ModeMisfit>& where,
                                          const std::vector<double>& shrink,
                                          std::vector<std::string>* order) {
  std::map<std::string, Misfit> out;
  for (size_t index = 0; index < where.size(); ++index) {
    const ModeMisfit& mode = where[index];
    const std::string label = mode.Name();
    Misfit misfit;
    misfit.frequency = Finite(mode.frequency_sigma);
    if (mode.damping_sigma) misfit.damping = Finite(*mode.damping_sigma);
    if (mode.shape_chi2 >= 0) misfit.shape = Finite(std::sqrt(mode.shape_chi2));
    misfit.chi2 = Finite(mode.chi2);
    if (index < shrink.size()) misfit.shrink = Finite(shrink[index]);
    if (order) AppendOnce(order, label);
    out[label] = misfit;
  }
  return out;
}

Misfits ReadMisfits(const DiagnosisResult& report) {
  Misfits misfits;
  const EffectFit* verdict = VerdictFit(report);
  misfits.has_after = verdict && !verdict->where.empty();
  misfits.before = ReadMisfits(report.where, report.mode_shrink, &misfits.labels);
  if (misfits.has_after) misfits.after = ReadMisfits(verdict->where, {}, &misfits.labels);
  return misfits;
}

// The fitted effect parameters as "name = value", else why it was not fitted.
Cell ValuesCell(const EffectFit& fit) {
  if (fit.values.empty()) return TextCell(fit.note.empty() ? "–" : fit.note);
  std::vector<std::string> items;
  for (const auto& [name, value] : fit.values) items.push_back(name + " = " + Format(value));
  return ListCell(items);
}

// Per effect parameter the free baseline parameters that absorb it whatever
// its size ("dm: m_b, I_by"), "–" where none does.
Cell AbsorbedCell(const EffectFit& fit) {
  std::vector<std::string> items;
  for (const auto& [name, by] : fit.absorbed_by) {
    if (!by.empty()) items.push_back(name + ": " + Join(by, ", "));
  }
  return items.empty() ? TextCell("–") : ListCell(items);
}

Row EffectRow(const EffectFit& fit) {
  // An effect that was not fitted has no evidence.
  const auto shown = [&fit](double value) { return fit.ok ? Finite(value) : std::nullopt; };
  return {TextCell(EffectName(fit.effect)),
          YesNoCell(fit.ok),
          NumberCell(shown(fit.gap_after)),
          PercentCell(shown(fit.shrink)),
          NumberCell(shown(fit.lrt_statistic)),
          NumberCell(shown(fit.lrt_p)),
          NumberCell(shown(fit.extra_parameters), "%.0f"),
          NumberCell(shown(fit.aic)),
          NumberCell(shown(fit.bic)),
          YesNoCell(fit.supported),
          NumberCell(shown(fit.chi2_above_verdict)),
          NumberCell(shown(fit.group_threshold)),
          ValuesCell(fit),
          AbsorbedCell(fit)};
}

void EffectsSection(const DiagnosisResult& report, Page* page) {
  std::vector<Row> rows;
  for (const EffectFit& fit : report.ranking) rows.push_back(EffectRow(fit));
  page->Heading("Effects, best first");
  page->Table({"effect", "fitted", "gap after", "shrink (%)", "likelihood ratio", "p",
               "extra parameters", "AIC", "BIC", "supported", "χ² above the verdict's",
               "group threshold", "values", "absorbed by (whatever its size)"},
              rows);
}

void WhereSection(const Misfits& misfits, Page* page) {
  std::vector<Row> rows;
  for (const std::string& label : misfits.labels) {
    const Misfit before = misfits.Before(label);
    Row row = {TextCell(label)};
    std::vector<std::optional<double>> values = {before.frequency, before.damping, before.shape,
                                                 before.chi2};
    if (misfits.has_after) {
      const Misfit after = misfits.After(label);
      values.insert(values.end(), {after.frequency, after.damping, after.shape, after.chi2});
    }
    for (const auto& value : values) row.push_back(NumberCell(value, "%.3g"));
    row.push_back(PercentCell(before.shrink));
    rows.push_back(row);
  }
  std::vector<std::string> head = {"mode", "frequency (σ)", "damping (σ)", "√ shape χ²", "χ²"};
  if (misfits.has_after) {
    for (const char* title :
         {"after: frequency (σ)", "after: damping (σ)", "after: √ shape χ²", "after: χ²"}) {
      head.push_back(title);
    }
  }
  head.push_back("shrink (%)");
  page->Heading("Where: misfit per mode");
  page->Table(head, rows);
}

// The misfit bars of one set; widens [low, high] to its values.
Series MisfitSeries(const Misfits& misfits, bool after, double* low, double* high) {
  Series series;
  for (size_t index = 0; index < misfits.labels.size(); ++index) {
    const std::string& label = misfits.labels[index];
    const Misfit misfit = after ? misfits.After(label) : misfits.Before(label);
    series.Row({static_cast<double>(index), misfit.frequency, misfit.damping, misfit.shape});
    for (const auto& value : {misfit.frequency, misfit.damping, misfit.shape}) {
      if (value) *low = std::min(*low, *value), *high = std::max(*high, *value);
    }
  }
  return series;
}

// Misfit per mode and observable, before and after.
void MisfitFigure(const Misfits& misfits, const std::string& effect, Page* page) {
  if (misfits.labels.empty()) return;
  const int modes = static_cast<int>(misfits.labels.size());
  Figure figure("diagnose-misfit", 920, misfits.has_after ? 620 : 360);
  double low = -2.5, high = 2.5;
  std::vector<std::string> data = {figure.AddData(MisfitSeries(misfits, false, &low, &high))};
  if (misfits.has_after) data.push_back(figure.AddData(MisfitSeries(misfits, true, &low, &high)));
  const double pad = 0.08 * (high - low);
  std::ostringstream script;
  script << (misfits.has_after ? "set multiplot layout 2,1\n" : "")
         << "set style fill solid 0.85 noborder\nset boxwidth 0.25\nset grid ytics\n"
         << "set xrange [-0.6:" << modes - 0.4 << "]\nset yrange [" << low - pad << ":"
         << high + pad << "]\n"
         << CategoryXTics(Pretty(misfits.labels), 560.0, -25)
         << "set ylabel 'misfit (σ)'\nset key outside right top\n"
         << "set lmargin 9\nset rmargin 26\n"
         << HorizontalLine(1, "2", kDashedGrey) << HorizontalLine(2, "-2", kDashedGrey)
         << HorizontalLine(3, "0", kAxisLine);
  for (size_t panel = 0; panel < data.size(); ++panel) {
    const std::string& file = data[panel];
    script << (panel == 1 ? "unset key\n" : "") << "set title "
           << GnuplotString(panel == 0 ? "before: the calibrated baseline"
                                       : "after: with " + effect)
           << " noenhanced\n"
           << "plot " << file << " using ($1-0.26):2 with boxes lc rgb '" << kBlue
           << "' title 'frequency (σ)', " << file << " using 1:3 with boxes lc rgb '" << kOrange
           << "' title 'damping ratio (σ)', " << file << " using ($1+0.26):4 with boxes lc rgb '"
           << kGreen << "' title '√(shape χ²)'\n";
  }
  if (misfits.has_after) script << "unset multiplot\n";
  figure.script = script.str();
  figure.caption =
      "Misfit of each mode in units of its measurement σ: frequency and damping ratio "
      "(model − measured, signed) and the square root of the mode shape's χ². " +
      std::string(misfits.has_after ? "Top: the calibrated baseline; bottom: with " + effect + ". "
                                    : "The baseline only (the verdict adds no effect). ") +
      "Dashed lines: ± 2σ.";
  page->AddFigure(std::move(figure));
}

// The effects that were fitted: shrink and likelihood ratio bars.
struct Ranking {
  std::vector<std::string> effects;
  std::vector<std::pair<double, double>> shrink, likelihood_ratio;
  std::vector<bool> supported;
  Series thresholds;  // the LR significant at the report's level, per effect
  double lr_min = 1, shrink_low = 0, shrink_high = 100;
  double level = 0;  // of the tests (DiagnosisResult::level)
};

Ranking ReadRanking(const DiagnosisResult& report) {
  Ranking out;
  out.level = report.level;
  for (const EffectFit& fit : report.ranking) {
    if (!fit.ok) continue;  // not fitted: not drawn
    const auto shrink = Finite(100 * fit.shrink);
    const auto ratio = Finite(fit.lrt_statistic);
    if (!shrink && !ratio) continue;
    out.effects.push_back(EffectName(fit.effect));
    out.shrink.push_back(shrink ? std::make_pair(std::min(0.0, *shrink), std::max(0.0, *shrink))
                                : std::make_pair(double(NAN), double(NAN)));
    out.likelihood_ratio.push_back({NAN, ratio && *ratio > 0 ? *ratio : NAN});
    if (shrink) {
      out.shrink_low = std::min(out.shrink_low, *shrink);
      out.shrink_high = std::max(out.shrink_high, *shrink);
    }
    if (ratio && *ratio > 0) out.lr_min = std::min(out.lr_min, *ratio);
    out.supported.push_back(fit.supported);
    if (std::isfinite(fit.lrt_threshold)) {
      out.thresholds.Row({static_cast<double>(out.effects.size() - 1), fit.lrt_threshold});
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
std::string LikelihoodRatioPanel(Figure* figure, const Ranking& ranking) {
  BarPanelOptions options = RankingPanel(ranking, ranking.likelihood_ratio);
  options.left = 0.62;
  options.right = 0.97;
  options.x_label = "likelihood ratio (log scale)";
  options.show_labels = false;
  options.log_x = true;
  std::string panel = BarPanel(figure, options);
  if (!ranking.thresholds.empty() && panel.find("plot ") != std::string::npos) {
    panel.pop_back();
    panel += ", " + figure->AddData(ranking.thresholds) +
             " using 2:($1-0.45):(0):(0.9) with vectors nohead lw 2.5 lc rgb '" + kRed + "'\n";
  }
  return panel;
}

void RankingFigure(const DiagnosisResult& report, Page* page) {
  Ranking ranking = ReadRanking(report);
  if (ranking.effects.empty()) {
    page->Note("No ranking figure: no effect was fitted.");
    return;
  }
  const double floor = std::pow(10, std::floor(std::log10(ranking.lr_min)));
  for (auto& bar : ranking.likelihood_ratio) bar.first = floor;
  const int count = static_cast<int>(ranking.effects.size());
  Figure figure("diagnose-ranking", 920, 110 + 36 * count);
  BarPanelOptions shrink = RankingPanel(ranking, ranking.shrink);
  shrink.x_label = "share of the gap removed (shrink, %)";
  std::ostringstream script;
  script << "set multiplot\nset style fill solid 0.85 noborder\nset grid xtics\nunset key\n"
         << ScreenMargins(figure, 20, 55) << "set yrange [" << count - 0.5 << ":-0.5]\nset xrange ["
         << ranking.shrink_low - 5 << ":" << ranking.shrink_high + 5 << "]\n"
         << BarPanel(&figure, shrink) << "set xrange [" << floor << ":*]\nset format x '10^{%L}'\n";
  script << LikelihoodRatioPanel(&figure, ranking) << "unset multiplot\n";
  figure.script = script.str();
  figure.caption =
      "Each catalogue effect refitted: left, the share of the gap it removes (%); right, "
      "its likelihood ratio against the baseline (log axis). Green: supported (LR test "
      "p < " + Format(ranking.level, "%g") + "); grey: not supported. Red marks: the likelihood "
      "ratio that gives p = " + Format(ranking.level, "%g") +
      " for the effect's number of extra parameters.";
  page->AddFigure(std::move(figure));
}

// The shrink per mode.
void ShrinkFigure(const Misfits& misfits, const std::string& effect, Page* page) {
  Series series;
  double low = 0, high = 100;
  for (size_t index = 0; index < misfits.labels.size(); ++index) {
    const auto it = misfits.before.find(misfits.labels[index]);
    if (it == misfits.before.end() || !it->second.shrink) continue;
    const double value = 100 * *it->second.shrink;
    series.Row({static_cast<double>(index), value});
    low = std::min(low, value), high = std::max(high, value);
  }
  if (series.empty()) {
    page->Note("No shrink figure: the report gives no shrink per mode.");
    return;
  }
  Figure figure("diagnose-shrink", 900, 340);
  const int modes = static_cast<int>(misfits.labels.size());
  std::ostringstream script;
  script << "set style fill solid 0.85 noborder\nset boxwidth 0.6\nset grid ytics\nunset key\n"
         << "set xrange [-0.6:" << modes - 0.4 << "]\nset yrange [" << low - 5 << ":" << high + 5
         << "]\n"
         << CategoryXTics(Pretty(misfits.labels), 700.0, -25)
         << "set ylabel 'share of the χ² removed (%)'\n"
         << HorizontalLine(1, "0", kAxisLine) << "plot " << figure.AddData(series)
         << " using 1:2 with boxes lc rgb '" << kBlue << "'\n";
  figure.script = script.str();
  figure.caption = "Share of each mode's misfit χ² removed by " +
                   (effect.empty() ? "the verdict" : effect) +
                   ", in %; below 0 the mode fits worse.";
  page->AddFigure(std::move(figure));
}

}  // namespace

void DiagnosePage(const DiagnoseReport& report, Page* page) {
  const DiagnosisResult& result = report.body.result;
  page->Summary(SummaryFacts(report));
  EffectsSection(result, page);
  const Misfits misfits = ReadMisfits(result);
  WhereSection(misfits, page);
  if (result.where_else) {
    std::vector<Row> rows;
    for (const ItemMisfit& w : *result.where_else) {
      rows.push_back({TextCell(w.condition.value_or("–")), TextCell(w.name),
                      NumberCell(w.sigma, "%+.2f")});
    }
    page->TableSection("Other measurements: baseline misfit",
                       {"condition", "measurement", "(model − measured) / σ"}, rows);
  }
  page->Heading("Figures");
  MisfitFigure(misfits, EffectName(result.verdict), page);
  RankingFigure(result, page);
  ShrinkFigure(misfits, EffectName(result.verdict), page);
}

}  // namespace ringid::html
