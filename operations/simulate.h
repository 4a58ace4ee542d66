// simulate (without lug_forces): a dataset measured from a parameter set,
// and its truth.
#ifndef RINGID_OPERATIONS_SIMULATE_H_
#define RINGID_OPERATIONS_SIMULATE_H_

#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "datasets/parameter_files.h"
#include "model/effects.h"
#include "operations/input_error.h"
#include "operations/options.h"

namespace ringid {

struct Simulated {
  Dataset dataset;  // named after `output`
  Truth truth;      // naming `output` as its dataset
  std::vector<const Effect*> effects;
};

// The simulation of the parameter set at `parameters` under s, its dataset
// to be written to `output`. False with the error, and *failed set when the
// simulation itself failed (the command line's exit status 1).
bool SimulateDataset(const std::string& parameters, const std::string& output,
                     const SimulateSettings& s, Simulated* out, InputError* error, bool* failed);

}  // namespace ringid

#endif  // RINGID_OPERATIONS_SIMULATE_H_
