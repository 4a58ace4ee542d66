// The score (Lagrange-multiplier) test of an effect at the calibrated
// baseline: whether the data pull its size away from 0, judged without
// fitting it (Rao 1948; Neyman's C(alpha) form, robust to a baseline a little
// off its optimum). Diagnose refits only the effects it keeps.
#ifndef RINGID_ESTIMATION_SCORE_H_
#define RINGID_ESTIMATION_SCORE_H_

#include <Eigen/Core>

#include "datasets/dataset.h"
#include "estimation/options.h"
#include "model/rigid_ring_model.h"

namespace ringid {
namespace internal {

struct EffectScore {
  bool ok = false;  // false when the effect's model cannot be evaluated there
  // r' S (S' S)^-1 S' r with r the weighted residuals at the baseline's
  // optimum and S the effect's signature (d r / d size, each sizing
  // parameter) with its part in the span of the baseline's Jacobian
  // removed. Chi-square on `dof` under "size 0"; one-sided (the upper normal
  // tail of the signed root) for one parameter that cannot be negative.
  double statistic = 0;
  int dof = 0;  // sizing parameters whose signature leaves the span
  double p = 1;
  // False where a sizing parameter has no derivative at 0 (the forward
  // difference stood in): the test's theory needs one, so its p-value is a
  // guide only (a hub released at s_h = 0).
  bool smooth = true;
  // Orthonormal columns spanning the projected signature (residuals x dof):
  // two effects whose spans nearly share a direction are rivals.
  Eigen::MatrixXd signature;
};

// `warm` with `effect`'s sizing parameters at 0 (the baseline's model) and
// its others (the hub mass m_a) at their typical values, known ones as known.
Dataset EffectAtZero(const Effect& effect, const Dataset& warm);

// The signature is the forward difference at kScoreStep of each sizing
// parameter's typical scale (its derivative at 0+, where a hub released at
// s_h = 0 has no derivative at 0 itself); the effect's other parameters at
// their known or typical values. `warm`: the dataset seeded at the calibrated
// baseline (every free parameter's initial value its estimate).
inline constexpr double kScoreStep = 1e-3;
EffectScore ScoreEffect(const RigidRingModel& baseline, const Effect& effect, const Dataset& warm,
                        const ResidualOptions& residuals, double rank_tolerance);

// The largest canonical correlation between two scores' signatures (0 when
// either has none): 1 where one effect's pull is, to first order, the other's.
double SignatureOverlap(const EffectScore& a, const EffectScore& b);

}  // namespace internal
}  // namespace ringid

#endif  // RINGID_ESTIMATION_SCORE_H_
