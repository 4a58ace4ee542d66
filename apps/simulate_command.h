// `ringid simulate` on the flags: the dataset and its truth, not written.
#ifndef RINGID_APPS_SIMULATE_COMMAND_H_
#define RINGID_APPS_SIMULATE_COMMAND_H_

#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "datasets/parameter_files.h"
#include "model/effects.h"

namespace ringid {

struct Simulated {
  Dataset dataset;  // named after --output
  Truth truth;      // naming --output as its dataset
  std::vector<const Effect*> effects;
};

// The simulation the flags ask for; with need_files, --output and --truth
// are required and checked as outputs. False with the one line of a usage
// error, or with *failed set when the simulation itself failed (exit 1).
bool SimulateFromFlags(bool need_files, Simulated* out, std::string* error, bool* failed);

}  // namespace ringid

#endif  // RINGID_APPS_SIMULATE_COMMAND_H_
