#include "estimation/starts.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>

#include "estimation/uncertainty.h"

namespace ringid {
namespace internal {
namespace {

const double kMaxStep = std::log(4.0);
constexpr int kDamperRepairs = 4;

// One observable row: which label it measures, its log misfit
// log(measured / model) and d log(model) / dx.
struct LogRow {
  ModeLabel label;
  bool damping;
  double misfit;
  Eigen::RowVectorXd sensitivity;
};

std::vector<LogRow> LogRows(const ModalResiduals& residuals, const Eigen::VectorXd& x) {
  std::vector<double> r(residuals.num_residuals());
  Eigen::MatrixXd J;
  if (!residuals.Evaluate(x.data(), r.data()) || !EvaluateJacobian(residuals, x, &J)) return {};
  std::vector<LogRow> rows;
  const auto& slots = residuals.slots();
  for (size_t k = 0; k < slots.size(); ++k) {
    const ModalResiduals::Slot& slot = slots[k];
    double measured = 0, sigma = 0;
    ModeLabel label;
    bool damping = false;
    if (!slot.measurement ||
        !slot.measurement->Scalar(residuals.dataset(), slot.item, residuals.options(), &measured,
                                  &sigma, &label, &damping)) {
      continue;
    }
    const double model = measured + r[k] * sigma;  // r = (model - measured) / sigma
    if (!(model > 0 && measured > 0)) continue;
    rows.push_back({label, damping, std::log(measured / model), J.row(k) * (sigma / model)});
  }
  return rows;
}

}  // namespace

Eigen::VectorXd MatchFrequencies(const ModalResiduals& residuals, const Eigen::VectorXd& x0,
                                 const Box& box) {
  const ParameterSetup& setup = residuals.setup();
  Eigen::VectorXd x = x0;
  for (int round = 0; round < kMatchRounds; ++round) {
    const std::vector<LogRow> rows = LogRows(residuals, x);
    if (rows.empty()) break;
    double worst = 0;
    for (const LogRow& row : rows) worst = std::max(worst, std::abs(row.misfit));
    if (worst < 1e-3) break;
    // Each stiffness (damper) joins the label whose frequency (damping) it
    // moves most per measured row.
    std::map<std::pair<ModeLabel, bool>, std::vector<int>> groups;
    for (int i = 0; i < setup.size(); ++i) {
      const Param p = setup.free()[i];
      if (!setup.is_log(i) || !(IsStiffness(p) || IsDamping(p))) continue;
      const bool damping = IsDamping(p);
      std::map<ModeLabel, std::pair<double, int>> pull;  // sum, rows
      for (const LogRow& row : rows) {
        if (row.damping != damping) continue;
        pull[row.label].first += row.sensitivity[i];
        ++pull[row.label].second;
      }
      double best = kOwnership;
      std::optional<ModeLabel> owner;
      for (const auto& [label, sum] : pull) {
        if (sum.first / sum.second > best) best = sum.first / sum.second, owner = label;
      }
      if (owner) groups[{*owner, damping}].push_back(i);
    }
    Eigen::VectorXd next = x;
    for (const auto& [key, members] : groups) {
      double num = 0, den = 0;
      for (const LogRow& row : rows) {
        if (row.label != key.first || row.damping != key.second) continue;
        double a = 0;
        for (int i : members) a += row.sensitivity[i];
        num += a * row.misfit;
        den += a * a;
      }
      if (!(den > 0)) continue;
      const double step = std::clamp(num / den, -kMaxStep, kMaxStep);
      for (int i : members) next[i] += step;
    }
    next = next.cwiseMax(box.lower).cwiseMin(box.upper);
    if (!std::isfinite(CostAt(residuals, next))) break;
    x = next;
  }
  return x;
}

std::vector<Start> PlanStarts(const ModalResiduals& residuals, const Eigen::VectorXd& x0,
                              const Box& box, int starts, double factor, unsigned seed,
                              const std::function<bool(const Eigen::VectorXd&)>& usable) {
  std::vector<Start> out = {{x0, StartOrigin::kInitial}};
  if (starts < 2 || x0.size() == 0) return out;
  const ParameterSetup& setup = residuals.setup();
  // Where a measured mode is overdamped at the user's guess (its roots
  // real), the sidewall dampers are lowered a factor 3 at a time until every
  // mode oscillates; the other starts are built from there.
  Eigen::VectorXd base = x0;
  for (int k = 0; k < kDamperRepairs && usable && !usable(base); ++k) {
    for (int i = 0; i < setup.size(); ++i) {
      if (setup.is_log(i) && IsDamping(setup.free()[i])) base[i] -= std::log(3.0);
    }
    base = base.cwiseMax(box.lower);
  }
  const Eigen::VectorXd matched = MatchFrequencies(residuals, base, box);
  if ((matched - x0).cwiseAbs().maxCoeff() > 1e-6) {
    out.push_back({matched, StartOrigin::kFrequencyMatched});
  }
  const int scattered = starts - static_cast<int>(out.size());
  if (scattered <= 0) return out;
  const int n = setup.size();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double half_width = std::log(factor);
  // Latin hypercube: each coordinate's range cut into `scattered` strata,
  // one draw in each, strata shuffled per coordinate.
  // Around the matched start and the user's in turn: the matched one
  // follows each label, and where two coupled modes trade their labels near
  // the user's guess (a lateral and a camber) the labels it follows may be
  // the guess's, not the optimum's.
  auto hypercube = [&] {
    std::vector<Eigen::VectorXd> points(scattered, matched);
    for (int k = 1; k < scattered; k += 2) points[k] = base;
    std::vector<int> strata(scattered);
    for (int i = 0; i < n; ++i) {
      std::iota(strata.begin(), strata.end(), 0);
      std::shuffle(strata.begin(), strata.end(), rng);
      const double width = setup.is_log(i) ? half_width : 1.0;
      for (int k = 0; k < scattered; ++k) {
        const double u = (strata[k] + unit(rng)) / scattered;
        points[k][i] += (2 * u - 1) * width;
      }
    }
    for (Eigen::VectorXd& p : points) p = p.cwiseMax(box.lower).cwiseMin(box.upper);
    return points;
  };
  std::vector<Eigen::VectorXd> points = hypercube();
  for (int k = 0; k < scattered; ++k) {
    for (int attempt = 0; attempt < 100 && usable && !usable(points[k]); ++attempt) {
      points[k] = hypercube()[k];
    }
    out.push_back({points[k], StartOrigin::kScattered});
  }
  return out;
}

}  // namespace internal
}  // namespace ringid
