// The residuals of ModalResiduals as Ceres cost functions: per condition
// (numeric or exact Jacobian), the priors with exact derivatives, and all
// rows as one block; central differences keep the labels of the point they
// perturb, and are made once per point.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include <ceres/cost_function.h>
#include <ceres/dynamic_numeric_diff_cost_function.h>

#include "estimation/residuals.h"

namespace ringid {
namespace internal {
namespace {

constexpr double kRelativeStep = 1e-4;

// One condition's rows as a function of the shared block and its own block;
// either may be absent (size 0).
struct ConditionRows {
  const ModalResiduals* residuals;
  int condition;
  bool shared, own;
  const ModalSolution* near;
  bool operator()(double const* const* x, double* r) const {
    const double* s = shared ? x[0] : nullptr;
    const double* o = own ? x[shared ? 1 : 0] : nullptr;
    return residuals->EvaluateCondition(condition, s, o, r, near);
  }
};

// Every row, labels carried from `near` (one solution per condition).
struct AllRows {
  const ModalResiduals* residuals;
  const std::vector<ModalSolution>* near;
  bool operator()(double const* const* x, double* r) const {
    return residuals->Evaluate(x[0], r, near);
  }
};

// Central differences with a relative step of 1e-4 whose perturbed points
// keep the labels of the point they perturb (ModalModel::SolveFrom): a step
// across a relabelling of nearly degenerate modes is no derivative, and
// carrying spares each perturbed point a continuation in speed. `Rows` is
// ConditionRows or AllRows; `Solve` gives its `near` at x. Ceres'
// DynamicNumericDiffCostFunction<CENTRAL> makes the differences.
template <class Rows, class Solve>
bool CarriedDifferences(const ceres::CostFunction& cost, Rows rows, const Solve& solve,
                        double const* const* x, double* r, double** jacobians) {
  const auto near = solve(x);
  rows.near = &near;
  ceres::NumericDiffOptions options;
  options.relative_step_size = kRelativeStep;
  ceres::DynamicNumericDiffCostFunction<Rows, ceres::CENTRAL> numeric(
      &rows, ceres::DO_NOT_TAKE_OWNERSHIP, options);
  for (int size : cost.parameter_block_sizes()) numeric.AddParameterBlock(size);
  numeric.SetNumResiduals(cost.num_residuals());
  return numeric.Evaluate(x, r, jacobians);
}

// The point a cost function last differentiated, its rows and Jacobian
// (each block's, row-major). Ceres' trust region asks for them twice at a
// point where the problem has bounds (its projected line search evaluates
// the candidate's gradient, then the accepted step its Jacobian) and for the
// rows in between: the differences are made once.
class LastJacobian {
 public:
  // Copies them where x is that point and every block asked for was made.
  bool Recall(const ceres::CostFunction& cost, double const* const* x, double* r,
              double** jacobians) const {
    std::lock_guard<std::mutex> lock(mutex_);
    if (x_.empty()) return false;
    const std::vector<int32_t>& sizes = cost.parameter_block_sizes();
    for (size_t k = 0, at = 0; k < sizes.size(); at += sizes[k++]) {
      if (!std::equal(x[k], x[k] + sizes[k], x_.begin() + at)) return false;
      if (jacobians && jacobians[k] && jacobians_[k].empty()) return false;
    }
    std::copy(r_.begin(), r_.end(), r);
    for (size_t k = 0; jacobians && k < sizes.size(); ++k) {
      if (jacobians[k]) std::copy(jacobians_[k].begin(), jacobians_[k].end(), jacobians[k]);
    }
    return true;
  }
  // Differentiates at x by `differentiate` (r and the blocks asked for, as
  // CostFunction::Evaluate) and keeps the result.
  template <class Differentiate>
  bool Make(const ceres::CostFunction& cost, double const* const* x, double* r, double** jacobians,
            const Differentiate& differentiate) const {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::vector<int32_t>& sizes = cost.parameter_block_sizes();
    x_.clear();
    r_.resize(cost.num_residuals());
    jacobians_.resize(sizes.size());
    std::vector<double*> made;
    for (size_t k = 0; k < sizes.size(); ++k) {
      jacobians_[k].resize(jacobians[k] ? static_cast<size_t>(cost.num_residuals()) * sizes[k] : 0);
      made.push_back(jacobians[k] ? jacobians_[k].data() : nullptr);
    }
    if (!differentiate(r_.data(), made.data())) return false;
    for (size_t k = 0; k < sizes.size(); ++k) {
      x_.insert(x_.end(), x[k], x[k] + sizes[k]);
      if (jacobians[k]) std::copy(jacobians_[k].begin(), jacobians_[k].end(), jacobians[k]);
    }
    std::copy(r_.begin(), r_.end(), r);
    return true;
  }

