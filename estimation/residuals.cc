#include "estimation/residuals.h"

#include <cmath>

#include <ceres/dynamic_numeric_diff_cost_function.h>

#include "estimation/statistics.h"
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
  // Modes are listed condition by condition (the loader's order).
  for (int c = 0; c < static_cast<int>(dataset.conditions.size()); ++c) {
    row_begin_.push_back(static_cast<int>(slots_.size()));
    for (int i = 0; i < static_cast<int>(dataset.modes.size()); ++i) {
      const MeasuredMode& m = dataset.modes[i];
      if (m.condition != c) continue;
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
  }
  row_begin_.push_back(static_cast<int>(slots_.size()));
  for (int i = 0; i < setup.num_shared(); ++i) {
    const Param p = setup.free()[i];
    const auto given = dataset.priors.find(p);
    const auto option = options_.prior.find(p);
    if (given != dataset.priors.end()) {
      const Prior& prior = given->second;
      if (prior.distribution == PriorDistribution::kNormal) {
        priors_.push_back({i, prior.distribution, prior.center, prior.spread});
      } else {
        priors_.push_back({i, prior.distribution, std::log(prior.center),
                           std::log(prior.spread) / kNormal95});
      }
    } else if (options_.prior_sigma > 0 && option != options_.prior.end() &&
               Info(p).group != Group::kEffect && option->second > 0 && setup.is_log(i)) {
      priors_.push_back({i, PriorDistribution::kLognormal, std::log(option->second),
                         options_.prior_sigma});
    }
  }
  for (int k = 0; k < static_cast<int>(priors_.size()); ++k) {
    Slot prior{-1, Slot::kPrior};
    prior.prior = k;
    slots_.push_back(prior);
  }
  num_residuals_ = static_cast<int>(slots_.size());
}

double ModalResiduals::PriorTerm::Residual(const ParameterSetup& setup, double x) const {
  return distribution == PriorDistribution::kNormal
             ? (setup.ToPhysical(coordinate, x) - center) / scale
             : (x - center) / scale;
}

double ModalResiduals::PriorTerm::Derivative(const ParameterSetup& setup, double x) const {
  if (distribution == PriorDistribution::kLognormal) return 1 / scale;
  // d value / dx: value for a log coordinate, the typical scale otherwise.
  return setup.PhysicalStd(coordinate, x, 1.0) / scale;
}

double ModalResiduals::PriorTerm::CoordinateVariance(const ParameterSetup& setup, double x) const {
  const double d = Derivative(setup, x);
  return 1 / (d * d);
}

bool ModalResiduals::PairCondition(int c, const ModalSolution& solution,
                                   std::vector<int>* pairs, std::string* why) const {
  const auto& measured = dataset_.modes;
  const auto& modes = solution.modes;
  // Measured shapes decide their pairing by MAC (docs/conventions.md §2) ...
  std::vector<int> shaped;
  for (int i = 0; i < static_cast<int>(measured.size()); ++i) {
    if (measured[i].condition == c && !measured[i].shape.empty()) shaped.push_back(i);
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
    if (measured[i].condition != c || (*pairs)[i] >= 0) continue;
    for (int b = 0; b < static_cast<int>(modes.size()); ++b) {
      if (modes[b].label == measured[i].label) (*pairs)[i] = b;
    }
    if ((*pairs)[i] < 0) {
      *why = std::string("the model has no oscillating ") + LabelName(measured[i].label) +
             " mode (its roots are real) in condition " + dataset_.conditions[c].name;
      return false;
    }
  }
  return true;
}

bool ModalResiduals::Pair(const double* x, std::vector<ModalSolution>* solutions,
                          std::vector<int>* pairs, std::string* why) const {
  solutions->clear();
  pairs->assign(dataset_.modes.size(), -1);
  for (int c = 0; c < setup_.num_conditions(); ++c) {
    solutions->push_back(model_.Solve(setup_.Decode(x, c), dataset_.conditions[c].speed_m_s));
    if (!solutions->back().ok) {
      *why = solutions->back().error;
      return false;
    }
    if (!PairCondition(c, solutions->back(), pairs, why)) return false;
  }
  return true;
}

