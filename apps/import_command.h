// `ringid import`: a test lab's UFF file as a ringid dataset (docs/uff.md).
#ifndef RINGID_APPS_IMPORT_COMMAND_H_
#define RINGID_APPS_IMPORT_COMMAND_H_

namespace ringid {

int ImportCommand(int argc, char** argv);

}  // namespace ringid

#endif  // RINGID_APPS_IMPORT_COMMAND_H_
