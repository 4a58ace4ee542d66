// JSON reports of contract section 6, parameter-set files, atomic writes.
#ifndef RINGID_APPS_REPORTS_H_
#define RINGID_APPS_REPORTS_H_

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "datasets/dataset.h"
#include "estimation/compare.h"
#include "estimation/diagnose.h"
#include "estimation/identifiability.h"
#include "estimation/identify.h"
#include "model/modal.h"

namespace ringid {

nlohmann::json IdentifyReport(const IdentifySummary& s, const Dataset& d,
                              const IdentifyOptions& o);
nlohmann::json PredictReport(const ModalSolution& s);
nlohmann::json DiagnoseJson(const DiagnosisReport& r, const Dataset& d);
nlohmann::json CompareJson(const ComparisonReport& r, const Dataset& d);
nlohmann::json IdentifiabilityJson(const IdentifiabilityReport& r, const Dataset& d);

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
// Several files, all or none: each is written to a temporary file, and the
// renames start only once every one is complete (e.g. a dataset and its truth).
// A path named twice is refused before anything is written.
bool WriteFilesAtomically(const std::vector<std::pair<std::string, std::string>>& files,
                          std::string* error);
// Whether `path` could be written, checked before a long run starts.
bool CanWrite(const std::string& path, std::string* error);

}  // namespace ringid

#endif  // RINGID_APPS_REPORTS_H_
