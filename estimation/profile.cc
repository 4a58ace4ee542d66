// The profile likelihood of one coordinate (ProfileCoordinate): refits with
// it held, stepped away from the optimum until 2 delta cost passes the
// chi-square(1) 95 % point, then the crossing bisected; jumps retried by a
// walk (IdentifiabilityOptions says how far and how finely).
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "estimation/fit.h"
#include "estimation/identifiability.h"
#include "estimation/identifiability_internal.h"
#include "estimation/problem.h"
#include "estimation/residuals.h"
#include "estimation/setup.h"
#include "estimation/uncertainty.h"
#include "estimation/statistics.h"

namespace ringid {

using internal::Box;
using internal::LocalFit;
using internal::ModalResiduals;
using internal::ParameterSetup;

namespace {

// Where a profile's crossing of the threshold is refined: within this of it
// (2 delta cost), or once the bracket is below kSmallestBracket (coordinate
// units: a jump), after at most kMaxBisections midpoints.
constexpr double kCrossingTolerance = 0.02;
constexpr double kSmallestBracket = 1e-6;
constexpr int kMaxBisections = 40;
// How often a step whose refit fails is halved toward the last good point,
// and a refit over the threshold restarted from where it stopped.
constexpr int kStepHalvings = 4;
constexpr int kRestarts = 3;
// A jump is retried by a walk of kWalkSteps refits, each warm-started from
// the one before, from the last profile point under the threshold to the
// jump; at most kJumpRetries times a side.
constexpr int kWalkSteps = 8;
constexpr int kJumpRetries = 3;

// One point of a profile: coordinate i held at t, the others refitted.
struct ProfilePoint {
  double t = 0;
  double delta = 0;  // 2 (cost - cost_min), at least 0
  Eigen::VectorXd x;
};

// How a bracket [under the threshold, over it] ended: at a crossing (t the
// bound), at a jump (t the first point over it, 1e-6 past the last under
// it), or failed (t where no refit was possible).
struct BracketEnd {
  enum Kind { kCrossing, kJump, kFailed } kind = kCrossing;
  double t = 0;
};

// The profile of one coordinate: refits with it held, from given starts.
class Profiler {
 public:
  Profiler(const ModalResiduals& residuals, const Eigen::VectorXd& xhat, double cost_min,
           const Box& box, int i, const IdentifiabilityOptions& o)
      : residuals_(residuals), xhat_(xhat), cost_min_(cost_min), box_(box), i_(i), o_(o) {}

  // Coordinate i held at t, the others refitted from each start in turn
  // (its coordinate i set to t), then from xhat: the first under the
  // threshold, else the lowest (a refit from a neighbour can land in a worse
  // valley than one from xhat); none when no start gives a finite cost.
  std::optional<ProfilePoint> RefitAt(double t, std::vector<const Eigen::VectorXd*> starts) const {
    starts.push_back(&xhat_);
    std::vector<Eigen::VectorXd> tried;
    std::optional<LocalFit> best;
    for (const Eigen::VectorXd* start : starts) {
      Eigen::VectorXd x = *start;
      x[i_] = t;
      if (std::find(tried.begin(), tried.end(), x) != tried.end()) continue;
      tried.push_back(x);
      LocalFit fit = Refit(x);
      if (std::isfinite(fit.cost) && (!best || fit.cost < best->cost)) best = std::move(fit);
      if (best && Delta(best->cost) < kChiSquare1Dof95) break;
    }
    if (!best) return std::nullopt;
    // Over the threshold, Levenberg-Marquardt may have stalled (next to
    // where the model cannot be solved): restarted while each restart
    // removes a tenth of the excess over the threshold.
    for (int k = 0; k < kRestarts && Delta(best->cost) >= kChiSquare1Dof95; ++k) {
      const double excess = Delta(best->cost) - kChiSquare1Dof95;
      LocalFit again = Refit(best->x);
      const double gain = 2 * (best->cost - again.cost);  // -inf where it failed
      if (gain > 0) best = std::move(again);
      if (!(gain > std::max(kCrossingTolerance, 0.1 * excess))) break;
    }
    return ProfilePoint{t, Delta(best->cost), best->x};
  }

  // The crossing between `below` (under the threshold) and `above` (over
  // it) by bisection on the coordinate, each midpoint refitted from the
  // nearer end first; the first trial is where the signed root of 2 delta
  // cost, linear in t for a quadratic profile, interpolates to the
  // threshold.
  BracketEnd Bisect(ProfilePoint below, ProfilePoint above,
                    std::vector<std::pair<double, double>>* curve,
                    const ParameterSetup& setup) const {
    for (int b = 0; b < kMaxBisections; ++b) {
      if (std::abs(above.delta - kChiSquare1Dof95) < kCrossingTolerance) return {BracketEnd::kCrossing, above.t};
      if (std::abs(below.delta - kChiSquare1Dof95) < kCrossingTolerance) return {BracketEnd::kCrossing, below.t};
      if (std::abs(above.t - below.t) < kSmallestBracket) break;
      double fraction = 0.5;
      if (b == 0) {  // kept within the middle 80 % of the bracket
        const double a = std::sqrt(below.delta), c = std::sqrt(above.delta);
        fraction = std::clamp((std::sqrt(kChiSquare1Dof95) - a) / (c - a), 0.1, 0.9);
      }
      const double t = below.t + fraction * (above.t - below.t);
      const bool nearer_below = fraction <= 0.5;
      const std::optional<ProfilePoint> mid =
          nearer_below ? RefitAt(t, {&below.x, &above.x}) : RefitAt(t, {&above.x, &below.x});
      if (!mid) return {BracketEnd::kFailed, t};
      curve->emplace_back(setup.ToPhysical(i_, t), mid->delta);
      (mid->delta < kChiSquare1Dof95 ? below : above) = *mid;
    }
    return {BracketEnd::kJump, above.t};
  }

