#include "estimation/residuals.h"

#include <cmath>

#include <ceres/dynamic_numeric_diff_cost_function.h>

#include "model/assignment.h"

namespace ringid {

bool ResidualOptions::IsValid(std::string* why) const {
  if (!(relative_sigma > 0 && std::isfinite(relative_sigma))) {
    *why = "relative_sigma must be positive";
    return false;
  }
  if (!(prior_sigma >= 0) || !std::isfinite(prior_sigma)) {
    *why = "prior_sigma must be finite and not negative";
    return false;
  }
  if (!(default_damping_sigma > 0) || !(default_shape_sigma > 0)) {
    *why = "default sigmas must be positive";
    return false;
  }
  return true;
}

RealShapeVector ComparableShape(const Mode& mode, ShapeConvention c) {
  return c == ShapeConvention::kPaper ? mode.PaperShape() : mode.RealShape();
}

double Mac(const RealShapeVector& model,
           const std::vector<std::pair<Dof, double>>& measured) {
  double mm = 0, uu = 0, mu = 0;
  for (const auto& [dof, v] : measured) {
    const double u = model[static_cast<int>(dof)];
    mm += v * v;
    uu += u * u;
    mu += u * v;
  }
  if (!(mm > 0) || !(uu > 0)) return 0;
  return mu * mu / (mm * uu);
}

namespace internal {

ModalResiduals::ModalResiduals(const ModalModel& model, const Dataset& dataset,
                               const ParameterSetup& setup,
                               const ResidualOptions& options)
    : model_(model), dataset_(dataset), setup_(setup), options_(options) {
  for (int i = 0; i < static_cast<int>(dataset.modes.size()); ++i) {
    const MeasuredMode& m = dataset.modes[i];
    slots_.push_back({i, Slot::kFrequency});
    if (options_.use_damping && m.damping_ratio) {
      slots_.push_back({i, Slot::kDamping});
    }
    if (options_.use_shapes) {
      for (const auto& [dof, v] : m.shape) {
        slots_.push_back({i, Slot::kShape, dof});
      }
    }
  }
  if (options_.prior_sigma > 0) {
    for (int i = 0; i < setup.size(); ++i) {
      const Param p = setup.free()[i];
      const auto it = options_.prior.find(p);
      if (Info(p).group == Group::kEffect || it == options_.prior.end() || !(it->second > 0) ||
          !setup.is_log(i)) {
        continue;
      }
      Slot prior{-1, Slot::kPrior};
      prior.coordinate = i;
      prior.center = std::log(it->second);
      slots_.push_back(prior);
    }
  }
  num_residuals_ = static_cast<int>(slots_.size());
}

bool ModalResiduals::Pair(const double* x, ModalSolution* solution,
                          std::vector<int>* pairs, std::string* why) const {
  *solution = model_.Solve(setup_.Decode(x));
  if (!solution->ok) {
    *why = solution->error;
    return false;
  }
  const auto& measured = dataset_.modes;
  const auto& modes = solution->modes;
  pairs->assign(measured.size(), -1);
  // Measured shapes decide their pairing by MAC (docs/conventions.md §2) ...
  std::vector<int> shaped;
  for (int i = 0; i < static_cast<int>(measured.size()); ++i) {
    if (!measured[i].shape.empty()) shaped.push_back(i);
  }
  if (!shaped.empty()) {
    if (shaped.size() > modes.size()) {
      *why = "fewer model modes than measured shapes";
      return false;
    }
    Eigen::MatrixXd score(shaped.size(), modes.size());
    for (size_t a = 0; a < shaped.size(); ++a) {
      for (size_t b = 0; b < modes.size(); ++b) {
        score(a, b) = Mac(ComparableShape(modes[b], options_.shape_convention),
                          measured[shaped[a]].shape);
      }
    }
    const std::vector<int> pick = AssignMaxScore(score);
    for (size_t a = 0; a < shaped.size(); ++a) (*pairs)[shaped[a]] = pick[a];
  }
  // ... and the label decides the rest.
  for (int i = 0; i < static_cast<int>(measured.size()); ++i) {
    if ((*pairs)[i] >= 0) continue;
    for (int b = 0; b < static_cast<int>(modes.size()); ++b) {
      if (modes[b].label == measured[i].label) (*pairs)[i] = b;
    }
    if ((*pairs)[i] < 0) {
      *why = std::string("the model has no oscillating ") +
             LabelName(measured[i].label) + " mode (its roots are real)";
      return false;
    }
  }
  return true;
}

bool ModalResiduals::Evaluate(const double* x, double* r) const {
  ++evaluations_;
  ModalSolution solution;
  std::vector<int> pairs;
  std::string why;
  if (!Pair(x, &solution, &pairs, &why)) return false;
  int k = 0;
  while (k < num_residuals_) {
    const Slot& slot = slots_[k];
    if (slot.kind == Slot::kPrior) {
      r[k++] = (x[slot.coordinate] - slot.center) / options_.prior_sigma;
      continue;
    }
    const MeasuredMode& m = dataset_.modes[slot.mode];
    const Mode& mode = solution.modes[pairs[slot.mode]];
    switch (slot.kind) {
      case Slot::kFrequency: {
        r[k++] = (mode.frequency_hz - m.frequency_hz) / FrequencySigma(m);
        break;
      }
      case Slot::kDamping:
        r[k++] = (mode.damping_ratio - *m.damping_ratio) /
                 m.damping_sigma.value_or(options_.default_damping_sigma);
        break;
      case Slot::kPrior:
        break;
      case Slot::kShape: {
        // Component-wise after alignment: the measured shape scaled to a
        // largest component of 1, the model shape by least squares onto it.
        const RealShapeVector u =
            ComparableShape(mode, options_.shape_convention);
        double largest = 0, uu = 0, um = 0;
        for (const auto& [dof, v] : m.shape) {
          largest = std::max(largest, std::abs(v));
        }
        for (const auto& [dof, v] : m.shape) {
          const double ui = u[static_cast<int>(dof)];
          uu += ui * ui;
          um += ui * v / largest;
        }
        // The paper's vectors have a fixed norm (unit state vector), which
        // carries zeta / |lambda|: only their sign is free.
        const double alpha =
            options_.shape_convention == ShapeConvention::kPaper
                ? (um >= 0 ? 1.0 : -1.0) / largest
                : (uu > 0 ? um / uu : 0);
        const double sigma = m.shape_sigma.value_or(options_.default_shape_sigma);
        for (const auto& [dof, v] : m.shape) {
          r[k++] = (alpha * u[static_cast<int>(dof)] - v / largest) / sigma;
        }
        break;
      }
    }
  }
  for (int i = 0; i < num_residuals_; ++i) {
    if (!std::isfinite(r[i])) return false;
  }
  return true;
}

ceres::CostFunction* NewCentralDifferenceCost(const ModalResiduals& residuals) {
  ceres::NumericDiffOptions options;
  options.relative_step_size = 1e-4;
  auto* cost = new ceres::DynamicNumericDiffCostFunction<ModalResiduals, ceres::CENTRAL>(
      &residuals, ceres::DO_NOT_TAKE_OWNERSHIP, options);
  cost->AddParameterBlock(residuals.num_parameters());
  cost->SetNumResiduals(residuals.num_residuals());
  return cost;
}

double ModalResiduals::FrequencySigma(const MeasuredMode& m) const {
  if (options_.frequency_weighting == FrequencyWeighting::kSigma && m.frequency_sigma_hz) {
    return *m.frequency_sigma_hz;
  }
  return options_.relative_sigma * m.frequency_hz;
}

}  // namespace internal
}  // namespace ringid
