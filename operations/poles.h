// poles: the physical poles of FRFs alone, without a tire model or labels
// (estimation/poles.h), from a UFF file (with a map for units and averages
// where given) or a format-3 dataset's frf blocks; POLES.json and the report
// (report/poles_report.h).
#ifndef RINGID_OPERATIONS_POLES_H_
#define RINGID_OPERATIONS_POLES_H_

#include <string>
#include <vector>

#include "estimation/poles.h"
#include "operations/input_error.h"
#include "operations/options.h"
#include "report/poles_report.h"

namespace ringid {


// Where the FRFs come from: exactly one of uff and dataset; map only with uff.
struct PolesInputs {
  std::string uff, map, dataset;
};

struct PolesRun {
  PolesFile file;
  PolesBody body;  // the report's, without its envelope
};

// The poles of the inputs' FRFs, condition by condition. False with the
// error: a file or option that does not read (exit 2), or an extraction that
// failed (out->body.status says which).
bool FindFilePoles(const PolesInputs& in, const PolesSettings& s, PolesRun* out, InputError* error);

}  // namespace ringid

#endif  // RINGID_OPERATIONS_POLES_H_
