// `ringid poles`: the physical poles of a UFF file's or a dataset's FRFs
// (operations/poles.h).
#ifndef RINGID_APPS_POLES_COMMAND_H_
#define RINGID_APPS_POLES_COMMAND_H_

#include <string>
#include <vector>

namespace ringid {

const std::vector<std::string>& PolesFlags();
int PolesCommand(int argc, char** argv);

}  // namespace ringid

#endif  // RINGID_APPS_POLES_COMMAND_H_
