// extract (issue 37): the modes in a dataset's FRFs as a modal dataset that
// identify reads, labelled by fit (estimation/frf_start.h), so that the
// modal and the FRF routes start from the same measurements.
#ifndef RINGID_OPERATIONS_EXTRACT_H_
#define RINGID_OPERATIONS_EXTRACT_H_

#include <optional>
#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "estimation/plscf.h"
#include "model/modal.h"
#include "operations/input_error.h"
#include "operations/options.h"
#include "report/extract_report.h"

namespace ringid {

// What a condition's modes came from: its FRFs and their extraction (the
// stabilisation diagram, the physical poles, LSFD per function).
struct ExtractedCondition {
  int condition = 0;
  Frf frf;
  PlscfResult plscf;
};

struct Extracted {
  Dataset dataset;  // the modes, the FRF dataset's conditions, known, initial, ties
  std::vector<ExtractedPole> poles;  // every condition's, ascending frequency in each
  std::vector<std::string> notes;    // what the dataset assumes
  std::vector<ExtractedCondition> conditions;  // each with an frf block
};

// The modes in the FRFs of the dataset at `path`: each condition's physical
// poles, the strongest (as many as the model has) labelled by fit from the
// dataset's initial values (the modal stage of a fit to FRFs, its labels
// tried in every order where the outputs give no shape) with their shapes
// where the outputs determine them; the FRF blocks dropped, the masses and
// inertias made known at their initial values (modes carry no modal mass).
// False with the error: a dataset without FRFs, or FRFs without a mode.
bool ExtractDataset(const std::string& path, const ExtractSettings& s, Extracted* out,
                    InputError* error);
// The same of a dataset read from `source` (its errors name it).
bool ExtractDataset(const Dataset& d, const std::string& source, const ExtractSettings& s,
                    Extracted* out, InputError* error);

// The report of `x`, extracted from the dataset `source` (--report): each
// function's LSFD synthesis on the lines pLSCF used
// (operations/extract_report.cc).
ExtractBody ExtractBodyOf(const Extracted& x, const std::string& source);

}  // namespace ringid

#endif  // RINGID_OPERATIONS_EXTRACT_H_
