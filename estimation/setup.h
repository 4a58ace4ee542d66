// Free, fixed and tied parameters, and the coordinates the optimisers move:
// log(value) for positive parameters, value / TypicalScale otherwise.
#ifndef RINGID_ESTIMATION_SETUP_H_
#define RINGID_ESTIMATION_SETUP_H_

#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "datasets/dataset.h"
#include "model/parameters.h"
#include "model/rigid_ring_model.h"

namespace ringid {

namespace internal {

class ParameterSetup {
 public:
  // Every parameter the model reads is known (fixed), tied (follows its
  // target) or free. Free ones start at the dataset's initial value.
  // Returns false with a message naming the parameter when one has no value.
  static bool Build(const ModalModel& model, const Dataset& dataset,
                    ParameterSetup* setup, std::string* error);

  int size() const { return static_cast<int>(free_.size()); }
  const std::vector<Param>& free() const { return free_; }
  const std::map<Param, Param>& ties() const { return ties_; }
  bool is_log(int i) const {
    return Info(free_[i]).domain == Domain::kPositive;
  }
  // Coordinate i at x as a parameter value, and a coordinate standard
  // deviation there in the parameter's units (delta method for log).
  double ToPhysical(int i, double x) const;
  double PhysicalStd(int i, double x, double sd) const;
  // The index of the coordinate that sets p, or -1 when p is fixed.
  int CoordinateOf(Param p) const;

  Eigen::VectorXd Encode(const Parameters& p) const;
  Parameters Decode(const double* x) const;
  const Parameters& start() const { return start_; }

 private:
  std::vector<Param> used_;
  std::vector<Param> free_;
  std::map<Param, Param> ties_;
  Parameters start_;
};

}  // namespace internal
}  // namespace ringid

#endif  // RINGID_ESTIMATION_SETUP_H_
