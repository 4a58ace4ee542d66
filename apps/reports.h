// The checks on the files a command makes, before it makes them; the
// writing itself, and the parameter set of --save_parameters, are the
// library's (operations/files.h, operations/fit.h).
#ifndef RINGID_APPS_REPORTS_H_
#define RINGID_APPS_REPORTS_H_

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "datasets/dataset.h"
#include "datasets/parameter_files.h"
#include "estimation/identify.h"
#include "operations/files.h"
#include "operations/fit.h"

namespace ringid {

// A report as text. Paths and names from the command line need not be UTF-8:
// invalid bytes become U+FFFD instead of an exception.
std::string JsonText(const nlohmann::json& report);

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
