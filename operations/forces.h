// forces: the lug forces from a response dataset (contract §8), and
// simulate --lug_forces, the axle's response to given lug forces.
#ifndef RINGID_OPERATIONS_FORCES_H_
#define RINGID_OPERATIONS_FORCES_H_

#include <string>

#include "datasets/dataset.h"
#include "datasets/response_dataset.h"
#include "estimation/forces.h"
#include "operations/input_error.h"
#include "operations/options.h"

namespace ringid {

// The source of forces from a parameter set's values.
inline constexpr const char* kParameterSetForces =
    "parameter set (values alone: std_total is std_measurement)";

// The parameters of an identify report (its values per condition and its
// covariance) or of a parameter set or a .tir (its values alone, `set` over
// them).
bool ReadForceParameters(const std::string& path, const ParameterValues& set,
                         ForceParameters* fp, InputError* error);
// `set` over a fit's values: only over values it did not fit, whose
// covariance would not hold them (`source` names the fit).
bool SetOverFit(const ParameterValues& set, const std::string& source, ForceParameters* fp,
                std::string* error);

// The forces of `data` (read from `dataset`) under fp (from `parameters`,
// s.set over it already) and s.effects; false with the error.
bool ForcesOf(const ForceParameters& fp, const ResponseDataset& data, const ForcesSettings& s,
              const std::string& parameters, const std::string& dataset, ForcesResult* r,
              InputError* error);

// The axle's response to the lug forces of s.lug_forces (read into
// `spectrum`) at s.speeds (each > 0) under the parameter set at `parameters`
// (s.set over it), with s.response_noise; false with the error.
bool SimulateResponse(const std::string& parameters, const SimulateSettings& s,
                      LugForceSpectrum* spectrum, ResponseDataset* data, InputError* error);

}  // namespace ringid

#endif  // RINGID_OPERATIONS_FORCES_H_
