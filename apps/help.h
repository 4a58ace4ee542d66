// `ringid help`: the commands, their flags, and the names the flags take.
#ifndef RINGID_APPS_HELP_H_
#define RINGID_APPS_HELP_H_

#include <string>

namespace ringid {

std::string Help();

}  // namespace ringid

#endif  // RINGID_APPS_HELP_H_
