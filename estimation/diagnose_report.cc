// DiagnosisResult's text (ringid diagnose's standard output).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "estimation/diagnose.h"

namespace ringid {

std::string DiagnosisResult::FullReport() const {
  std::ostringstream o;
  char line[512];
  if (!status.ok()) return "ringid diagnose: FAILED: " + status.message + "\n";
  o << "ringid diagnose: verdict " << EffectName(verdict);
  if (!indistinguishable.empty()) {
    o << " (indistinguishable:";
    for (const Effect* e : indistinguishable) o << " " << EffectName(e);
    o << ")";
  }
  o << "\n  " << explanation << "\n\n";
  std::snprintf(line, sizeof line, "  the gap: chi-square %.4g on %d dof", chi2_before, dof);
  o << line;
  if (p_value) {
    std::snprintf(line, sizeof line, ", p = %.3g (%s)", *p_value, significant ? "significant" : "not significant");
    o << line;
  }
  int width = 20;
  for (const ModeMisfit& w : where) width = std::max<int>(width, w.Name().size());
  for (const ItemMisfit& w : where_else.value_or(std::vector<ItemMisfit>{})) {
    width = std::max<int>(width, (w.condition ? w.condition->size() + 1 : 0) + w.name.size());
  }
  o << "\n\n  where it lies (baseline misfit, in sigma):\n  mode" << std::string(width - 4, ' ')
    << "  chi2     freq    damping  shape chi2  worst component\n";
  for (size_t i = 0; i < where.size(); ++i) {
    const ModeMisfit& w = where[i];
    std::snprintf(line, sizeof line, "  %-*s %7.1f  %+7.2f  %7s  %9.1f   %s %+.1f%s\n", width, w.Name().c_str(), w.chi2,
                  w.frequency_sigma, w.damping_sigma ? std::to_string(*w.damping_sigma).substr(0, 6).c_str() : "-",
                  w.shape_chi2, w.worst_component.c_str(), w.worst_component_sigma,
                  i < mode_shrink.size() ? ("   shrink " + std::to_string(static_cast<int>(std::round(100 * mode_shrink[i]))) + " %").c_str() : "");
    o << line;
  }
  for (const ItemMisfit& w : where_else.value_or(std::vector<ItemMisfit>{})) {
    std::snprintf(line, sizeof line, "  %-*s %7.1f  (%+.2f sigma)\n", width,
                  ((w.condition ? *w.condition + " " : "") + w.name).c_str(), w.sigma * w.sigma,
                  w.sigma);
    o << line;
  }
  for (const std::string& a : absorbed) o << "  absorbed: " << a << "\n";
  o << "\n  effect                  chi2      LRT p      AIC      shrink  held-out chi2  vs verdict (threshold)\n";
  for (const EffectFit& f : ranking) {
    char versus[48] = "-";
    if (std::isfinite(f.chi2_above_verdict)) {
      std::snprintf(versus, sizeof versus, "%+.2f (%.2f)", f.chi2_above_verdict, f.group_threshold);
    }
    std::snprintf(line, sizeof line, "  %-22s %8.1f  %9.2e  %8.1f  %5.0f %%  %-13s  %-22s%s\n", EffectName(f.effect),
                  f.chi2, f.lrt_p, f.aic, 100 * f.shrink,
                  f.held_out_chi2 ? std::to_string(*f.held_out_chi2).substr(0, 8).c_str() : "-", versus,
                  f.supported ? "  supported" : "");
    if (!f.ok) std::snprintf(line, sizeof line, "  %s: %s\n", EffectName(f.effect), f.note.c_str());
    o << line;
    for (const auto& [name, by] : f.absorbed_by) {
      o << "    " << name << ": absorbed whatever its size by the free";
      for (size_t i = 0; i < by.size(); ++i) o << (i ? ", " : " ") << by[i];
      o << "\n";
    }
  }
  if (held_out_before) {
    std::snprintf(line, sizeof line, "  baseline held-out chi2 %.1f\n", *held_out_before);
    o << line;
  }
  return o.str();
}

}  // namespace ringid
