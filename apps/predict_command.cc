#include "apps/predict_command.h"

#include <cstdio>

#include "apps/flags.h"
#include "apps/reports.h"
#include "datasets/tir_parameters.h"
#include "operations/predict.h"
#include "report/report.h"

namespace ringid {

int Predict(int argc, char** argv) {
  std::string error;
  PredictSettings s;
  if (!ReadSettings(&s, &error)) return Usage(error);
  if (FLAGS_parameters.empty() == FLAGS_dataset.empty()) {
    return Usage("predict needs exactly one of --parameters=FILE or --dataset=FILE");
  }
  auto inputs = Inputs();
  inputs.emplace_back("lug_profile", s.lug_profile);
  if (!CheckOutputs({{"output", FLAGS_output}}, inputs, &error)) return Usage(error);
  Parameters p;
  LoadError load;
  std::vector<std::string> notes;
  Dataset d;
  if (!FLAGS_parameters.empty()) {  // a .tir by its extension
    if (!LoadParameters(FLAGS_parameters, s.set, &p, &load, &notes)) return Usage(load.OneLine());
  } else if (!LoadDataset(FLAGS_dataset, &d, &load)) {
    return Usage(load.OneLine());
  }
  const std::string& source = FLAGS_parameters.empty() ? FLAGS_dataset : FLAGS_parameters;
  PredictBody body;
  std::string solve_error;
  InputError bad;
  if (!PredictBodyOf(p, FLAGS_parameters.empty() ? &d : nullptr, s, source, notes, &body,
                     &solve_error, &bad)) {
    return Usage(bad.line);
  }
  if (!solve_error.empty()) std::fprintf(stderr, "ringid: predict: %s\n", solve_error.c_str());
  else std::printf("%s", body.FullReport().c_str());
  if (!FLAGS_output.empty()) {
    Provenance provenance = ThisRun(argc, argv, std::nullopt);
    if (!s.lug_profile.empty()) {
      provenance.inputs.push_back({"lug_profile", s.lug_profile, FileSha256(s.lug_profile)});
    }
    const int rc = Write(FLAGS_output, ReportText(PredictReport{provenance, body}));
    if (rc != kExitOk) return rc;
  }
  return solve_error.empty() ? kExitOk : kExitFailure;
}

}  // namespace ringid
