// The files an operation writes, whole or not at all: a report, a dataset
// and its truth, a parameter set. The command line's Ctrl-C handler
// (apps/interrupt.h) waits on HoldFileWrites, so that it never ends the
// process between the files of one group.
#ifndef RINGID_OPERATIONS_FILES_H_
#define RINGID_OPERATIONS_FILES_H_

#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace ringid {

// Writes via a temporary file beside `path` and a rename: a reader never sees
// a half-written report. False with a one-line message on failure.
bool WriteFileAtomically(const std::string& path, const std::string& text,
                         std::string* error);
// Several files, all or none (e.g. a dataset and its truth): each is written
// to a temporary file and renamed only once every one is complete; if a rename
// fails, the files renamed before it are put back as they were (an existing
// file from a hard link kept beside it, a new one removed). A path named
// twice is refused before anything is written. Not atomic against a crash
// between two renames.
bool WriteFilesAtomically(const std::vector<std::pair<std::string, std::string>>& files,
                          std::string* error);

// While held, no group of files is being written. Recursive, so that one
// holder may write several groups.
std::unique_lock<std::recursive_mutex> HoldFileWrites();
// The files written whole so far, in order; read while holding HoldFileWrites.
const std::vector<std::string>& FilesWritten();

}  // namespace ringid

#endif  // RINGID_OPERATIONS_FILES_H_
