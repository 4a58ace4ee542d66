#include "apps/forces_command.h"

#include <cstdio>

#include "apps/flags.h"
#include "apps/reports.h"
#include "datasets/response_dataset.h"
#include "operations/forces.h"
#include "report/report.h"

namespace ringid {

int SimulateResponsesCommand(const SimulateSettings& s) {
  std::string error;
  if (FLAGS_parameters.empty() || FLAGS_output.empty()) {
    return Usage("simulate --lug_forces needs --parameters=FILE and --output=RESPONSE");
  }
  if (!FLAGS_truth.empty()) {
    return Usage("--truth: the file of --lug_forces is the truth of a response simulation");
  }
  // Its default, 0 (standing), has no lug order: the drum speeds are asked for.
  if (gflags::GetCommandLineFlagInfoOrDie("speeds").is_default) {
    return Usage("simulate --lug_forces needs --speeds=V1,V2,... (drum speeds in m/s, each > 0: "
                 "a lug order exists only rolling)");
  }
  if (!CheckOutputs({{"output", FLAGS_output}}, Inputs(), &error)) return Usage(error);
  LugForceSpectrum spectrum;
  ResponseDataset data;
  InputError bad;
  if (!SimulateResponse(FLAGS_parameters, s, &spectrum, &data, &bad)) return Usage(bad.line);
  const int rc = Write(FLAGS_output, ResponseDatasetToJson(data));
  if (rc != kExitOk) return rc;
  std::printf("wrote %s: %zu conditions, %zu orders, 5 channels\n", FLAGS_output.c_str(),
              data.conditions.size(), spectrum.orders.size());
  return kExitOk;
}

int ForcesCommand(int argc, char** argv) {
  std::string error;
  ForcesSettings s;
  if (!ReadSettings(&s, &error)) return Usage(error);
  if (FLAGS_parameters.empty() || FLAGS_dataset.empty()) {
    return Usage("forces needs --parameters=FILE (a parameter set or an identify report) and "
                 "--dataset=FILE (a response dataset, ringid-lug-response/1)");
  }
  if (!CheckOutputs({{"output", FLAGS_output}}, Inputs(), &error)) return Usage(error);
  ForceParameters fp;
  InputError bad;
  std::vector<std::string> notes;  // where a .tir's values came from
  if (!ReadForceParameters(FLAGS_parameters, s.set, &fp, &bad, &notes)) return Usage(bad.line);
  ResponseDataset data;
  LoadError load;
  if (!LoadResponseDataset(FLAGS_dataset, &data, &load)) return Usage(load.OneLine());
  ForcesResult r;
  if (!ForcesOf(fp, data, s, FLAGS_parameters, FLAGS_dataset, &r, &bad, notes)) {
    return Usage(bad.line);
  }
  for (const std::string& note : notes) std::printf("%s%s\n", kParameterNotePrefix, note.c_str());
  return Finish<ForcesReport>(argc, argv, data, r);
}

}  // namespace ringid