bool ModalResiduals::EvaluateCondition(int c, const double* shared, const double* own,
                                       double* r) const {
  ++evaluations_;
  const ModalSolution solution =
      model_.Solve(setup_.Decode(shared, own, c), dataset_.conditions[c].speed_m_s);
  std::vector<int> pairs(dataset_.modes.size(), -1);
  std::string why;
  if (!solution.ok || !PairCondition(c, solution, &pairs, &why)) return false;
  const int end = row_begin_[c + 1];
  for (int k = row_begin_[c]; k < end;) {
    const Slot& slot = slots_[k];
    const MeasuredMode& m = dataset_.modes[slot.mode];
    const Mode& mode = solution.modes[pairs[slot.mode]];
    double* out = r + (k - row_begin_[c]);
    switch (slot.kind) {
      case Slot::kFrequency:
        *out = (mode.frequency_hz - m.frequency_hz) / FrequencySigma(m);
        ++k;
        break;
      case Slot::kDamping:
        *out = (mode.damping_ratio - *m.damping_ratio) /
               m.damping_sigma.value_or(options_.default_damping_sigma);
        ++k;
        break;
      case Slot::kPrior:
        ++k;
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
          r[k++ - row_begin_[c]] = (alpha * u[static_cast<int>(dof)] - v / largest) / sigma;
        }
        break;
      }
    }
  }
  for (int k = row_begin_[c]; k < end; ++k) {
    if (!std::isfinite(r[k - row_begin_[c]])) return false;
  }
  return true;
}

bool ModalResiduals::Evaluate(const double* x, double* r) const {
  for (int c = 0; c < setup_.num_conditions(); ++c) {
    if (!EvaluateCondition(c, x, x + setup_.own_begin(c), r + row_begin_[c])) return false;
  }
  const int first = row_begin_.back();
  for (size_t k = 0; k < priors_.size(); ++k) {
    r[first + k] = priors_[k].Residual(setup_, x[priors_[k].coordinate]);
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

namespace ringid {
namespace internal {
namespace {

// One condition's rows as a function of the shared block and its own block;
// either may be absent (size 0).
struct ConditionRows {
  const ModalResiduals* residuals;
  int condition;
  bool shared, own;
  bool operator()(double const* const* x, double* r) const {
    const double* s = shared ? x[0] : nullptr;
    const double* o = own ? x[shared ? 1 : 0] : nullptr;
    return residuals->EvaluateCondition(condition, s, o, r);
  }
};

// The priors, with their exact derivatives, on the shared block.
class PriorCost final : public ceres::CostFunction {
 public:
  PriorCost(const ModalResiduals& residuals, const ParameterSetup& setup)
      : residuals_(residuals), setup_(setup) {
    set_num_residuals(static_cast<int>(residuals.priors().size()));
    mutable_parameter_block_sizes()->push_back(setup.num_shared());
  }
  bool Evaluate(double const* const* x, double* r, double** jacobians) const override {
    const auto& priors = residuals_.priors();
    const int n = setup_.num_shared();
    for (size_t k = 0; k < priors.size(); ++k) {
      const double xi = x[0][priors[k].coordinate];
      r[k] = priors[k].Residual(setup_, xi);
      if (jacobians && jacobians[0]) {
        std::fill(jacobians[0] + k * n, jacobians[0] + (k + 1) * n, 0.0);
        jacobians[0][k * n + priors[k].coordinate] = priors[k].Derivative(setup_, xi);
      }
    }
    return true;
  }

 private:
  const ModalResiduals& residuals_;
  const ParameterSetup& setup_;
};

}  // namespace

std::vector<std::pair<int, int>> AddResidualBlocks(const ModalResiduals& residuals,
                                                   Eigen::VectorXd* x, ceres::Problem* problem) {
  const ParameterSetup& setup = residuals.setup();
  std::vector<std::pair<int, int>> blocks;
  const int ns = setup.num_shared();
  bool shared_used = !residuals.priors().empty();
  ceres::NumericDiffOptions options;
  options.relative_step_size = 1e-4;  // as NewCentralDifferenceCost
  for (int c = 0; c < setup.num_conditions(); ++c) {
    const int begin = setup.own_begin(c), size = setup.own_begin(c + 1) - begin;
    const int rows = residuals.row_begin(c + 1) - residuals.row_begin(c);
    if (rows == 0 || (ns == 0 && size == 0)) continue;
    if (size > 0) blocks.emplace_back(begin, size);
    shared_used = shared_used || ns > 0;
    auto* cost = new ceres::DynamicNumericDiffCostFunction<ConditionRows, ceres::CENTRAL>(
        new ConditionRows{&residuals, c, ns > 0, size > 0}, ceres::TAKE_OWNERSHIP, options);
    std::vector<double*> parameters;
    if (ns > 0) {
      cost->AddParameterBlock(ns);
      parameters.push_back(x->data());
    }
    if (size > 0) {
      cost->AddParameterBlock(size);
      parameters.push_back(x->data() + begin);
    }
    cost->SetNumResiduals(rows);
    problem->AddResidualBlock(cost, nullptr, parameters);
  }
  if (!residuals.priors().empty()) {
    problem->AddResidualBlock(new PriorCost(residuals, setup), nullptr, x->data());
  }
  if (ns > 0 && shared_used) blocks.insert(blocks.begin(), {0, ns});
  return blocks;
}

}  // namespace internal
}  // namespace ringid
