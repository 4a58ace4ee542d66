#include "estimation/residuals.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

#include "datasets/pairing.h"
#include "estimation/statistics.h"

namespace ringid {

bool ResidualOptions::IsValid(std::string* why) const {
  if (!(relative_sigma > 0 && std::isfinite(relative_sigma))) {
    *why = "relative_sigma must be positive";
    return false;
  }
  if (!(default_damping_sigma > 0) || !(default_shape_sigma > 0)) {
    *why = "default sigmas must be positive";
    return false;
  }
  return true;
}

namespace internal {

ModalResiduals::ModalResiduals(const ModalModel& model, const Dataset& dataset,
                               const ParameterSetup& setup,
                               const ResidualOptions& options)
    : model_(model), dataset_(dataset), setup_(setup), options_(options), id_(NextId()) {
  // Condition by condition, record by record (a measured mode, a static
  // stiffness), each record's measurements in registry order.
  for (int c = 0; c < static_cast<int>(dataset.conditions.size()); ++c) {
    row_begin_.push_back(static_cast<int>(slots_.size()));
    for (const MeasurementRecords* records : Records()) {
      for (int i = 0; i < records->Items(dataset); ++i) {
        if (records->ConditionOf(dataset, i) != c) continue;
        for (const Measurement* unit : Measurements()) {
          if (&unit->records() != records) continue;
          const int rows = unit->Rows(dataset, i, options_);
          for (int k = 0; k < rows; ++k) slots_.push_back({i, unit, k});
        }
      }
    }
  }
  row_begin_.push_back(static_cast<int>(slots_.size()));
  modal_.assign(dataset.conditions.size(), false);
  for (const MeasuredMode& m : dataset.modes) modal_[m.condition] = true;
  // The parameters a coordinate moves: the free ones and those tied to them.
  for (int i = 0; i < kNumParams; ++i) {
    const auto tie = setup.ties().find(ParamAt(i));
    const Param moved = tie == setup.ties().end() ? ParamAt(i) : tie->second;
    if (std::find(setup.free().begin(), setup.free().end(), moved) != setup.free().end()) {
      derived_.push_back(i);
    }
  }
  for (int i = 0; i < setup.num_shared(); ++i) {
    const Param p = setup.free()[i];
    const auto given = dataset.priors.find(p);
    if (given != dataset.priors.end()) {
      const Prior& prior = given->second;
      if (prior.distribution == PriorDistribution::kNormal) {
        priors_.push_back({i, prior.distribution, prior.center, prior.spread});
      } else {
        priors_.push_back({i, prior.distribution, std::log(prior.center),
                           std::log(prior.spread) / kNormal95});
      }
    }
  }
  for (int k = 0; k < static_cast<int>(priors_.size()); ++k) {
    Slot prior;
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
  // The one rule of datasets/pairing.h: shapes by MAC, then labels, then
  // frequency within the label's plane (PairingWarnings says where it forced one).
  std::vector<int> index;
  std::vector<ModeToPair> measured;
  for (int i = 0; i < static_cast<int>(dataset_.modes.size()); ++i) {
    const MeasuredMode& m = dataset_.modes[i];
    if (m.condition != c) continue;
    index.push_back(i);
    measured.push_back({m.frequency_hz, &m.shape, m.label});
  }
  std::vector<const Mode*> modes;
  for (const Mode& mode : solution.modes) modes.push_back(&mode);
  std::vector<int> local;
  std::vector<PairedBy> by;
  if (!PairModes(measured, modes, options_.shape_convention, &local, &by, why)) {
    *why += " in condition " + dataset_.conditions[c].name;
    return false;
  }
  for (size_t a = 0; a < index.size(); ++a) (*pairs)[index[a]] = local[a];
  return true;
}

namespace {

// A measured mode whose paired model mode is this factor further from it than
// the nearest model mode is not paired with its nearest (a swap, not a
// crossing, where the two are a few per cent apart).
constexpr double kNearerRatio = 1.2;

// "lateral 44.1 Hz, camber 52.0 Hz": the model modes nearest to hz, at most two.
std::string Nearest(const ModalSolution& solution, double hz) {
  std::vector<const Mode*> by;
  for (const Mode& m : solution.modes) by.push_back(&m);
  auto distance = [hz](const Mode* m) { return std::abs(std::log(m->frequency_hz / hz)); };
  std::sort(by.begin(), by.end(),
            [&](const Mode* a, const Mode* b) { return distance(a) < distance(b); });
  std::string out;
  char item[80];
  for (size_t k = 0; k < by.size() && k < 2; ++k) {
    std::snprintf(item, sizeof item, "%s%s %.1f Hz", k ? ", " : "", LabelName(by[k]->label),
                  by[k]->frequency_hz);
    out += item;
  }
  return out;
}

}  // namespace

std::vector<std::string> ModalResiduals::PairingWarnings(const double* x, bool start) const {
  const char* when = start ? "at the start" : "at the best fit";
  std::vector<ModalSolution> solutions;
  std::vector<int> pairs;
  std::string why;
  if (!Pair(x, &solutions, &pairs, &why)) {
    return {std::string(when) + ", the measured modes cannot be paired: " + why};
  }
  std::vector<std::string> out;
  std::set<std::pair<int, int>> coincident;  // (condition, lower model index) said
  char line[512];
  for (size_t i = 0; i < dataset_.modes.size(); ++i) {
    const MeasuredMode& m = dataset_.modes[i];
    const ModalSolution& solution = solutions[m.condition];
    const Mode& paired = solution.modes[pairs[i]];
    const std::string where =
        dataset_.conditions.size() > 1 ? " in condition " + dataset_.conditions[m.condition].name : "";
    const std::string nearest = Nearest(solution, m.frequency_hz);
    double ratio = INFINITY;  // to the nearest model mode, >= 1
    for (const Mode& mode : solution.modes) {
      ratio = std::min(ratio, std::max(mode.frequency_hz / m.frequency_hz,
                                       m.frequency_hz / mode.frequency_hz));
    }
    const double limit = start ? kStartFrequencyRatio : kFitFrequencyRatio;
    if (ratio > limit) {
      std::snprintf(line, sizeof line,
                    "%s%s, measured %s (%.4g Hz) is a factor %.3g from every model mode, more "
                    "than %g (nearest: %s): is it a rigid-ring mode, and its frequency right?",
                    when, where.c_str(), LabelName(m.label), m.frequency_hz, ratio, limit,
                    nearest.c_str());
      out.push_back(line);
    } else if (paired.label != m.label ||
               std::abs(std::log(paired.frequency_hz / m.frequency_hz)) >
                   std::log(kNearerRatio * ratio)) {
      std::snprintf(line, sizeof line,
                    "%s%s, measured %s (%.4g Hz) is paired %s with model %s (%.4g Hz); nearest "
                    "model modes: %s",
                    when, where.c_str(), LabelName(m.label), m.frequency_hz,
                    !m.shape.empty()            ? "by its shape"
                    : paired.label == m.label   ? "by label"
                                                : "as the nearest model mode a shape left free",
                    LabelName(paired.label),
                    paired.frequency_hz, nearest.c_str());
      out.push_back(line);
    }
    // Two model modes at one frequency where the data have two.
    for (int b = 0; b < static_cast<int>(solution.modes.size()); ++b) {
      const Mode& other = solution.modes[b];
      if (b == pairs[i] ||
          std::abs(other.frequency_hz - paired.frequency_hz) >
              kCoincidentRelative * paired.frequency_hz) {
        continue;
      }
      bool data_too = false;  // the other is paired with a measured mode at this frequency
      for (size_t k = 0; k < dataset_.modes.size(); ++k) {
        data_too |= k != i && pairs[k] == b && dataset_.modes[k].condition == m.condition &&
                    std::abs(dataset_.modes[k].frequency_hz - m.frequency_hz) <=
                        kCoincidentRelative * m.frequency_hz;
      }
      if (data_too || !coincident.insert({m.condition, std::min(b, pairs[i])}).second) continue;
      std::snprintf(line, sizeof line,
                    "%s%s, model modes %s and %s are driven to one frequency (%.5g and %.5g "
                    "Hz, within %g %%) while the data put measured %s at %.4g Hz",
                    when, where.c_str(), LabelName(paired.label), LabelName(other.label),
                    paired.frequency_hz, other.frequency_hz, 100 * kCoincidentRelative,
                    LabelName(m.label), m.frequency_hz);
      out.push_back(line);
    }
  }
  return out;
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

bool ModalResiduals::Rows(int c, const Parameters& p, const ModalSolution* solution, double* r,
                          Eigen::Ref<RowMatrix> dr) const {
  std::vector<int> pairs(dataset_.modes.size(), -1);
  std::string why;
  if (solution && (!solution->ok || !PairCondition(c, *solution, &pairs, &why))) return false;
  const ModelAt at{&model_, &p, solution, solution ? &pairs : nullptr};
  const bool derive = dr.size() > 0;
  const int end = row_begin_[c + 1];
  for (int k = row_begin_[c]; k < end;) {
    const Slot& slot = slots_[k];
    const int row = k - row_begin_[c];
    const int n = slot.measurement->Rows(dataset_, slot.item, options_);
    const bool done = derive ? slot.measurement->Evaluate(dataset_, slot.item, at, options_,
                                                          r + row, &derived_, dr.middleRows(row, n))
                             : slot.measurement->Evaluate(dataset_, slot.item, at, options_,
                                                          r + row, nullptr, dr);
    if (!done) return false;
    k += n;
  }
  if (!AllFinite(r, end - row_begin_[c])) return false;
  for (int row = 0; derive && row < dr.rows(); ++row) {
    if (!AllFinite(dr.data() + static_cast<size_t>(row) * dr.outerStride(), dr.cols())) return false;
  }
  return true;
}

ModalSolution ModalResiduals::SolveCondition(int c, const double* shared,
                                             const double* own) const {
  if (!modal_[c]) return ModalSolution{};
  ++evaluations_;
  return model_.Solve(setup_.Decode(shared, own, c), dataset_.conditions[c].speed_m_s);
}

bool ModalResiduals::EvaluateCondition(int c, const double* shared, const double* own,
                                       double* r, const ModalSolution* near) const {
  ++evaluations_;
  const Parameters p = setup_.Decode(shared, own, c);
  RowMatrix none;
  if (!modal_[c]) return Rows(c, p, nullptr, r, none);
  const double speed = dataset_.conditions[c].speed_m_s;
  const ModalSolution solution = near ? model_.SolveFrom(*near, p, speed) : model_.Solve(p, speed);
  return Rows(c, p, &solution, r, none);
}

namespace {

// What a thread last differentiated of each condition of one problem.
struct Kept {
  std::vector<double> at;  // the shared then own coordinates; empty: nothing
  std::vector<double> r, shared, own;  // shared, own empty where not made
  bool defined = false;
};
struct KeptHere {
  uint64_t owner = 0;  // ModalResiduals::id_
  std::vector<Kept> conditions;
};
thread_local KeptHere kept_here;

// Whether `at` holds shared[0, ns) then own[0, no).
bool SamePoint(const std::vector<double>& at, const double* shared, int ns, const double* own,
               int no) {
  return !at.empty() && static_cast<int>(at.size()) == ns + no &&
         std::equal(at.begin(), at.begin() + ns, shared) &&
         std::equal(at.begin() + ns, at.end(), own);
}

}  // namespace

uint64_t ModalResiduals::NextId() {
  static std::atomic<uint64_t> next{1};
  return next++;
}

void ModalResiduals::ForgetKept() const {
  if (kept_here.owner != id_) return;
  for (Kept& kept : kept_here.conditions) kept.at.clear();  // the storage stays
}

bool ModalResiduals::Recall(int c, const double* shared, const double* own, double* r,
                            double* jacobian_shared, double* jacobian_own, bool* defined) const {
  if (kept_here.owner != id_ || c >= static_cast<int>(kept_here.conditions.size())) return false;
  const Kept& kept = kept_here.conditions[c];
  const int ns = setup_.num_shared(), no = setup_.own_begin(c + 1) - setup_.own_begin(c);
  if (!SamePoint(kept.at, shared, ns, own, no)) return false;
  const bool made_all = !kept.defined || ((!jacobian_shared || !kept.shared.empty()) &&
                                          (!jacobian_own || !kept.own.empty()));
  if (!made_all) return false;
  std::copy(kept.r.begin(), kept.r.end(), r);
  *defined = kept.defined;
  if (kept.defined && jacobian_shared) std::copy(kept.shared.begin(), kept.shared.end(), jacobian_shared);
  if (kept.defined && jacobian_own) std::copy(kept.own.begin(), kept.own.end(), jacobian_own);
  return true;
}

bool ModalResiduals::EvaluateConditionJacobian(int c, const double* shared, const double* own,
                                               double* r, double* jacobian_shared,
                                               double* jacobian_own, bool* defined) const {
  if (Recall(c, shared, own, r, jacobian_shared, jacobian_own, defined)) return true;
  const bool made = MakeConditionJacobian(c, shared, own, r, jacobian_shared, jacobian_own, defined);
  if (!made) return false;
  if (kept_here.owner != id_) {
    kept_here.owner = id_;
    for (Kept& kept : kept_here.conditions) kept.at.clear();
  }
  kept_here.conditions.resize(setup_.num_conditions());
  Kept& kept = kept_here.conditions[c];
  const int ns = setup_.num_shared(), no = setup_.own_begin(c + 1) - setup_.own_begin(c);
  const size_t rows = static_cast<size_t>(row_begin_[c + 1] - row_begin_[c]);
  kept.at.assign(shared, shared + ns);
  kept.at.insert(kept.at.end(), own, own + no);
  kept.r.assign(r, r + rows);
  kept.defined = *defined;
  const bool js = *defined && jacobian_shared, jo = *defined && jacobian_own;
  kept.shared.assign(jacobian_shared, jacobian_shared + (js ? rows * ns : 0));
  kept.own.assign(jacobian_own, jacobian_own + (jo ? rows * no : 0));
  return true;
}

bool ModalResiduals::MakeConditionJacobian(int c, const double* shared, const double* own,
                                           double* r, double* jacobian_shared,
                                           double* jacobian_own, bool* defined) const {
  ++evaluations_;
  *defined = false;
  const Parameters p = setup_.Decode(shared, own, c);
  const ModalSolution solution =
      modal_[c] ? model_.Solve(p, dataset_.conditions[c].speed_m_s, true) : ModalSolution{};
  const ModalSolution* modes = modal_[c] ? &solution : nullptr;
  const int rows = row_begin_[c + 1] - row_begin_[c];
  // A column per parameter a coordinate moves (derived_), as Rows fills them.
  thread_local RowMatrix dr;  // reused: an FRF's are megabytes
  dr.setZero(rows, static_cast<int>(derived_.size()));
  if (!solution.derivatives_undefined.empty()) {
    RowMatrix none;
    return Rows(c, p, modes, r, none);
  }
  if (!Rows(c, p, modes, r, dr)) return false;
  *defined = true;
  // Chain rule through the coordinates: coordinate i sets free()[i] and every
  // parameter tied to it, d value / d x = PhysicalStd(i, x, 1).
  // Row by row: dr and J are row-major.
  const auto chain = [&](int begin, int end, const double* x, double* out) {
    if (!out) return;
    const int n = end - begin;
    std::vector<double> scale(n);
    // dr's columns of free()[i], then of the parameters tied to it.
    const auto column = [&](Param q) {
      return static_cast<int>(std::find(derived_.begin(), derived_.end(), static_cast<int>(q)) -
                              derived_.begin());
    };
    std::vector<std::vector<int>> from(n);
    for (int i = begin; i < end; ++i) {
      scale[i - begin] = setup_.PhysicalStd(i, x[i - begin], 1.0);
      from[i - begin].push_back(column(setup_.free()[i]));
      for (const auto& [tied, to] : setup_.ties()) {
        if (to == setup_.free()[i]) from[i - begin].push_back(column(tied));
      }
    }
    for (int row = 0; row < rows; ++row) {
      const double* d = dr.data() + static_cast<size_t>(row) * dr.cols();
      for (int i = 0; i < n; ++i) {
        double v = d[from[i][0]];
        for (size_t t = 1; t < from[i].size(); ++t) v += d[from[i][t]];
        out[static_cast<size_t>(row) * n + i] = v * scale[i];
      }
    }
  };
  chain(0, setup_.num_shared(), shared, jacobian_shared);
  chain(setup_.own_begin(c), setup_.own_begin(c + 1), own, jacobian_own);
  return true;
}

bool ModalResiduals::Evaluate(const double* x, double* r,
                              const std::vector<ModalSolution>* near) const {
  for (int c = 0; c < setup_.num_conditions(); ++c) {
    if (!EvaluateCondition(c, x, x + setup_.own_begin(c), r + row_begin_[c],
                           near ? &(*near)[c] : nullptr)) {
      return false;
    }
  }
  const int first = row_begin_.back();
  for (size_t k = 0; k < priors_.size(); ++k) {
    r[first + k] = priors_[k].Residual(setup_, x[priors_[k].coordinate]);
  }
  return true;
}

void RelativeErrors(const Dataset& dataset, const std::vector<ModalSolution>& solutions,
                    const std::vector<int>& pairs, double* in_plane, double* out_of_plane) {
  double e[2] = {0, 0};
  int n[2] = {0, 0};
  for (size_t i = 0; i < dataset.modes.size(); ++i) {
    const MeasuredMode& m = dataset.modes[i];
    const double model_hz = solutions[m.condition].modes[pairs[i]].frequency_hz;
    const double rel = (m.frequency_hz - model_hz) / m.frequency_hz;
    const int k = LabelPlane(m.label) == Plane::kInPlane ? 0 : 1;
    e[k] += rel * rel;
    ++n[k];
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  *in_plane = n[0] ? e[0] : nan;
  *out_of_plane = n[1] ? e[1] : nan;
}

}  // namespace internal
}  // namespace ringid
