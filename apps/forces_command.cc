#include "apps/forces_command.h"

#include <cstdio>

#include "apps/flags.h"
#include "apps/reports.h"
#include "datasets/response_dataset.h"
#include "datasets/tir_parameters.h"
#include "estimation/forces.h"
#include "report/report.h"

namespace ringid {
namespace {

// An identify report gives its values per condition and its covariance; a
// parameter set or a .tir its values alone.
bool ReadForceParameters(const std::string& path, ForceParameters* fp, LoadError* error) {
  std::string text;
  Json json;
  if (!ReadInputFile(path, &text, error)) return false;
  if (ParseJsonInput(text, &json, error) && json.is_object() && json.contains("report")) {
    IdentifyReport report;
    std::string why;
    if (!ReadReport(json, &report, &why)) {
      SetArchiveError(why, error);
      return false;
    }
    *fp = ForceParameters::From(report.body.result);
    return true;
  }
  *fp = ForceParameters{};
  if (!LoadParameters(path, &fp->shared, error)) return false;
  fp->source = "parameter set (values alone: std_total is std_measurement)";
  return true;
}

}  // namespace

int ForcesCommand(int argc, char** argv) {
  std::string error;
  std::vector<const Effect*> effects;
  if (!ParseEffects(&effects, &error)) return Usage(error);
  if (FLAGS_parameters.empty() || FLAGS_dataset.empty()) {
    return Usage("forces needs --parameters=FILE (a parameter set or an identify report) and "
                 "--dataset=FILE (a response dataset, ringid-lug-response/1)");
  }
  if (!CheckOutputs({{"output", FLAGS_output}}, Inputs(), &error)) return Usage(error);
  LoadError load;
  ForceParameters fp;
  if (!ReadForceParameters(FLAGS_parameters, &fp, &load)) return Usage(load.OneLine());
  ResponseDataset data;
  if (!LoadResponseDataset(FLAGS_dataset, &data, &load)) return Usage(load.OneLine());
  const RigidRingModel model(effects);
  for (const ResponseCondition& c : data.conditions) {
    const std::vector<Param> missing = Missing(model, fp.In(c));
    if (!missing.empty()) return Usage(MissingParameters(FLAGS_parameters, missing));
  }
  ForcesResult r;
  EstimateForces(model, fp, data, ForcesOptions{}, &r);
  return Finish<ForcesReport>(argc, argv, data, r);
}

}  // namespace ringid
