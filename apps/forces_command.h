// `ringid forces`: the lug forces from a response dataset (contract §8).
#ifndef RINGID_APPS_FORCES_COMMAND_H_
#define RINGID_APPS_FORCES_COMMAND_H_

#include <map>
#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "datasets/response_dataset.h"
#include "estimation/forces.h"
#include "model/effects.h"

namespace ringid {

// The source of forces from a parameter set's values.
inline constexpr const char* kParameterSetForces =
    "parameter set (values alone: std_total is std_measurement)";
// An identify report gives its values per condition and its covariance; a
// parameter set or a .tir its values alone, with `set` over them (as
// LoadParameters, whose notes say where a .tir's values came from). `set`
// over a report is refused.
bool ReadForceParameters(const std::string& path, ForceParameters* fp, LoadError* error,
                         const std::map<Param, double>& set = {},
                         std::vector<std::string>* notes = nullptr);
// The forces of `data` (read from `dataset`) under fp (from `parameters`,
// read with `notes`) and `effects`; false with the one line of a usage error.
bool ForcesOf(const ForceParameters& fp, const ResponseDataset& data,
              const std::vector<const Effect*>& effects, const std::string& parameters,
              const std::string& dataset, ForcesResult* r, std::string* error,
              const std::vector<std::string>& notes = {});
int ForcesCommand(int argc, char** argv);
// `simulate --lug_forces=FILE`: the axle's response to known lug forces.
int SimulateResponsesCommand(int argc, char** argv);

}  // namespace ringid

#endif  // RINGID_APPS_FORCES_COMMAND_H_
