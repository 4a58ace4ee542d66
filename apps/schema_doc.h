// docs/reports.md: every kind of report, its fields and their types, drawn
// from the reports' Serialize lists (`ringid schema`).
#ifndef RINGID_APPS_SCHEMA_DOC_H_
#define RINGID_APPS_SCHEMA_DOC_H_

#include <string>

namespace ringid {

std::string ReportsMarkdown();
// docs/inputs.md: the input files' fields (`ringid inputs`).
std::string InputsMarkdown();

}  // namespace ringid

#endif  // RINGID_APPS_SCHEMA_DOC_H_