 private:
  mutable std::mutex mutex_;
  mutable std::vector<double> x_, r_;  // x_ empty: nothing kept
  mutable std::vector<std::vector<double>> jacobians_;  // empty: not made
};

// One condition's rows, differentiated by CarriedDifferences.
class NumericConditionCost final : public ceres::CostFunction {
 public:
  NumericConditionCost(const ModalResiduals& residuals, int condition, int num_shared,
                       int num_own)
      : rows_{&residuals, condition, num_shared > 0, num_own > 0, nullptr} {
    for (int size : {num_shared, num_own}) {
      if (size > 0) mutable_parameter_block_sizes()->push_back(size);
    }
    set_num_residuals(residuals.row_begin(condition + 1) - residuals.row_begin(condition));
  }
  bool Evaluate(double const* const* x, double* r, double** jacobians) const override {
    if (last_.Recall(*this, x, r, jacobians)) return true;
    if (!jacobians) return rows_(x, r);
    const auto solve = [&](double const* const* at) {
      return rows_.residuals->SolveCondition(rows_.condition, rows_.shared ? at[0] : nullptr,
                                             rows_.own ? at[rows_.shared ? 1 : 0] : nullptr);
    };
    return last_.Make(*this, x, r, jacobians, [&](double* rows, double** made) {
      return CarriedDifferences(*this, rows_, solve, x, rows, made);
    });
  }

 private:
  ConditionRows rows_;
  LastJacobian last_;
};

// Every row (one block of all coordinates), differentiated by CarriedDifferences.
class NumericResidualCost final : public ceres::CostFunction {
 public:
  explicit NumericResidualCost(const ModalResiduals& residuals) : rows_{&residuals, nullptr} {
    mutable_parameter_block_sizes()->push_back(residuals.num_parameters());
    set_num_residuals(residuals.num_residuals());
  }
  bool Evaluate(double const* const* x, double* r, double** jacobians) const override {
    if (!jacobians) return rows_(x, r);
    const ModalResiduals& residuals = *rows_.residuals;
    const auto solve = [&](double const* const* at) {
      std::vector<ModalSolution> near;
      for (int c = 0; c < residuals.setup().num_conditions(); ++c) {
        near.push_back(residuals.SolveCondition(c, at[0], at[0] + residuals.setup().own_begin(c)));
      }
      return near;
    };
    return CarriedDifferences(*this, rows_, solve, x, r, jacobians);
  }

 private:
  AllRows rows_;
};

// One condition's rows with the exact Jacobian; CarriedDifferences where the
// derivatives do not exist.
class AnalyticConditionCost final : public ceres::CostFunction {
 public:
  AnalyticConditionCost(const ModalResiduals& residuals, int condition, int num_shared,
                        int num_own)
      : residuals_(residuals), condition_(condition), shared_(num_shared > 0),
        own_(num_own > 0), numeric_(residuals, condition, num_shared, num_own) {
    *mutable_parameter_block_sizes() = numeric_.parameter_block_sizes();
    set_num_residuals(numeric_.num_residuals());
  }
  // The residuals keep the last point (ModalResiduals::EvaluateConditionJacobian).
  bool Evaluate(double const* const* x, double* r, double** jacobians) const override {
    const double* s = shared_ ? x[0] : nullptr;
    const double* o = own_ ? x[shared_ ? 1 : 0] : nullptr;
    if (!jacobians) {
      return residuals_.KeptRows(condition_, s, o, r) ||
             residuals_.EvaluateCondition(condition_, s, o, r);
    }
    double* js = shared_ ? jacobians[0] : nullptr;
    double* jo = own_ ? jacobians[shared_ ? 1 : 0] : nullptr;
    bool defined = false;
    if (!residuals_.EvaluateConditionJacobian(condition_, s, o, r, js, jo, &defined)) return false;
    return defined || numeric_.Evaluate(x, r, jacobians);
  }

