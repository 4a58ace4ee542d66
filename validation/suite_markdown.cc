// The suites' Markdown tables, drawn from their typed reports.
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "validation/suites.h"

namespace ringid {
namespace {

std::string Format(const char* format, double v) {
  if (!std::isfinite(v)) return "-";
  char text[64];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

std::string Percent(double fraction) { return Format("%.1f %%", 100 * fraction); }

// A time per call in the unit that reads best: µs below 0.1 ms, ms below 1 s.
std::string Seconds(std::optional<double> s) {
  if (!s) return "-";
  if (*s < 1e-4) return Format("%#.3g µs", 1e6 * *s);
  if (*s < 1) return Format("%#.3g ms", 1e3 * *s);
  return Format("%#.3g s", *s);
}

std::string Times(std::optional<double> ratio) { return ratio ? Format("%.2f×", *ratio) : "-"; }

}  // namespace

std::string PaperSuite::Markdown() const {
  std::string md =
      "### Table 3 reproduced\n\n| mode | paper Hz | ringid Hz | difference |\n"
      "| --- | --- | --- | --- |\n";
  for (const Table3Row& r : table3) {
    md += std::string("| ") + ToString(r.label) + " | " + Format("%.1f", r.paper_hz) + " | " +
          Format("%.3f", r.model_hz) + " | " + Format("%+.3f", r.model_hz - r.paper_hz) + " |\n";
  }
  md += "\n### Table 1 identified\n\n| method | eq. (19) | eq. (20) | evaluations | ms |\n"
        "| --- | --- | --- | --- | --- |\n";
  for (const Table1Fit& f : identify) {
    md += std::string("| ") + ToString(f.method) + " | " +
          Format("%.2e", f.relative_error_in_plane_eq19) + " | " +
          Format("%.2e", f.relative_error_out_of_plane_eq20) + " | " +
          std::to_string(f.evaluations) + " | " + Format("%.1f", 1e3 * f.seconds) + " |\n";
  }
  md += "| paper (simplex) | " + Format("%.2e", paper_reported_eq19_eq20.first) + " | " +
        Format("%.2e", paper_reported_eq19_eq20.second) + " | - | - |\n";
  return md;
}

std::string SyntheticSuite::Markdown() const {
  std::string md =
      "| tire | replicates | 95 % coverage | median abs error / std | fits failed |\n"
      "| --- | --- | --- | --- | --- |\n";
  for (const TireCoverage& t : tires) {
    md += "| " + t.tire + " | " + std::to_string(t.replicates) + " | " + Percent(t.coverage_95) +
          " | " + Format("%.2f", t.median_error_over_std) + " | " + std::to_string(t.failed_fits) +
          " |\n";
  }
  return md + "\nAll tires: " + Percent(coverage_95) +
         " of 95 % intervals cover the truth (a median error/std of 0.67 is what a correct std"
         " gives).\n";
}

std::string ConditioningSuite::Markdown() const {
  std::string md =
      "The paper's setup (Table 2 ties, 16 free), noise-free data of the paper's tire.\n\n"
      "| data | residuals | rank | condition number | yes | practically_no | no |\n"
      "| --- | --- | --- | --- | --- | --- | --- |\n";
  for (const ConditioningVariant& v : variants) {
    md += "| " + v.data + " | " + std::to_string(v.residuals) + " | " + std::to_string(v.rank) +
          " | " + (std::isfinite(v.condition_number) ? Format("%.2e", v.condition_number) : "inf") +
          " | " + std::to_string(v.Count(Identifiability::kYes)) + " | " +
          std::to_string(v.Count(Identifiability::kPracticallyNo)) + " | " +
          std::to_string(v.Count(Identifiability::kNo)) + " |\n";
  }
  return md;
}

std::string DiagnosisSuite::Markdown() const {
  std::string md = "| truth \\ verdict |";
  for (const std::string& v : effects) md += " " + v + " |";
  md += "\n| --- |";
  for (size_t i = 0; i < effects.size(); ++i) md += " --- |";
  md += "\n";
  for (const std::string& t : effects) {
    md += "| " + t + " |";
    const auto row = confusion.find(t);
    for (const std::string& v : effects) {
      int count = 0;
      if (row != confusion.end() && row->second.count(v)) count = row->second.at(v);
      md += " " + (count ? std::to_string(count) : std::string(".")) + " |";
    }
    md += "\n";
  }
  return md + "\n" + std::to_string(cases.size()) +
         " cases (standing and rolling in turn, 3 tire sizes, effects shifting the largest "
         "frequency by 3 % and 5 %, noise 0.25 % / 10 % / 0.02; initial values within a factor " +
         Format("%g", start_factor) + " of the truth): accuracy " + Percent(accuracy) + ", " +
         std::to_string(wrong) + " wrong; " + std::to_string(differ_from_truth_start) +
         " verdicts differ from those started at the truth; " +
         std::to_string(named) + " named, " + std::to_string(absorbed_and_explained) +
         " answered 'none' with the effect below the size a re-calibration absorbs; " +
         std::to_string(false_alarms) + " false alarms in " + std::to_string(no_effect_cases) +
         " no-effect cases; mean shrink when named " + Format("%.0f %%", 100 * mean_shrink_when_named) +
         "; " + Format("%.2f s", seconds_per_diagnosis) + " per diagnosis.\n";
}

std::string RollingSuite::Markdown() const {
  const auto names = [](const std::vector<Param>& params, const char* separator) {
    std::string text;
    for (Param p : params) text += (text.empty() ? "" : separator) + std::string(ToString(p));
    return text;
  };
  std::string speeds;
  for (double v : speeds_m_s) speeds += (speeds.empty() ? "" : ", ") + Format("%g", v);
  std::string md = "Tire: " + tire + "; at " + speeds +
                   " m/s, every condition identified jointly; " + std::to_string(replicates) +
                   " replicates, noise " + Format("%g", 100 * frequency_noise) +
                   " % frequency, " + Format("%g", 100 * damping_noise) + " % damping, " +
                   Format("%g", shape_noise) +
                   " shapes.\n\n" + CoverageTableHeader();
  for (const RollingParameter& r : parameters) md += CoverageRow(r.param, r);
  const std::string contact_names = names(contact, " and ");
  const std::string outside = names(OutsideCoverageRange(), ", ");
  const auto verdict = [](bool ok) { return ok ? std::string("met") : std::string("NOT met"); };
  return md + "\nAll intervals: " + Percent(coverage_95) + " of " + std::to_string(intervals) +
         " cover the truth (z = log(estimate / truth) / (std / estimate): rms 1 when the std is"
         " right); " + std::to_string(failed_fits) + " fits failed; " +
         Format("%.1f s", seconds) + " in all, " + Format("%.2f s", seconds_per_fit) +
         " per fit.\n\nCriteria: " + contact_names + " classed yes in at least " +
         Percent(contact_yes_min) + " of the replicates (" + verdict(ContactClassedYes()) +
         "); no parameter ever classed no (" + verdict(NeverNo()) +
         "); all intervals together cover the truth " + Percent(coverage_range.first) + " to " +
         Percent(coverage_range.second) + " of the time (" + verdict(CoverageInRange()) +
         "). Each parameter's own coverage is reported; outside that range: " +
         (outside.empty() ? std::string("none") : outside) + ". " +
         (Pass() ? "PASS" : "FAIL") + ".\n";
}

std::string SpeedSuite::Markdown() const {
  std::string md =
      "Median time per call over " + std::to_string(batches) + " batches, each case and mode "
      "about " + Format("%g", seconds_per_case) +
      " s in all, on this machine and build. numeric: central-difference Jacobians (an "
      "evaluation: without derivatives); analytic: exact Jacobians (an evaluation: with every "
      "mode's derivatives). Both always, whatever --derivatives says.\n\n"
      "| case | numeric | analytic | numeric / analytic | target | met |\n"
      "| --- | --- | --- | --- | --- | --- |\n";
  for (const SpeedRow& r : rows) {
    std::optional<double> speedup;
    if (r.numeric_seconds && r.analytic_seconds && *r.analytic_seconds > 0) {
      speedup = *r.numeric_seconds / *r.analytic_seconds;
    }
    // Whether it is met, with the figure the target bounds.
    std::string met = "-";
    std::optional<double> value;
    double limit = 0;
    if (r.met && Target(r.name, &value, &limit)) {
      met = std::string(*r.met ? "yes" : "NO") + " (" +
            (r.name == SpeedCase::kIdentifyInPlane ? Seconds(value) : Times(value)) + ")";
    }
    md += "| " + std::string(SpeedCaseText(r.name)) + " | " + Seconds(r.numeric_seconds) +
          " | " + Seconds(r.analytic_seconds) + " | " + Times(speedup) + " | " +
          (r.target.empty() ? "-" : r.target) + " | " + met + " |\n";
  }
  return md + "\nThe evaluation takes " + Times(EvaluationOverBareEigenvalues()) +
         " the eigenvalues alone; with derivatives, " + Times(DerivativesOverEvaluation()) +
         " the evaluation alone; the three-condition joint fit takes " +
         Times(JointFitOverStanding(Derivatives::kNumeric)) +
         " the standing one with numeric derivatives. " + Format("%.1f s", seconds) +
         " in all.\n";
}

std::string ForcesSuite::Markdown() const {
  std::string speeds;
  for (double v : speeds_m_s) speeds += (speeds.empty() ? "" : ", ") + Format("%.3g", v);
  const auto optional_percent = [](const std::optional<double>& v) {
    return v ? Percent(*v) : std::string("-");
  };
  std::string md =
      "Tire: " + tire + "; " + std::to_string(lugs_per_revolution) + " lugs, orders 1-" +
      std::to_string(orders) + " at " + speeds + " m/s (order 1 meets the vertical mode at " +
      Format("%.3f", resonance_speed_m_s) + " m/s); every axle channel with noise of " +
      Format("%.3g", response_noise) + " |Y| on re and on im; the parameters identified from " +
      "modal data standing and on the drum; " + std::to_string(replicates) + " replicates.\n\n"
      "| method | estimates | largest bias | rms error | median error | rms z (std_measurement) |"
      " 95 % coverage, std_total | 95 % coverage, std_measurement | on the resonance: std_total |"
      " std_measurement |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const ForcesMethodRow& r : methods) {
    md += std::string("| ") + ToString(r.method) + " | " + std::to_string(r.estimates) + " | " +
          Percent(r.bias_max) + " | " + Percent(r.rms_error) + " | " + Percent(r.median_error) +
          " | " + (r.rms_z_measurement ? Format("%.3f", *r.rms_z_measurement) : "-") + " | " +
          optional_percent(r.coverage_total) + " | " + optional_percent(r.coverage_measurement) +
          " | " + optional_percent(r.coverage_total_at_resonance) + " | " +
          optional_percent(r.coverage_measurement_at_resonance) + " |\n";
  }
  const auto verdict = [](bool ok) { return ok ? std::string("met") : std::string("NOT met"); };
  return md + "\n" + std::to_string(failed_fits) + " identifications failed; " +
         Format("%.1f s", seconds) + " in all.\n\nCriteria: with the true parameters, bias at most " +
         Percent(bias_max_allowed) + " of |F| per force and order (" + verdict(Unbiased()) +
         ") and the spread as std_measurement says, rms z within " + Format("%.2f", rms_z_tolerance) +
         " of 1 (" + verdict(StdIsRight()) + "); with identified parameters, std_total covers in " +
         Percent(coverage_range.first) + "-" + Percent(coverage_range.second) +
         ", on the resonance too (" + verdict(TotalCovers()) +
         "), and std_measurement alone covers less, below the nominal 95 % (" +
         verdict(MeasurementUnderCovers()) + ").\n";
}

}  // namespace ringid
