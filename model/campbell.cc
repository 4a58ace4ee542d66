#include "model/campbell.h"

#include <algorithm>
#include <cmath>

namespace ringid {

double LugOrderHz(int order, int lugs_per_revolution, double r_e0, double speed_m_s) {
  return double(order) * lugs_per_revolution * speed_m_s / (2 * M_PI * r_e0);
}

std::vector<CriticalSpeed> CriticalSpeeds(const ModalModel& model, const Parameters& p,
                                          int lugs_per_revolution, const std::vector<double>& speeds,
                                          int max_order) {
  std::vector<CriticalSpeed> out;
  if (lugs_per_revolution <= 0 || speeds.size() < 2) return out;
  const double r = p[Param::r_e0];
  std::vector<ModalSolution> at;
  double highest = 0;
  for (double v : speeds) {
    at.push_back(model.Solve(p, v));
    for (const Mode& m : at.back().modes) highest = std::max(highest, m.frequency_hz);
  }
  // The lowest order above `highest` at the lowest moving speed meets nothing.
  double slowest = INFINITY;
  for (double v : speeds) {
    if (v > 0) slowest = std::min(slowest, v);
  }
  if (!std::isfinite(slowest)) return out;
  // At most max_order: a slowest speed near 0 would ask for millions.
  const double needed = std::ceil(highest / LugOrderHz(1, lugs_per_revolution, r, slowest));
  const int orders = needed < max_order ? static_cast<int>(needed) : max_order;
  // f_label(V) - f_order(V); NaN where the label has no oscillating mode.
  auto gap = [&](const ModalSolution& s, ModeLabel label, int k, double v) {
    const Mode* m = s.ok ? s.Find(label) : nullptr;
    return m ? m->frequency_hz - LugOrderHz(k, lugs_per_revolution, r, v) : NAN;
  };
  for (int k = 1; k <= orders; ++k) {
    for (int l = 0; l < kNumLabels; ++l) {
      const ModeLabel label = static_cast<ModeLabel>(l);
      for (size_t i = 0; i + 1 < speeds.size(); ++i) {
        double lo = speeds[i], hi = speeds[i + 1];
        double g_lo = gap(at[i], label, k, lo);
        const double g_hi = gap(at[i + 1], label, k, hi);
        if (!(g_lo * g_hi <= 0) || g_lo == 0) continue;  // no sign change (or NaN)
        while (hi - lo > 1e-6 * (speeds[i + 1] - speeds[i])) {
          const double mid = (lo + hi) / 2;
          const double g = gap(model.Solve(p, mid), label, k, mid);
          if (std::isnan(g)) break;
          if ((g <= 0) == (g_lo <= 0)) lo = mid, g_lo = g;
          else hi = mid;
        }
        const double v = (lo + hi) / 2;
        const ModalSolution s = model.Solve(p, v);
        const Mode* m = s.ok ? s.Find(label) : nullptr;
        if (!m) continue;
        out.push_back({k, label, v, m->frequency_hz, m->damping_ratio});
      }
    }
  }
  std::sort(out.begin(), out.end(),
            [](const CriticalSpeed& a, const CriticalSpeed& b) { return a.speed_m_s < b.speed_m_s; });
  return out;
}

}  // namespace ringid