 private:
  const ModalResiduals& residuals_;
  int condition_;
  bool shared_, own_;
  NumericConditionCost numeric_;
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

ceres::CostFunction* NewResidualCost(const ModalResiduals& residuals) {
  auto* numeric = new NumericResidualCost(residuals);
  const ParameterSetup& setup = residuals.setup();
  bool any_exact = false;
  for (int c = 0; c < setup.num_conditions(); ++c) any_exact |= residuals.ExactJacobian(c);
  if (!any_exact) return numeric;

  // Every condition's rows placed in x's columns (exact, or differenced on
  // their own where ExactJacobian says so), then the priors.
  class Analytic final : public ceres::CostFunction {
   public:
    Analytic(const ModalResiduals& residuals, ceres::CostFunction* numeric)
        : residuals_(residuals), numeric_(numeric) {
      set_num_residuals(residuals.num_residuals());
      mutable_parameter_block_sizes()->push_back(residuals.num_parameters());
      const ParameterSetup& setup = residuals.setup();
      for (int c = 0; c < setup.num_conditions(); ++c) {
        differenced_.emplace_back(
            residuals.ExactJacobian(c)
                ? nullptr
                : new NumericConditionCost(residuals, c, setup.num_shared(),
                                           setup.own_begin(c + 1) - setup.own_begin(c)));
      }
    }
    bool Evaluate(double const* const* x, double* r, double** jacobians) const override {
      if (!jacobians || !jacobians[0]) return residuals_.Evaluate(x[0], r);
      const ParameterSetup& setup = residuals_.setup();
      const int m = num_residuals(), n = setup.size(), ns = setup.num_shared();
      Eigen::Map<RowMatrix> J(jacobians[0], m, n);
      J.setZero();
      for (int c = 0; c < setup.num_conditions(); ++c) {
        const int row = residuals_.row_begin(c), rows = residuals_.row_begin(c + 1) - row;
        const int own = setup.own_begin(c), size = setup.own_begin(c + 1) - own;
        // Without own coordinates the shared block is whole rows of J.
        const bool direct = size == 0 && ns == n;
        RowMatrix Js(direct ? 0 : rows, ns), Jo(rows, size);
        double* js = direct ? &J(row, 0) : Js.data();
        double* jo = size ? Jo.data() : nullptr;
        if (const NumericConditionCost* cost = differenced_[c].get()) {
          std::vector<const double*> blocks;
          std::vector<double*> made;
          if (ns > 0) blocks.push_back(x[0]), made.push_back(js);
          if (size > 0) blocks.push_back(x[0] + own), made.push_back(jo);
          const bool evaluated =
              blocks.empty() ? residuals_.EvaluateCondition(c, nullptr, nullptr, r + row)
                             : cost->Evaluate(blocks.data(), r + row, made.data());
          if (!evaluated) return false;
        } else {
          bool defined = false;
          if (!residuals_.EvaluateConditionJacobian(c, x[0], x[0] + own, r + row, js, jo,
                                                    &defined)) {
            return false;
          }
          if (!defined) return numeric_->Evaluate(x, r, jacobians);
        }
        if (!direct) J.block(row, 0, rows, ns) = Js;
        J.block(row, own, rows, size) = Jo;
      }
      const auto& priors = residuals_.priors();
      for (size_t k = 0; k < priors.size(); ++k) {
        const int row = residuals_.row_begin(setup.num_conditions()) + static_cast<int>(k);
        const double xi = x[0][priors[k].coordinate];
        r[row] = priors[k].Residual(setup, xi);
        J(row, priors[k].coordinate) = priors[k].Derivative(setup, xi);
      }
      return true;
    }

   private:
    using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    const ModalResiduals& residuals_;
    std::unique_ptr<ceres::CostFunction> numeric_;
    std::vector<std::unique_ptr<NumericConditionCost>> differenced_;  // null: exact
  };
  return new Analytic(residuals, numeric);
}

std::vector<std::pair<int, int>> AddResidualBlocks(const ModalResiduals& residuals,
                                                   Eigen::VectorXd* x, ceres::Problem* problem) {
  const ParameterSetup& setup = residuals.setup();
  std::vector<std::pair<int, int>> blocks;
  const int ns = setup.num_shared();
  bool shared_used = !residuals.priors().empty();
  for (int c = 0; c < setup.num_conditions(); ++c) {
    const int begin = setup.own_begin(c), size = setup.own_begin(c + 1) - begin;
    const int rows = residuals.row_begin(c + 1) - residuals.row_begin(c);
    if (rows == 0 || (ns == 0 && size == 0)) continue;
    if (size > 0) blocks.emplace_back(begin, size);
    shared_used = shared_used || ns > 0;
    std::vector<double*> parameters;
    if (ns > 0) parameters.push_back(x->data());
    if (size > 0) parameters.push_back(x->data() + begin);
    if (residuals.ExactJacobian(c)) {
      problem->AddResidualBlock(new AnalyticConditionCost(residuals, c, ns, size), nullptr,
                                parameters);
      continue;
    }
    auto* cost = new NumericConditionCost(residuals, c, ns, size);
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
