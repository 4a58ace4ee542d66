// extract (issue 37): the modes in a dataset's FRFs as a modal dataset that
// identify reads (estimation/extract.h), from a file or a loaded dataset.
#ifndef RINGID_OPERATIONS_EXTRACT_H_
#define RINGID_OPERATIONS_EXTRACT_H_

#include <string>

#include "datasets/dataset.h"
#include "estimation/extract.h"
#include "operations/input_error.h"
#include "operations/options.h"
#include "report/extract_report.h"

namespace ringid {

// ExtractModalDataset of the dataset at `path` under s; where `guess` is
// given (--parameters: a parameter set, weighed masses, say), its values
// replace the dataset's initial ones they name. False with the error: the
// file, the options, a dataset without FRFs or FRFs without a mode (exit 2),
// or the labelling failed (out->status says so).
bool ExtractDataset(const std::string& path, const ExtractSettings& s, ExtractResult* out,
                    InputError* error, const Parameters* guess = nullptr);
// The same of a dataset read from `source` (its errors name it).
bool ExtractDataset(const Dataset& d, const std::string& source, const ExtractSettings& s,
                    ExtractResult* out, InputError* error, const Parameters* guess = nullptr);

// The report of `x`, extracted from the dataset `source` (--report): each
// function's LSFD synthesis on the lines pLSCF used
// (operations/extract_report.cc).
ExtractBody ExtractBodyOf(const ExtractResult& x, const std::string& source);
// One condition's part of it: its diagram, and each function against its
// synthesis.
ExtractCondition ExtractConditionOf(const ExtractedCondition& c, std::optional<std::string> name);

}  // namespace ringid

#endif  // RINGID_OPERATIONS_EXTRACT_H_
