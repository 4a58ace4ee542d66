#include "datasets/synthetic.h"

#include <algorithm>
#include <cmath>

namespace ringid {

bool Simulate(const ModalModel& model, const Parameters& truth,
              const SimulateOptions& o, std::mt19937_64* rng, Dataset* d,
              std::string* error) {
  std::normal_distribution<double> n(0, 1);
  const ModalSolution s = model.Solve(truth);
  if (!s.ok) {
    *error = "the truth model cannot be solved: " + s.error;
    return false;
  }
  d->modes.clear();
  for (int l = 0; l < 7; ++l) {
    const Mode* m = s.Find(static_cast<ModeLabel>(l));
    if (!m) {
      *error = std::string("the truth has no oscillating ") +
               LabelName(static_cast<ModeLabel>(l)) + " mode";
      return false;
    }
    MeasuredMode mm;
    mm.label = m->label;
    mm.frequency_hz = m->frequency_hz * (1 + o.frequency_noise * n(*rng));
    mm.frequency_sigma_hz = o.frequency_noise * m->frequency_hz;
    if (o.damping) {
      mm.damping_ratio = std::clamp(m->damping_ratio * (1 + o.damping_noise * n(*rng)), 1e-4, 0.999);
      mm.damping_sigma = o.damping_noise * m->damping_ratio;
    }
    if (o.shapes) {
      const RealShapeVector u = m->RealShape();
      const int dofs = o.hub_components ? kNumDofs : static_cast<int>(Dof::kXa);
      for (int i = 0; i < dofs; ++i) {
        mm.shape.emplace_back(static_cast<Dof>(i), u[i] + o.shape_noise * n(*rng));
      }
      mm.shape_sigma = o.shape_noise;
    }
    d->modes.push_back(mm);
  }
  return true;
}

void SetEngineerPriors(const Parameters& truth, double prior_spread,
                       std::mt19937_64* rng, Dataset* d) {
  std::normal_distribution<double> normal(0, 1);
  for (Param q : {Param::m_b, Param::I_ay, Param::I_by, Param::I_bx, Param::I_bz,
                  Param::F_cz0, Param::sigma_cx, Param::sigma_cy}) {
    d->known[q] = truth[q];
  }
  if (truth.IsSet(Param::m_a)) d->known[Param::m_a] = truth[Param::m_a];
  d->ties = {{Param::c_bz, Param::c_bx}, {Param::k_bz, Param::k_bx},
             {Param::c_bpsi, Param::c_bgamma}, {Param::k_bpsi, Param::k_bgamma}};
  for (int i = 0; i < kNumParams; ++i) {
    const Param q = ParamAt(i);
    if (Info(q).group == Group::kEffect || d->known.count(q) || d->ties.count(q)) continue;
    d->initial[q] = truth[q] * std::exp(prior_spread * normal(*rng));
  }
}

double LargestShift(const Parameters& truth, const Effect& effect, Param p, double value) {
  const ModalSolution base = RigidRingModel().Solve(truth);
  Parameters q = truth;
  q[p] = value;
  const ModalSolution with = RigidRingModel({&effect}).Solve(q);
  if (!base.ok || !with.ok) return INFINITY;
  double shift = 0;
  for (const Mode& m : base.modes) {
    const Mode* w = with.Find(m.label);
    if (!w) return INFINITY;
    shift = std::max(shift, std::abs(w->frequency_hz / m.frequency_hz - 1));
  }
  return shift;
}

double ValueForShift(const Parameters& truth, const Effect& effect, Param p, double target) {
  double lo = TypicalScale(p) * 1e-4, hi = TypicalScale(p) * 1e3;
  for (int k = 0; k < 60; ++k) {
    const double mid = std::sqrt(lo * hi);
    (LargestShift(truth, effect, p, mid) < target ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

}  // namespace ringid
