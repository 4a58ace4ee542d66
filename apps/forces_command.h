// `ringid forces`: the lug forces from a response dataset (contract §8),
// and `simulate --lug_forces` (operations/forces.h).
#ifndef RINGID_APPS_FORCES_COMMAND_H_
#define RINGID_APPS_FORCES_COMMAND_H_

#include "operations/options.h"

namespace ringid {

int ForcesCommand(int argc, char** argv);
// `simulate --lug_forces=FILE`: the axle's response to known lug forces.
int SimulateResponsesCommand(const SimulateSettings& s);

}  // namespace ringid

#endif  // RINGID_APPS_FORCES_COMMAND_H_
