// extract (issue 37): the modes in a dataset's FRFs as a modal dataset that
// identify reads, labelled by fit (estimation/frf_start.h), so that the
// modal and the FRF routes start from the same measurements.
#ifndef RINGID_OPERATIONS_EXTRACT_H_
#define RINGID_OPERATIONS_EXTRACT_H_

#include <optional>
#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "model/modal.h"
#include "operations/input_error.h"
#include "operations/options.h"

namespace ringid {

// A physical pole of a condition's FRFs (pLSCF, estimation/plscf.h).
struct ExtractedPole {
  int condition = 0;
  double frequency_hz = 0;  // damped (contract §2)
  double damping_ratio = 0;
  int stable_orders = 0;    // orders of the stabilisation diagram that hold it
  // Its label where it went into the dataset (the model has seven modes per
  // condition: the strongest are kept), and whether the outputs gave it a
  // shape on the model's coordinates.
  std::optional<ModeLabel> label;
  bool shape = false;
};

struct Extracted {
  Dataset dataset;  // the modes, the FRF dataset's conditions, known, initial, ties
  std::vector<ExtractedPole> poles;  // every condition's, ascending frequency in each
  std::vector<std::string> notes;    // what the dataset assumes
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

}  // namespace ringid

#endif  // RINGID_OPERATIONS_EXTRACT_H_
