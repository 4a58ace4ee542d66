// The text of an identify result (IdentifyResult::BriefReport, FullReport).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "estimation/identify.h"

namespace ringid {

namespace {

// One row per measured function (estimation/frf_fits.h): lines, chi2, values, FRAC.
std::string FrfRows(const std::vector<FrfFit>& frfs) {
  std::ostringstream o;
  size_t name_width = 28;
  for (const FrfFit& f : frfs) {
    name_width = std::max(name_width, (f.condition ? f.condition->size() + 1 : 0) +
                                          f.output.size() + 1 + f.input.size());
  }
  char row[512];  // names may be long
  std::snprintf(row, sizeof row, "\n  %-*s %6s %10s %7s %11s %8s\n",
                static_cast<int>(name_width), "FRF output/input", "lines", "chi2", "values",
                "chi2/values", "FRAC");
  o << row;
  for (const FrfFit& f : frfs) {
    const std::string name = (f.condition ? *f.condition + " " : "") + f.output + "/" + f.input;
    char frac[16] = "-";  // not defined against a zero function
    if (std::isfinite(f.frac)) std::snprintf(frac, sizeof frac, "%.4f", f.frac);
    std::snprintf(row, sizeof row, "  %-*s %6d %10.4g %7d %11.3f %8s\n",
                  static_cast<int>(name_width), name.c_str(), f.lines(), f.chi2,
                  f.values(), f.chi2 / f.values(), frac);
    o << row;
  }
  return o.str();
}

}  // namespace

std::string IdentifyResult::BriefReport() const {
  std::ostringstream o;
  o << "ringid identify (" << ToString(method) << "): "
    << (status.ok() ? (converged ? "converged" : "not converged") : "FAILED")
    << ", cost " << cost << ", " << evaluations << " model evaluations in "
    << starts << " start(s), " << seconds * 1e3 << " ms";
  if (!status.ok()) o << ": " << status.message;
  return o.str();
}

std::string IdentifyResult::FullReport() const {
  std::ostringstream o;
  char line[256];
  o << BriefReport() << "\n";
  for (const std::string& w : warnings) o << "  warning: " << w << "\n";
  if (!status.ok()) return o.str();
  o << "  termination: " << status.message << "\n";
  o << "  " << fit.verdict << "\n";
  o << "  starts: " << start_agreement.verdict << "\n";
  std::snprintf(line, sizeof line,
                "  eq. (19) in-plane error %.3e, eq. (20) out-of-plane error %.3e\n",
                relative_error_in_plane, relative_error_out_of_plane);
  int width = 20;  // the longest label; with conditions, "condition label"
  for (const ModeFit& m : modes) {
    if (m.condition) width = std::max<int>(width, m.condition->size() + 20);
  }
  if (!modes.empty()) {  // FRFs or statics alone: no mode, no eq. (19)
    o << line << "\n  " << std::string("mode") + std::string(width - 4, ' ')
      << " measured Hz   model Hz   zeta   MAC\n";
  }
  for (const ModeFit& m : modes) {
    char mac[16] = "-";
    if (m.mac) std::snprintf(mac, sizeof mac, "%.3f", *m.mac);
    const std::string name = m.condition ? *m.condition + " " + LabelName(m.label)
                                         : std::string(LabelName(m.label));
    std::snprintf(line, sizeof line, "  %-*s %10.3f %10.3f %6.3f %5s%s\n", width,
                  name.c_str(), m.measured_hz, m.model_hz,
                  m.model_damping, mac,
                  m.model_label != m.label
                      ? (std::string("  (paired with model ") +
                         LabelName(m.model_label) + ")").c_str()
                      : "");
    o << line;
  }
  for (const MeasurementFit& m : measurements.value_or(std::vector<MeasurementFit>{})) {
    const std::string name = m.condition ? *m.condition + " " + m.name : m.name;
    std::snprintf(line, sizeof line, "  %-*s measured %.5g, model %.5g %s (%+.2f sigma)\n", width,
                  name.c_str(), m.measured, m.model, m.unit.c_str(),
                  (m.model - m.measured) / m.sigma);
    o << line;
  }
  std::snprintf(line, sizeof line, "\n  %-12s %12s %-9s  %-11s  %s\n", "parameter", "value", "unit",
                "std", "identifiable");
  o << line;
  for (const ParameterEstimate& e : estimates) {
    std::string sd = e.std ? std::to_string(*e.std) : "-";
    if (e.std) {
      std::snprintf(line, sizeof line, "%.3e", *e.std);
      sd = line;
    }
    const std::string cls = std::string(e.free || e.tied_to ? ToString(e.identifiable) : "(fixed)") +
                            (e.conditional_on.empty() ? "" : " *");
    std::snprintf(line, sizeof line, "  %-12s %12.4e %-9s  %-11s  %-15s %s\n",
                  e.key.Text().c_str(), e.value, Info(e.key.param).unit, sd.c_str(), cls.c_str(),
                  e.tied_to ? (std::string("= ") + ParamName(*e.tied_to)).c_str()
                            : "");
    o << line;
  }
  // The marker's meaning, one line per parameter whose class rests on a known one.
  bool marked = false;
  for (const ParameterEstimate& e : estimates) {
    if (const std::optional<std::string> given = e.Condition()) {
      if (!marked) o << "  * the class holds only at the known value (a wrong one moves the estimate):\n";
      marked = true;
      o << "    " << e.key.Text() << ": " << *given << "\n";
    }
  }
  // Which parameters the data decide and which their priors decide.
  std::string by_prior, by_both, by_data;
  for (const ParameterEstimate& e : estimates) {
    if (!e.decided_by) continue;
    std::string& list = *e.decided_by == DecidedBy::kPrior  ? by_prior
                        : *e.decided_by == DecidedBy::kData ? by_data
                                                            : by_both;
    list += (list.empty() ? "" : ", ") + e.key.Text();
  }
  if (!by_prior.empty()) o << "\n  decided by their priors (posterior variance > " << 100 * kPriorDecides << " % of the prior's): " << by_prior;
  if (!by_both.empty()) o << "\n  decided by data and priors together: " << by_both;
  if (!by_data.empty()) o << "\n  decided by the data despite a prior (< " << 100 * kDataDecides << " % of its variance left): " << by_data;
  if (!by_prior.empty() || !by_both.empty() || !by_data.empty()) o << "\n";
  if (const std::string bounds = OnBounds(); !bounds.empty()) o << "\n  " << bounds << "\n";
  if (const std::string conflicts = PriorConflicts(); !conflicts.empty()) {
    o << "\n  " << conflicts << "\n";
  }
  for (const PlausibilityFlag& f : plausibility) o << "\n  implausible (" << f.rule << "): " << f.reason;
  if (!plausibility.empty()) o << "\n";
  if (frfs) o << FrfRows(*frfs);
  if (uncertainty.ok) {
    o << "\n  Jacobian rank " << uncertainty.rank << " of "
      << uncertainty.jacobian.cols() << " free coordinates ("
      << uncertainty.jacobian.rows() << " residuals)";
    if (!uncertainty.covariance_ok) {
      o << "; covariance unavailable: " << uncertainty.covariance_error;
    }
    o << "\n";
  } else {
    o << "\n  uncertainty: " << uncertainty.error << "\n";
  }
  return o.str();
}

}  // namespace ringid
