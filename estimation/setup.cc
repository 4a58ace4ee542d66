#include "estimation/setup.h"

#include <algorithm>
#include <cmath>

namespace ringid {
namespace internal {

bool ParameterSetup::Build(const ModalModel& model, const Dataset& dataset,
                           ParameterSetup* s, std::string* error) {
  *s = ParameterSetup{};
  s->used_ = model.parameters();
  auto used = [&](Param p) {
    return std::find(s->used_.begin(), s->used_.end(), p) != s->used_.end();
  };
  for (const auto& [p, v] : dataset.known) s->start_[p] = v;
  for (const auto& [p, v] : dataset.initial) s->start_[p] = v;
  for (const auto& [from, to] : dataset.ties) {
    if (used(from)) s->ties_[from] = to;
  }
  for (Param p : s->used_) {
    if (dataset.known.count(p) || s->ties_.count(p)) continue;
    // Effect parameters start at their baseline value 0 unless seeded.
    if (!s->start_.IsSet(p)) {
      *error = std::string("free parameter ") + ParamName(p) +
               " has no value: give it in 'initial' or 'known'";
      return false;
    }
    s->free_.push_back(p);
  }
  for (const auto& [from, to] : s->ties_) {
    if (!s->start_.IsSet(to)) {
      *error = std::string("ties.") + ParamName(from) + ": target " +
               ParamName(to) + " has no value";
      return false;
    }
    s->start_[from] = s->start_[to];
  }
  return true;
}

double ParameterSetup::ToPhysical(int i, double x) const {
  return is_log(i) ? std::exp(x) : x * TypicalScale(free_[i]);
}

double ParameterSetup::PhysicalStd(int i, double x, double sd) const {
  return is_log(i) ? std::exp(x) * sd : sd * TypicalScale(free_[i]);
}

int ParameterSetup::CoordinateOf(Param p) const {
  const auto tie = ties_.find(p);
  if (tie != ties_.end()) p = tie->second;
  const auto it = std::find(free_.begin(), free_.end(), p);
  return it == free_.end() ? -1 : static_cast<int>(it - free_.begin());
}

Eigen::VectorXd ParameterSetup::Encode(const Parameters& p) const {
  Eigen::VectorXd x(size());
  for (int i = 0; i < size(); ++i) {
    x[i] = is_log(i) ? std::log(p[free_[i]]) : p[free_[i]] / TypicalScale(free_[i]);
  }
  return x;
}

Parameters ParameterSetup::Decode(const double* x) const {
  Parameters p = start_;
  for (int i = 0; i < size(); ++i) {
    p[free_[i]] = is_log(i) ? std::exp(x[i]) : x[i] * TypicalScale(free_[i]);
  }
  for (const auto& [from, to] : ties_) p[from] = p[to];
  return p;
}

}  // namespace internal
}  // namespace ringid
