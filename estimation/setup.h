// Free, fixed and tied parameters, and the coordinates the optimisers move:
// log(value) for positive parameters, value / TypicalScale otherwise.
// Shared coordinates come first, then each condition's own (docs/conventions.md §7).
#ifndef RINGID_ESTIMATION_SETUP_H_
#define RINGID_ESTIMATION_SETUP_H_

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "datasets/dataset.h"
#include "estimation/types.h"
#include "model/parameters.h"
#include "model/rigid_ring_model.h"

namespace ringid {

namespace internal {

class ParameterSetup {
 public:
  // Every parameter the model reads is known (fixed), tied (follows its
  // target) or free, in each condition for a per-condition parameter. Free
  // ones start at the dataset's initial value. Returns false with a message
  // naming the parameter when one has no value.
  static bool Build(const ModalModel& model, const Dataset& dataset,
                    ParameterSetup* setup, std::string* error);

  int size() const { return static_cast<int>(free_.size()); }
  // The parameter each coordinate sets (a per-condition one once per condition).
  const std::vector<Param>& free() const { return free_; }
  // The condition a coordinate belongs to; -1 when shared.
  int condition_of(int i) const { return condition_[i]; }
  ParameterKey key(int i) const;
  std::string name(int i) const { return key(i).Text(); }
  int num_conditions() const { return static_cast<int>(conditions_.size()); }
  // Coordinates [0, num_shared()) are shared; condition c owns
  // [own_begin(c), own_begin(c + 1)).
  int num_shared() const { return own_begin_[0]; }
  int own_begin(int c) const { return own_begin_[c]; }
  const std::map<Param, Param>& ties() const { return ties_; }
  bool is_log(int i) const {
    return Info(free_[i]).domain == Domain::kPositive;
  }
  // Coordinate i at x as a parameter value, and a coordinate standard
  // deviation there in the parameter's units (delta method for log).
  double ToPhysical(int i, double x) const;
  double ToCoordinate(int i, double value) const;
  double PhysicalStd(int i, double x, double sd) const;
  // The Wald 95 % interval of coordinate i at x, sd its coordinate standard
  // deviation, in the parameter's units: symmetric in the coordinate it is
  // fitted in (the log of a positive parameter, else the value itself).
  std::pair<double, double> Interval95(int i, double x, double sd) const;
  // The index of the coordinate that sets p in `condition`, or -1 when p is
  // fixed there.
  int CoordinateOf(Param p, int condition = 0) const;

  // The dataset's starting point in coordinates.
  Eigen::VectorXd StartCoordinates() const;
  // p in coordinates, a per-condition coordinate taking p's one value.
  Eigen::VectorXd Encode(const Parameters& p) const;
  // The parameters of `condition` at x; `own` points to that condition's
  // coordinates (x + own_begin(condition) when x is whole).
  Parameters Decode(const double* shared, const double* own, int condition) const;
  Parameters Decode(const double* x, int condition = 0) const {
    return Decode(x, x + own_begin_[condition], condition);
  }
  const Parameters& start(int condition = 0) const { return start_[condition]; }

 private:
  std::vector<Param> used_;
  std::vector<Param> free_;
  std::vector<int> condition_;
  std::vector<std::string> conditions_;
  std::vector<int> own_begin_;  // num_conditions + 1 entries
  std::map<Param, Param> ties_;
  std::vector<Parameters> start_;  // per condition
};

}  // namespace internal
}  // namespace ringid

#endif  // RINGID_ESTIMATION_SETUP_H_
