// Loads a dataset, identifies the rigid-ring parameters and prints each with
// its standard deviation; with a second argument, writes the typed report
// there as ringid identify --output does. Usage: identify_parameters DATASET.json [REPORT.json]
#include <cstdio>
#include <fstream>

#include <ringid/datasets/dataset.h>
#include <ringid/estimation/identify.h>
#include <ringid/report/report.h>

int main(int argc, char** argv) {
  ringid::Dataset dataset;
  ringid::LoadError error;
  if (argc < 2 || argc > 3 || !ringid::LoadDataset(argv[1], &dataset, &error)) {
    std::fprintf(stderr, "%s\n", argc == 2 || argc == 3
                                     ? error.OneLine().c_str()
                                     : "usage: identify_parameters DATASET.json [REPORT.json]");
    return 2;
  }
  ringid::IdentifyResult summary;
  ringid::Identify(ringid::RigidRingModel(), dataset, ringid::IdentifyOptions(), &summary);
  std::printf("%s\n", summary.BriefReport().c_str());
  for (const ringid::ParameterEstimate& e : summary.estimates) {
    if (!e.free) continue;
    std::printf("%-10s %12.6g", e.key.Text().c_str(), e.value);
    if (e.std) std::printf(" +- %.2g\n", *e.std); else std::printf("  (std not defined)\n");
  }
  if (argc == 3) {
    const ringid::IdentifyReport report{
        ringid::MakeProvenance(argc, argv, {{"dataset", argv[1]}}, std::nullopt),
        {dataset.name, summary}};
    std::ofstream(argv[2]) << ringid::ReportText(report);
  }
  return summary.status.ok() ? 0 : 1;
}