  // Refits at kWalkSteps even steps from `from` to t, each warm-started from
  // the one before, up to the first over the threshold or that failed.
  std::vector<ProfilePoint> Walk(const ProfilePoint& from, double t) const {
    std::vector<ProfilePoint> walk;
    const ProfilePoint* previous = &from;
    for (int k = 1; k <= kWalkSteps; ++k) {
      std::optional<ProfilePoint> next =
          RefitAt(from.t + (t - from.t) * k / kWalkSteps, {&previous->x});
      if (!next) break;
      walk.push_back(std::move(*next));
      previous = &walk.back();
      if (previous->delta >= kChiSquare1Dof95) break;
    }
    return walk;
  }

 private:
  LocalFit Refit(const Eigen::VectorXd& start) const {
    return FitLocally(residuals_, Method::kLevenbergMarquardt, start, box_, o_.fit.max_iterations,
                      o_.fit.simplex, i_, o_.fit.stop_chi_square);
  }
  double Delta(double cost) const { return std::max(0.0, 2 * (cost - cost_min_)); }

  const ModalResiduals& residuals_;
  const Eigen::VectorXd& xhat_;
  const double cost_min_;
  const Box& box_;
  const int i_;
  const IdentifiabilityOptions& o_;
};

}  // namespace

namespace internal {

ProfileInterval ProfileCoordinate(const Problem& problem, const Eigen::VectorXd& xhat,
                                  double cost_min, int i, double wald_std,
                                  const IdentifiabilityOptions& o) {
  const ParameterSetup& setup = problem.setup();
  const Box box = BoundsAround(setup, problem.start(), o.fit.bound_factor, o.fit.bounds);
  const Profiler profiler(problem.residuals(), xhat, cost_min, box, i, o);
  ProfileInterval p;
  p.computed = true;
  p.curve.emplace_back(setup.ToPhysical(i, xhat[i]), 0.0);
  for (int side : {-1, +1}) {
    ProfilePoint last{xhat[i], 0.0, xhat};
    // Start at a quarter of the Wald standard deviation where there is one.
    double step = std::isfinite(wald_std) ? std::min(o.profile_first_step, 0.25 * wald_std)
                                          : o.profile_first_step;
    std::optional<BracketEnd> end;
    std::optional<double> failed;  // nearest t past `last` no refit reached
    int retries = 0;
    for (int k = 0; k < o.profile_steps; ++k) {
      double t = std::clamp(last.t + side * step, box.lower[i], box.upper[i]);
      std::optional<ProfilePoint> next = profiler.RefitAt(t, {&last.x});
      // A failed refit: the step halved toward the last good point.
      for (int h = 0; !next && h < kStepHalvings; ++h) {
        failed = t;
        t = last.t + 0.5 * (t - last.t);
        next = profiler.RefitAt(t, {&last.x});
      }
      if (!next) {
        failed = t;
        break;
      }
      const size_t mark = p.curve.size();
      p.curve.emplace_back(setup.ToPhysical(i, t), next->delta);
      if (failed && side * (t - *failed) >= 0) failed.reset();  // got past it
      if (next->delta >= kChiSquare1Dof95) {
        end = profiler.Bisect(last, *next, &p.curve, setup);
        if (end->kind == BracketEnd::kJump && retries < kJumpRetries) {
          // A failed refit or another optimum: walked to again from `last`.
          ++retries;
          std::vector<ProfilePoint> walk = profiler.Walk(last, end->t);
          if (walk.empty()) break;
          p.curve.resize(mark);  // the walk supersedes the step and its bisection
          for (const ProfilePoint& w : walk) p.curve.emplace_back(setup.ToPhysical(i, w.t), w.delta);
          if (walk.back().delta >= kChiSquare1Dof95) {
            end = profiler.Bisect(walk.size() > 1 ? walk[walk.size() - 2] : last, walk.back(),
                                  &p.curve, setup);
            break;
          }
          end.reset();  // the jump was a failed refit: the scan goes on
          --k;
          last = walk.back();
          continue;
        }
        break;
      }
      if (t <= box.lower[i] || t >= box.upper[i]) break;
      step = std::abs(t - last.t) * o.profile_growth;
      last = *next;
    }
    const auto set = [&](std::optional<double>* lower, std::optional<double>* upper, double t) {
      (side < 0 ? *lower : *upper) = setup.ToPhysical(i, t);
    };
    if (end && end->kind == BracketEnd::kCrossing) set(&p.lower, &p.upper, end->t);
    else if (end && end->kind == BracketEnd::kJump) set(&p.lower_jump_at, &p.upper_jump_at, end->t);
    else if (end && end->kind == BracketEnd::kFailed) set(&p.lower_failed_at, &p.upper_failed_at, end->t);
    else if (failed) set(&p.lower_failed_at, &p.upper_failed_at, *failed);
  }
  std::sort(p.curve.begin(), p.curve.end());
  return p;
}

}  // namespace internal

}  // namespace ringid
