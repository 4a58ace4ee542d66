// `ringid predict`: the modes of a parameter set, standing and at speeds,
// and where the lug orders meet them.
#ifndef RINGID_APPS_PREDICT_COMMAND_H_
#define RINGID_APPS_PREDICT_COMMAND_H_

#include <map>
#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "model/effects.h"
#include "report/report.h"

namespace ringid {

// The body of predict: the modes of `parameters` (read from `source` with
// `notes`), or of dataset d's initial values with `set` over them (d not
// null), and at --speeds with --lugs_per_revolution. False with the one line
// of a usage error; solve_error says why the model could not be solved.
bool PredictBodyOf(const Parameters& parameters, const Dataset* d,
                   const std::map<Param, double>& set, const std::vector<const Effect*>& effects,
                   const std::string& source, const std::vector<std::string>& notes,
                   PredictBody* body, std::string* solve_error, std::string* error);
int Predict(int argc, char** argv);

}  // namespace ringid

#endif  // RINGID_APPS_PREDICT_COMMAND_H_
