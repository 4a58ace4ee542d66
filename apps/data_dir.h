// Where the data shipped with ringid are found (datasets/paper/ for the
// suites of `ringid bench`), from whatever directory ringid runs in.
#ifndef RINGID_APPS_DATA_DIR_H_
#define RINGID_APPS_DATA_DIR_H_

#include <string>

namespace ringid {

// The directory holding datasets/paper/, the first of:
//  * beside the executable as installed, PREFIX/bin/ringid ->
//    PREFIX/share/ringid: found from the executable's own path, so it holds
//    for any prefix given at install time (cmake --install --prefix), not
//    only the one the build was configured with;
//  * the source tree the executable was built from (a build-tree binary);
//  * the working directory, "." (the last resort: a repository root).
std::string DataDir();

}  // namespace ringid

#endif  // RINGID_APPS_DATA_DIR_H_
