#include "estimation/setup.h"

#include <algorithm>
#include <cmath>

#include "estimation/statistics.h"

namespace ringid {

std::string ParameterKey::Text() const {
  return condition.empty() ? std::string(ParamName(param))
                           : std::string(ParamName(param)) + "@" + condition;
}

bool ParameterKey::Parse(const std::string& text, ParameterKey* key) {
  const size_t at = text.find('@');
  const auto p = ParseParam(text.substr(0, at));
  if (!p) return false;
  key->param = *p;
  key->condition = at == std::string::npos ? "" : text.substr(at + 1);
  return at == std::string::npos || !key->condition.empty();
}

namespace internal {

bool ParameterSetup::Build(const ModalModel& model, const Dataset& dataset,
                           ParameterSetup* s, std::string* error) {
  *s = ParameterSetup{};
  s->used_ = model.parameters();
  auto used = [&](Param p) {
    return std::find(s->used_.begin(), s->used_.end(), p) != s->used_.end();
  };
  const int nc = static_cast<int>(dataset.conditions.size());
  for (const Condition& c : dataset.conditions) {
    if (!c.obstacle) continue;
    *error = "condition '" + c.name + "': ringid simulates obstacle tests but does not fit " +
             "them: leave its obstacle block out of the dataset to fit the rest";
    return false;
  }
  for (int c = 0; c < nc; ++c) {
    s->conditions_.push_back(nc > 1 || dataset.NamesConditions() ? dataset.conditions[c].name : "");
    s->start_.push_back(InitialParameters(dataset, c));
  }
  for (const auto& [from, to] : dataset.ties) {
    if (used(from)) s->ties_[from] = to;
  }
  auto add = [&](Param p, int c) {
    // Effect parameters start at their baseline value 0 unless seeded.
    if (!s->start_[std::max(c, 0)].IsSet(p)) {
      *error = std::string("free parameter ") + ParamName(p) +
               (c >= 0 ? "@" + dataset.conditions[c].name : std::string()) +
               " has no value: give it in 'initial' or 'known'";
      return false;
    }
    s->free_.push_back(p);
    s->condition_.push_back(c);
    return true;
  };
  for (Param p : s->used_) {
    if (dataset.known.count(p) || s->ties_.count(p) || dataset.IsPerCondition(p)) continue;
    if (!add(p, -1)) return false;
  }
  for (int c = 0; c < nc; ++c) {
    s->own_begin_.push_back(s->size());
    for (Param p : s->used_) {
      if (!dataset.IsPerCondition(p) || dataset.conditions[c].known.count(p)) continue;
      if (!add(p, c)) return false;
    }
  }
  s->own_begin_.push_back(s->size());
  for (const auto& [from, to] : s->ties_) {
    for (Parameters& start : s->start_) {
      if (!start.IsSet(to)) {
        *error = std::string("ties.") + ParamName(from) + ": target " +
                 ParamName(to) + " has no value";
        return false;
      }
      start[from] = start[to];
    }
  }
  return true;
}

ParameterKey ParameterSetup::key(int i) const {
  return {free_[i], condition_[i] < 0 ? "" : conditions_[condition_[i]]};
}

double ParameterSetup::ToPhysical(int i, double x) const {
  return is_log(i) ? std::exp(x) : x * TypicalScale(free_[i]);
}

double ParameterSetup::ToCoordinate(int i, double value) const {
  return is_log(i) ? std::log(value) : value / TypicalScale(free_[i]);
}

double ParameterSetup::PhysicalStd(int i, double x, double sd) const {
  return is_log(i) ? std::exp(x) * sd : sd * TypicalScale(free_[i]);
}

std::pair<double, double> ParameterSetup::Interval95(int i, double x, double sd) const {
  if (is_log(i)) return {std::exp(x - kNormal95 * sd), std::exp(x + kNormal95 * sd)};
  const double v = ToPhysical(i, x), half = kNormal95 * PhysicalStd(i, x, sd);
  return {v - half, v + half};
}

int ParameterSetup::CoordinateOf(Param p, int condition) const {
  const auto tie = ties_.find(p);
  if (tie != ties_.end()) p = tie->second;
  for (int i = 0; i < size(); ++i) {
    if (free_[i] == p && (condition_[i] < 0 || condition_[i] == condition)) return i;
  }
  return -1;
}

Eigen::VectorXd ParameterSetup::StartCoordinates() const {
  Eigen::VectorXd x(size());
  for (int i = 0; i < size(); ++i) {
    x[i] = ToCoordinate(i, start_[std::max(condition_[i], 0)][free_[i]]);
  }
  return x;
}

Eigen::VectorXd ParameterSetup::Encode(const Parameters& p) const {
  Eigen::VectorXd x(size());
  for (int i = 0; i < size(); ++i) x[i] = ToCoordinate(i, p[free_[i]]);
  return x;
}

Parameters ParameterSetup::Decode(const double* shared, const double* own,
                                  int condition) const {
  Parameters p = start_[condition];
  for (int i = 0; i < num_shared(); ++i) p[free_[i]] = ToPhysical(i, shared[i]);
  for (int i = own_begin_[condition]; i < own_begin_[condition + 1]; ++i) {
    p[free_[i]] = ToPhysical(i, own[i - own_begin_[condition]]);
  }
  for (const auto& [from, to] : ties_) p[from] = p[to];
  return p;
}

}  // namespace internal
}  // namespace ringid
