// predict: the modes of a parameter set, standing and at speeds, and where
// the lug orders meet them.
#ifndef RINGID_OPERATIONS_PREDICT_H_
#define RINGID_OPERATIONS_PREDICT_H_

#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "operations/input_error.h"
#include "operations/options.h"
#include "report/report.h"

namespace ringid {

// The body of predict: the modes of `parameters` (read from `source` with
// `notes`; s.set over them already), or of dataset d's initial values with
// s.set over them (d not null), and at s.speeds with s.lugs_per_revolution.
// False with the error; solve_error says why the model could not be solved.
bool PredictBodyOf(const Parameters& parameters, const Dataset* d, const PredictSettings& s,
                   const std::string& source, const std::vector<std::string>& notes,
                   PredictBody* body, std::string* solve_error, InputError* error);

}  // namespace ringid

#endif  // RINGID_OPERATIONS_PREDICT_H_
