// Parameter-set files and atomic writes of the files a command makes.
#ifndef RINGID_APPS_REPORTS_H_
#define RINGID_APPS_REPORTS_H_

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "datasets/dataset.h"
#include "datasets/parameter_files.h"
#include "estimation/identify.h"

namespace ringid {

// The shared values of a fit as a parameter set (--save_parameters), with
// their standard deviations and what the data determined of them.
ParameterSet IdentifiedParameterSet(const IdentifyResult& s, const std::string& name,
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
// between two renames; an interruption (apps/interrupt.h) waits for the group.
bool WriteFilesAtomically(const std::vector<std::pair<std::string, std::string>>& files,
                          std::string* error);
// Whether `path` could be written, checked before a long run starts: not a
// directory, and a probe file beside it can be made (and is removed).
bool CanWrite(const std::string& path, std::string* error);

// Whether two paths name one file: the same after resolving ".", ".." and
// symbolic links, or hard links to one file.
bool SameFile(const std::string& a, const std::string& b);

// The files one run will write, as (flag, path) with "" for a flag not given,
// checked before any work: each can be written (CanWrite), no two are one
// file, and none is an input (flag, path) it would overwrite. False with one
// line naming the flag.
bool CheckOutputs(const std::vector<std::pair<std::string, std::string>>& outputs,
                  const std::vector<std::pair<std::string, std::string>>& inputs,
                  std::string* error);

// Whether `dir` is a directory one can write in, or could be made: its
// nearest existing ancestor is a directory one can write in. Nothing is made.
bool CanMakeDirectory(const std::string& dir, std::string* error);
// Makes `dir` and any missing parents, appending each one made to `made`
// (so that RemoveMade can take them away if the files for them fail).
bool MakeDirectory(const std::string& dir, std::vector<std::string>* made, std::string* error);
// Removes the directories of `made` that are empty, deepest first.
void RemoveMade(const std::vector<std::string>& made);

}  // namespace ringid

#endif  // RINGID_APPS_REPORTS_H_
