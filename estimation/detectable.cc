#include "estimation/detectable.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include <Eigen/SVD>

#include "estimation/fit.h"
#include "estimation/parallel.h"
#include "estimation/problem.h"
#include "estimation/residuals.h"
#include "estimation/setup.h"
#include "estimation/structure.h"
#include "estimation/uncertainty.h"
#include "model/effects.h"

namespace ringid {

using internal::LocalFit;
using internal::ParameterSetup;

namespace {

// Noise-free data of `truth` under `model`, measured as `dataset` was (the
// same modes, observables, degrees of freedom and sigmas). False when a
// measured mode is lost.
bool Remeasure(const ModalModel& model, const Parameters& truth, const Dataset& dataset,
               const MeasurementOptions& options, Dataset* out) {
  std::vector<ModalSolution> solutions;  // per condition, at its speed
  for (const Condition& c : dataset.conditions) {
    solutions.push_back(model.Solve(truth, c.speed_m_s));
    if (!solutions.back().ok) return false;
  }
  *out = dataset;
  for (const Measurement* unit : Measurements()) {
    for (int i = 0; i < unit->records().Items(*out); ++i) {
      const int c = unit->records().ConditionOf(*out, i);
      const ModelAt at{&model, &truth, &solutions[c], nullptr};  // modes by label
      if (!unit->Measure(at, i, options, out)) return false;
    }
  }
  return true;
}

// The cost at which the baseline, re-calibrated from the calibrated point
// with the diagnosis' prior, fits noise-free data of `truth` under `model`:
// what the diagnosis would see of the difference, noise aside.
double RecalibratedCost(const RigidRingModel& baseline, const ModalModel& model,
                        const Parameters& truth, const Dataset& warm,
                        const DiagnoseOptions& o) {
  Dataset data;
  if (!Remeasure(model, truth, warm, o.fit.residuals, &data)) return INFINITY;
  Status status;
  const auto problem = Problem::Create(baseline, data, o.fit.residuals, &status);
  if (!problem) return NAN;
  const Eigen::VectorXd x0 = problem->start();
  const LocalFit fit = FitLocally(problem->residuals(), Method::kLevenbergMarquardt, x0,
                                  BoundsAround(problem->setup(), x0, o.fit.bound_factor, o.fit.bounds),
                                  o.fit.max_iterations, o.fit.simplex);
  return fit.cost;
}

// RecalibratedCost of the calibrated point with `effect`'s parameter `p` at
// `value` (its other parameters known, or at a typical value).
double AbsorbedCost(const RigidRingModel& baseline, const Effect& effect, Param p, double value,
                    const IdentifyResult& calibrated,
                    const Dataset& warm, const DiagnoseOptions& o) {
  Parameters truth = calibrated.parameters;
  for (Param q : effect.parameters()) {
    if (q == p) truth[q] = value;
    else if (warm.known.count(q)) truth[q] = warm.known.at(q);
    else truth[q] = Info(q).domain == Domain::kPositive ? TypicalScale(q) : 0.0;
  }
  return RecalibratedCost(baseline, baseline.With(&effect), truth, warm, o);
}

// The linearised detectable size `linear` of `p`, checked against the
// re-calibrated baseline (AbsorbedCost) and moved by secant steps in log-log
// until the likelihood ratio is within a factor 1.5 of `detect`. A column
// outside the baseline's span can be absorbed at second order (a compliant
// hub against softer stiffnesses): the linear size then promises too much.
// `zero` is RecalibratedCost of the calibrated baseline itself.
double CheckedDetectable(const RigidRingModel& baseline, const Effect& effect, Param p,
                         double linear, const IdentifyResult& calibrated,
                         const Dataset& warm, const DiagnoseOptions& o, double zero, double detect) {
  if (!std::isfinite(linear) || !(linear > 0) || !std::isfinite(zero)) return linear;
  double v = linear, v_prev = 0, lr_prev = 0;
  for (int step = 0; step < 5; ++step) {
    const double lr = 2 * (AbsorbedCost(baseline, effect, p, v, calibrated, warm, o) - zero);
    if (!std::isfinite(lr)) return v;  // a mode is lost: certainly seen
    if (lr > detect / 1.5 && lr < detect * 1.5) return v;
    double next;
    if (!(lr > 1e-3 * detect)) {
      next = 4 * v;  // absorbed: no slope to follow
    } else {
      double k = 2;  // a likelihood ratio grows as the size squared at first order
      if (v_prev > 0 && lr_prev > 1e-3 * detect && v != v_prev) {
        k = std::clamp(std::log(lr / lr_prev) / std::log(v / v_prev), 1.0, 8.0);
      }
      next = v * std::pow(detect / lr, 1 / k);
    }
    v_prev = v, lr_prev = lr;
    v = next;
  }
  return v;
}

}  // namespace

namespace internal {

std::map<std::string, double> MinimalDetectable(const RigidRingModel& baseline,
                                                const Effect& effect, const Dataset& warm,
                                                const Eigen::MatrixXd& J_base, int rank,
                                                const DiagnoseOptions& o, double detect) {
  std::map<std::string, double> out;
  const RigidRingModel model = baseline.With(&effect);
  Dataset at = warm;
  for (Param p : effect.parameters()) {
    if (!at.known.count(p)) at.initial[p] = TypicalScale(p);  // away from a kink at 0
  }
  Status status;
  const auto problem = Problem::Create(model, at, o.fit.residuals, &status);
  Eigen::MatrixXd J;
  if (!problem || !EvaluateJacobian(problem->residuals(), problem->start(), &J) ||
      J.rows() != J_base.rows()) {
    return out;
  }
  const ParameterSetup& setup = problem->setup();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(J_base, Eigen::ComputeThinU);
  const Eigen::MatrixXd U = svd.matrixU().leftCols(rank);
  for (int c = static_cast<int>(J_base.cols()); c < J.cols(); ++c) {
    const Eigen::VectorXd j = J.col(c);
    const double outside = (j - U * (U.transpose() * j)).norm();
    const Param p = setup.free()[c];
    // A parameter that cannot be 0 (the hub mass m_a) sizes nothing.
    if (Info(p).domain == Domain::kPositive) continue;
    out[ParamName(p)] = outside > 0 ? std::sqrt(detect) / outside * TypicalScale(p) : INFINITY;
  }
  return out;
}

namespace {

// A component of a structural invariance counts where it is above rounding
// (as estimation/structure.cc reads them).
constexpr double kInvariancePart = 1e-8;
// The data confirm an invariance where the exact Jacobian along it is this
// small against the effect parameter's own column: the system's entries miss
// what an FRF's axle channels and contact inputs read of the parameters
// (k_bz in the axle's force, dk_bz with it), which the data then separate.
constexpr double kUnseenAlong = 1e-6;

bool InEffect(const Effect& effect, const std::string& name) {
  for (Param q : effect.parameters()) {
    if (name == ParamName(q)) return true;
  }
  return false;
}

// A sizing parameter of the effect (coordinate k) moving with free baseline
// parameters `by` along `direction`, which the data do not see.
struct Absorption {
  int k;
  Eigen::VectorXd direction;
  std::vector<std::string> by;
};

// Each sizing parameter of `effect` that takes part, with free baseline
// parameters, in a structural invariance (`readable`, in `problem`'s
// coordinates) that the problem's exact Jacobian at its start confirms.
std::vector<Absorption> Absorptions(const Problem& problem, const Effect& effect,
                                    const std::vector<Eigen::VectorXd>& readable) {
  std::vector<Absorption> out;
  const int n = problem.num_coordinates();
  for (Param p : effect.parameters()) {
    int k = -1;
    for (int i = 0; i < n; ++i) {
      if (problem.coordinate_name(i) == ParamName(p)) k = i;
    }
    if (k < 0 || Info(p).domain == Domain::kPositive) continue;  // m_a sizes nothing
    for (const Eigen::VectorXd& v : readable) {
      if (v.size() != n) continue;
      const double big = v.cwiseAbs().maxCoeff();
      if (!(std::abs(v[k]) > kInvariancePart * big)) continue;
      Absorption a{k, v, {}};
      for (int i = 0; i < n; ++i) {
        const std::string name = problem.coordinate_name(i);
        if (std::abs(v[i]) > kInvariancePart * big && !InEffect(effect, name)) a.by.push_back(name);
      }
      if (!a.by.empty()) {
        out.push_back(std::move(a));
        break;
      }
    }
  }
  if (out.empty()) return out;
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  if (!problem.Evaluate(problem.start(), &r, &J)) return {};
  std::vector<Absorption> confirmed;
  for (Absorption& a : out) {
    const double own = (J.col(a.k) * a.direction[a.k]).norm();
    if ((J * a.direction).norm() <= kUnseenAlong * own) confirmed.push_back(std::move(a));
  }
  return confirmed;
}

// Absorptions at `fit`, a fit of `model` (the baseline with `effect`).
std::vector<Absorption> Absorptions(const RigidRingModel& model, const Dataset& dataset,
                                    const Effect& effect, const IdentifyResult& fit,
                                    const ResidualOptions& options) {
  Dataset at = dataset;
  for (const ParameterEstimate& e : fit.estimates) {
    if (e.free) at.initial[e.param()] = e.value;
  }
  Status status;
  const auto problem = Problem::Create(model, at, options, &status);
  if (!problem || problem->num_coordinates() != fit.x.size()) return {};
  return Absorptions(*problem, effect, fit.uncertainty.structural_readable);
}

}  // namespace

std::map<std::string, std::vector<std::string>> AbsorbedBy(const RigidRingModel& model,
                                                           const Dataset& dataset,
                                                           const Effect& effect,
                                                           const IdentifyResult& fit,
                                                           const ResidualOptions& options) {
  std::map<std::string, std::vector<std::string>> out;
  for (const Absorption& a : Absorptions(model, dataset, effect, fit, options)) {
    out[fit.coordinate_names[a.k]] = a.by;
  }
  return out;
}

std::map<std::string, std::vector<std::string>> AbsorbedAt(const RigidRingModel& model,
                                                           const Dataset& at,
                                                           const Effect& effect,
                                                           const ResidualOptions& options) {
  std::map<std::string, std::vector<std::string>> out;
  Status status;
  const auto problem = Problem::Create(model, at, options, &status);
  if (!problem) return out;
  const StructuralFreedom freedom = FindStructuralFreedom(problem->residuals(), problem->start());
  for (const Absorption& a : Absorptions(*problem, effect, freedom.readable)) {
    out[problem->coordinate_name(a.k)] = a.by;
  }
  return out;
}

Dataset BaselineFrom(const RigidRingModel& model, const Dataset& dataset, const Effect& effect,
                     const IdentifyResult& fit, const ResidualOptions& options) {
  Dataset d = dataset;
  for (const ParameterEstimate& e : fit.estimates) {
    if (e.free) d.initial[e.param()] = e.value;
  }
  ParameterSetup setup;
  std::string error;
  if (ParameterSetup::Build(model, d, &setup, &error) && setup.size() == fit.x.size()) {
    Eigen::VectorXd x = fit.x;
    for (const Absorption& a : Absorptions(model, dataset, effect, fit, options)) {
      x -= (x[a.k] / a.direction[a.k]) * a.direction;
    }
    const Parameters moved = setup.Decode(x.data(), 0);
    for (Param q : setup.free()) d.initial[q] = moved[q];
  }
  for (Param q : effect.parameters()) d.initial.erase(q);
  return d;
}

std::string DetectableSizes(const RigidRingModel& baseline, const Dataset& warm,
                            const DiagnoseOptions& o, DiagnosisResult* r) {
  const double zero = RecalibratedCost(baseline, baseline, r->baseline.parameters, warm, o);
  struct Size {
    const Effect* effect;
    Param p;
    double* v;
  };
  std::vector<Size> sizes;
  for (EffectFit& f : r->ranking) {
    for (auto& [name, v] : f.minimal_detectable) sizes.push_back({f.effect, *ParseParam(name), &v});
  }
  internal::ParallelFor(static_cast<int>(sizes.size()), o.fit.threads, [&](int k) {
    const Size& s = sizes[k];
    *s.v = CheckedDetectable(baseline, *s.effect, s.p, *s.v, r->baseline, warm, o, zero,
                             o.detectable_likelihood_ratio);
  });
  std::ostringstream small;
  for (EffectFit& f : r->ranking) {
    for (auto& [name, v] : f.minimal_detectable) {
      char b[96];
      std::snprintf(b, sizeof b, "%s%s |%s| < %.3g", small.tellp() ? ", " : "", f.effect->name(),
                    name.c_str(), v);
      small << b;
    }
  }
  return small.str();
}

}  // namespace internal

}  // namespace ringid
