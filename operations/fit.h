// The fitting operations (identify, identifiability, compare, diagnose and
// ringid.Problem) on their settings: the library's options, the dataset with
// --fix applied, and the parameter set --save_parameters writes.
#ifndef RINGID_OPERATIONS_FIT_H_
#define RINGID_OPERATIONS_FIT_H_

#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "datasets/parameter_files.h"
#include "estimation/diagnose.h"
#include "estimation/identifiability.h"
#include "estimation/identify.h"
#include "operations/options.h"

namespace ringid {

// The options of a fit under `settings`; `jobs` datasets fitted at once (a
// campaign's) share the cores that threads=0 asks for. False with the line
// naming the option.
bool FitOptionsOf(const FitSettings& settings, int jobs, IdentifyOptions* options,
                  std::string* error);
// The same with the diagnosis's level.
bool DiagnoseOptionsOf(const DiagnoseSettings& settings, int jobs, DiagnoseOptions* options,
                       std::string* error);

// The same with identifiability's profiles.
bool IdentifiabilityOptionsOf(const IdentifiabilitySettings& settings, int jobs,
                              IdentifiabilityOptions* options, std::string* error);

// The parameters of `fix` held at their initial values in `dataset`
// (FixParameters); false with the line naming --fix.
bool ApplyFix(const std::vector<Param>& fix, Dataset* dataset, std::string* error);

// The shared values of a fit as a parameter set (--save_parameters), with
// their standard deviations and what the data determined of them.
ParameterSet IdentifiedParameterSet(const IdentifyResult& s, const std::string& name,
                                    const std::string& description);

}  // namespace ringid

#endif  // RINGID_OPERATIONS_FIT_H_
