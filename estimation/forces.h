// The lug forces a rolling tire produces at the contact, estimated from what
// the held axle carries (contract §8, docs/forces.md §3): per condition and
// lug order, the weighted least-squares estimate of the forces the measured
// channels determine, with standard errors from the measurement and with the
// parameters' uncertainty added.
#ifndef RINGID_ESTIMATION_FORCES_H_
#define RINGID_ESTIMATION_FORCES_H_

#include <chrono>
#include <cmath>
#include <complex>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "datasets/response_dataset.h"
#include "estimation/identify.h"
#include "estimation/status.h"
#include "model/archive.h"
#include "model/forced_response.h"
#include "model/rigid_ring_model.h"

namespace ringid {

struct ForcesOptions {
  // A set of forces is determined where the condition number (2-norm) of
  // its weighted response matrix stays below this; a force that would raise
  // it beyond is said to be undetermined, with the number.
  double max_condition_number = 1e6;
  // The parameters' uncertainty is carried by central differences of a
  // hundredth of each coordinate's standard deviation.
  double step_in_std = 1e-2;
  bool IsValid(std::string* why) const;
};

// The parameters the forces are estimated with: the values in each
// condition and, where known, a Gaussian over the coordinates of a fit (the
// log of a positive parameter, the value of another).
struct ForceParameters {
  Parameters shared;
  std::map<std::string, Parameters> by_condition;  // a fit's conditions, by name
  struct Coordinate {
    ParameterKey key;
    std::vector<Param> tied;  // parameters that take this one's value
  };
  std::vector<Coordinate> coordinates;
  Eigen::MatrixXd covariance;  // over coordinates; empty: the values are exact
  std::string source;          // "identify report (covariance of N coordinates)" or "parameter set"

  // Values and covariance of an identification (its per-condition values by
  // condition name); the covariance only where it was computed.
  static ForceParameters From(const IdentifyResult& fit);
  // The values in the response condition `c`: the fit's condition of that
  // name where there is one, then c's known values.
  Parameters In(const ResponseCondition& c) const;
};

struct ForceEstimate {
  std::complex<double> value;
  double std_measurement = 0;  // of re and of im each, from the measurement alone
  double std_total = 0;        // with the parameters' uncertainty added (RMS of re and im)

  template <class Archive>
  void Serialize(Archive* a) {
    double re = value.real(), im = value.imag();
    a->Visit("re", &re);
    a->Visit("im", &im);
    value = {re, im};
    a->Derived("abs", std::abs(value));
    a->Derived("phase_deg", std::arg(value) * 180 / M_PI);
    a->Visit("std_measurement", &std_measurement);
    a->Visit("std_total", &std_total);
  }
};

// A force the measured channels do not determine, and why.
struct UndeterminedForce {
  std::string why;
  // Where it was left out for the conditioning: the condition number of the
  // kept forces' weighted response matrix with it (infinite, null in JSON,
  // where the channels are fewer than those forces).
  std::optional<double> condition_number_with_it;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("why", &why);
    a->VisitIfSet("condition_number_with_it", &condition_number_with_it);
  }
};

struct OrderForces {
  int order = 1;
  double frequency_hz = 0;
  // Above the condition's model_valid_below_hz: estimated with a model that
  // does not describe the tire there (docs/forces.md §3).
  bool above_model_range = false;
  std::vector<AxleChannel> channels;          // measured at this order
  std::map<LugForce, ForceEstimate> forces;   // those the channels determine
  std::map<LugForce, UndeterminedForce> undetermined;  // the others
  double condition_number = 0;  // of the weighted response matrix of `forces`
  // Where the channels over-determine the forces: chi-square of the
  // weighted residual on 2 (channels - forces) degrees of freedom.
  std::optional<double> chi_square;
  int degrees_of_freedom = 0;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("order", &order);
    a->Visit("frequency_hz", &frequency_hz);
    a->Visit("above_model_range", &above_model_range);
    a->Visit("channels", &channels);
    a->Visit("forces", &forces);
    a->Visit("undetermined", &undetermined);
    a->Visit("condition_number", &condition_number);
    a->Visit("chi_square", &chi_square);
    a->Visit("degrees_of_freedom", &degrees_of_freedom);
  }
};

struct ConditionForces {
  std::string name;
  double speed_m_s = 0;
  double f_lug_hz = 0;
  bool f_lug_measured = false;  // given by the dataset (order tracking), else lugs V / (2 pi r_e0)
  // The rigid-ring model holds below this, from the standing modes of this
  // condition's parameters (ModelValidBelowHz, model/forced_response.h).
  double model_valid_below_hz = 0;
  std::vector<OrderForces> orders;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("name", &name);
    a->Visit("speed_m_s", &speed_m_s);
    a->Visit("f_lug_hz", &f_lug_hz);
    a->Visit("f_lug_measured", &f_lug_measured);
    a->Visit("model_valid_below_hz", &model_valid_below_hz);
    a->Visit("orders", &orders);
  }
};

struct ForcesResult {
  Status status;
  int lugs_per_revolution = 0;
  std::string parameters;  // ForceParameters::source
  double max_condition_number = 0;
  std::vector<ConditionForces> conditions;
  double seconds = 0;

  // Per condition and order, each force with its interval, and the rest.
  std::string FullReport() const;
  template <class Archive>
  void Serialize(Archive* a) {
    status.Serialize(a);
    a->Visit("lugs_per_revolution", &lugs_per_revolution);
    a->Visit("parameters", &parameters);
    a->Visit("max_condition_number", &max_condition_number);
    a->Visit("conditions", &conditions);
    a->Visit("seconds", &seconds);
  }
};

void EstimateForces(const RigidRingModel& model, const ForceParameters& parameters,
                    const ResponseDataset& data, const ForcesOptions& options, ForcesResult* result);

}  // namespace ringid

#endif  // RINGID_ESTIMATION_FORCES_H_
