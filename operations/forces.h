// forces: the lug forces from a response dataset (contract §8), and
// simulate --lug_forces, the axle's response to given lug forces.
#ifndef RINGID_OPERATIONS_FORCES_H_
#define RINGID_OPERATIONS_FORCES_H_

#include <string>
#include <vector>

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
// them, as LoadParameters, whose `notes` say where a .tir's values came
// from). `set` over a report is refused (NoSetOverFit).
bool ReadForceParameters(const std::string& path, const ParameterValues& set,
                         ForceParameters* fp, InputError* error,
                         std::vector<std::string>* notes = nullptr);
// `set` over a fit's values (`source` names the fit): refused, its values
// carry the fit's covariance.
bool NoSetOverFit(const ParameterValues& set, const std::string& source, InputError* error);

// The forces of `data` (read from `dataset`) under fp (from `parameters`,
// s.set over it already, read with `notes`) and s.effects; false with the
// error.
bool ForcesOf(const ForceParameters& fp, const ResponseDataset& data, const ForcesSettings& s,
              const std::string& parameters, const std::string& dataset, ForcesResult* r,
              InputError* error, const std::vector<std::string>& notes = {});

// The axle's response to the lug forces of s.lug_forces (read into
// `spectrum`) at s.speeds (each > 0) under the parameter set at `parameters`
// (s.set over it), with s.response_noise; false with the error.
bool SimulateResponse(const std::string& parameters, const SimulateSettings& s,
                      LugForceSpectrum* spectrum, ResponseDataset* data, InputError* error);

}  // namespace ringid

#endif  // RINGID_OPERATIONS_FORCES_H_
