// Rolling labels by continuation in speed (docs/rolling.md §5): modes carried
// from standstill step by step, paired by shape (MAC) and kept nearer their
// predicted eigenvalues than their neighbours'; and the one strict step that
// carries labels to a nearby point at the same speed (SolveNear). Declared in
// model/modal.h.
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "model/assignment.h"
#include "model/modal.h"

namespace ringid {

using internal::AssignMaxScore;

namespace {

// |a^H b|^2 / (|a|^2 |b|^2): the complex MAC of two displacement shapes.
double ComplexMac(const ShapeVector& a, const ShapeVector& b) {
  const double ab = std::norm(a.dot(b));
  const double aa = a.squaredNorm(), bb = b.squaredNorm();
  return aa > 0 && bb > 0 ? ab / (aa * bb) : 0;
}

// How Follow accepts the assignment by shape (docs/rolling.md §5).
enum class Rule {
  kShape,  // as it is
  // A step in speed: every pair looks alike (MAC >= 0.8) and each eigenvalue
  // lies less than half the distance from its prediction (`expected`, else
  // its predecessor) to the nearest other prediction of shared support.
  kStep,
  // A nearby point at the same speed, with as many modes: every pair looks
  // alike (MAC >= 0.9), and each other predecessor of shared support is told
  // apart by shape (MAC < 0.5) or lies farther from the new eigenvalue than
  // the pair's own. With roughly orthogonal shapes the first clause decides.
  kNear,
};

// Gives `next` the labels of `prev` by shape, where `rule` accepts the
// assignment. A mode with no predecessor (a real pair turned oscillatory)
// takes a label that had vanished, its own by energy where it can.
bool Follow(const ModalSolution& prev, ModalSolution* next, Rule rule,
            const std::vector<std::complex<double>>& expected = {}) {
  const int np = static_cast<int>(prev.modes.size());
  const int nn = static_cast<int>(next->modes.size());
  if (np == 0 || nn == 0) return nn == np;
  if (rule == Rule::kNear && nn != np) return false;  // a pair turned real or back
  Eigen::MatrixXd mac(nn, np);
  for (int i = 0; i < nn; ++i) {
    for (int j = 0; j < np; ++j) mac(i, j) = ComplexMac(next->modes[i].shape, prev.modes[j].shape);
  }
  std::vector<int> pick(nn, -1);
  if (nn <= np) {
    pick = AssignMaxScore(mac);
  } else {
    const std::vector<int> back = AssignMaxScore(mac.transpose());
    for (int j = 0; j < np; ++j) {
      if (back[j] >= 0) pick[back[j]] = j;
    }
  }
  const auto shared = [&](int o, int j) {
    return ((prev.modes[o].shape.cwiseAbs().array() > 0) &&
            (prev.modes[j].shape.cwiseAbs().array() > 0)).any();
  };
  for (int i = 0; i < nn; ++i) {
    const int j = pick[i];
    if (j < 0 || rule == Rule::kShape) continue;
    if (mac(i, j) < (rule == Rule::kStep ? 0.8 : 0.9)) return false;
    const auto before = [&](int k) {
      return expected.empty() ? prev.modes[k].eigenvalue : expected[k];
    };
    const std::complex<double> now = next->modes[i].eigenvalue, was = before(j);
    double limit = std::numeric_limits<double>::infinity();
    for (int o = 0; o < np; ++o) {
      if (o == j || !shared(o, j)) continue;
      const std::complex<double> other = before(o);
      if (rule == Rule::kStep) {
        limit = std::min(limit, 0.5 * std::abs(other - was));
      } else if (mac(i, o) >= 0.5) {
        limit = std::min(limit, std::abs(other - now));
      }
    }
    if (std::abs(now - was) > limit) return false;
  }
  std::vector<ModeLabel> free = prev.vanished;
  std::vector<bool> used(np, false);
  for (int i = 0; i < nn; ++i) {
    if (pick[i] < 0) continue;
    next->modes[i].label = prev.modes[pick[i]].label;
    used[pick[i]] = true;
  }
  for (int i = 0; i < nn; ++i) {
    if (pick[i] >= 0) continue;
    auto it = std::find(free.begin(), free.end(), next->modes[i].label);
    if (it == free.end()) {
      it = std::find_if(free.begin(), free.end(),
                        [&](ModeLabel l) { return LabelPlane(l) == next->modes[i].plane(); });
    }
    if (it == free.end()) return false;
    next->modes[i].label = *it;
    free.erase(it);
  }
  for (int j = 0; j < np; ++j) {
    if (!used[j]) free.push_back(prev.modes[j].label);
  }
  next->vanished = free;
  return true;
}

}  // namespace

std::optional<ModalSolution> SolveNear(const ModalSolution& near, const MechanicalSystem& system,
                                       const BasicSystem<ParameterJet>* jets) {
  if (!near.ok) return std::nullopt;
  ModalSolution next = SolveModes(system, jets);
  if (!next.ok || !Follow(near, &next, Rule::kNear)) return std::nullopt;
  return next;
}

bool SameLabelsNear(const ModalSolution& near, const ModalSolution& at) {
  if (!near.ok || !at.ok) return false;
  ModalSolution carried = at;
  if (!Follow(near, &carried, Rule::kNear)) return false;
  for (size_t i = 0; i < at.modes.size(); ++i) {
    if (carried.modes[i].label != at.modes[i].label) return false;
  }
  return true;
}

ModalSolution SolveRolling(
    const std::function<MechanicalSystem(double)>& assemble, double speed,
    ModalSolution standing,
    const std::function<BasicSystem<ParameterJet>(double)>& assemble_jets, bool* forced) {
  if (forced) *forced = false;
  ModalSolution prev = std::move(standing);
  if (!prev.ok || !(speed > 0)) return prev;
  // Below this step the assignment by shape is taken as it is (an exact
  // degeneracy, where continuation has no direction to follow).
  const double finest = speed / 256;
  double at = 0, step = speed;
  // The step before `prev`, to predict each eigenvalue by linear extrapolation.
  ModalSolution older;
  double older_at = 0;
  while (at < speed) {
    const double to = std::min(speed, at + step);
    std::optional<BasicSystem<ParameterJet>> jets;
    if (assemble_jets && to == speed) jets = assemble_jets(to);
    ModalSolution next = SolveModes(assemble(to), jets ? &*jets : nullptr);
    if (!next.ok) return next;
    std::vector<std::complex<double>> expected;
    for (const Mode& m : prev.modes) {
      const Mode* o = older.ok ? older.Find(m.label) : nullptr;
      const double ahead = (to - at) / (at - older_at);
      expected.push_back(o ? m.eigenvalue + (m.eigenvalue - o->eigenvalue) * ahead : m.eigenvalue);
    }
    const bool coarse = step <= finest;
    if (Follow(prev, &next, coarse ? Rule::kShape : Rule::kStep, expected)) {
      if (coarse && forced) *forced = true;
      older = std::move(prev);
      older_at = at;
      prev = std::move(next);
      at = to;
      step *= 2;
    } else if (coarse) {
      next.ok = false;
      next.error = "the modes at " + std::to_string(to) + " m/s cannot be matched to those at " +
                   std::to_string(at) + " m/s";
      return next;
    } else {
      step /= 4;
    }
  }
  return prev;
}

}  // namespace ringid
