// Parameter-set files and atomic writes of the files a command makes.
#ifndef RINGID_APPS_REPORTS_H_
#define RINGID_APPS_REPORTS_H_

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "datasets/dataset.h"
#include "estimation/identify.h"

namespace ringid {

// A parameter set (see LoadParameterSet in datasets/dataset.h).
nlohmann::json ParameterSetJson(const IdentifySummary& s, const std::string& name,
                                const std::string& description);

// A report as text. Paths and names from the command line need not be UTF-8:
// invalid bytes become U+FFFD instead of an exception.
std::string JsonText(const nlohmann::json& report);

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
// Whether `path` could be written, checked before a long run starts.
bool CanWrite(const std::string& path, std::string* error);

}  // namespace ringid

#endif  // RINGID_APPS_REPORTS_H_
