#include "apps/schema_doc.h"

#include <cstdio>

#include "datasets/dataset_file.h"
#include "datasets/frf_spec.h"
#include "datasets/parameter_files.h"
#include "datasets/response_dataset.h"
#include "datasets/synthetic.h"
#include "datasets/uff_dataset.h"
#include "report/extract_report.h"
#include "report/poles_report.h"
#include "report/report.h"
#include "report/schema.h"
#include "validation/suites.h"

namespace ringid {
namespace {

template <class R>
std::string Section(const char* command, const std::string& about = "") {
  return std::string("## ") + ToString(R::kKind) + "\n\nWritten by `" + command + "`.\n\n" +
         (about.empty() ? "" : about + "\n\n") + ReportSchema<R>() + "\n";
}

std::string Number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

}  // namespace

std::string ReportsMarkdown() {
  return "# The reports of ringid\n\n"
         "Made by `ringid schema` from the reports' own field lists; a test keeps this file\n"
         "equal to its output. Every report is one JSON object. A reader refuses a missing,\n"
         "mistyped or unknown field, naming its path. Units are in the field names (`_hz`,\n"
         "`seconds`) or given beside the value (`unit`); fractions (a shrink, a success rate, a\n"
         "coverage) are fractions, not percentages. Schema version " +
         std::to_string(kReportSchemaVersion) + ".\n\n" +
         Section<IdentifyReport>("ringid identify --output=FILE") +
         Section<PredictReport>("ringid predict --output=FILE") +
         Section<IdentifiabilityReport>("ringid identifiability --output=FILE") +
         Section<CompareReport>("ringid compare --output=FILE") +
         Section<DiagnoseReport>("ringid diagnose --output=FILE") +
         Section<CampaignReport>("ringid identify|diagnose --output_dir=DIR (DIR/campaign.json)") +
         Section<ForcesReport>("ringid forces --output=FILE") +
         Section<ExtractReport>(
             "ringid extract --dataset=FILE --output=FILE --report=FILE",
             "Per condition with FRFs, pLSCF's stabilisation diagram (`diagram`: each order's\n"
             "poles with Im λ > 0, stable where `stable_frequency`, `stable_damping` and\n"
             "`stable_vector` all hold) and each function on the lines pLSCF used, measured\n"
             "(`measured_re`, `measured_im`) and synthesised by LSFD at the physical poles\n"
             "(`model_re`, `model_im`), as real and imaginary parts, with the FRAC of the two\n"
             "(`frac`) and `chi2` with the measured `sigma`. `poles` are the physical poles;\n"
             "`frequency_sigma_hz` and `damping_sigma` are absent where the estimator gives\n"
             "no standard error (pLSCF gives none).") +
         Section<PolesReport>(
             "ringid poles --uff=FILE --output=POLES.json --report=FILE",
             "`poles` is POLES.json as written: per set of lines (`conditions`: its units, and\n"
             "`noise` \"given\" where every function has sigma or coherence with averages, else\n"
             "\"from the residuals\"), the physical poles with their standard errors (null where\n"
             "the refinement does not give one), each function's residue by the file's response\n"
             "and reference names, and the shape over the side with several coordinates. Per\n"
             "condition, the diagram and the synthesis as extract's.") +
         Section<BenchPaperReport>("ringid bench --suite=paper --output=FILE") +
         Section<BenchSyntheticReport>("ringid bench --suite=synthetic --output=FILE") +
         Section<BenchConditioningReport>("ringid bench --suite=conditioning --output=FILE") +
         Section<BenchDiagnosisReport>("ringid bench --suite=diagnosis --output=FILE") +
         Section<BenchRollingReport>("ringid bench --suite=rolling --output=FILE") +
         Section<BenchSpeedReport>("ringid bench --suite=speed --output=FILE") +
         Section<BenchForcesReport>("ringid bench --suite=forces --output=FILE") +
         Section<BenchStaticReport>("ringid bench --suite=static --output=FILE") +
         Section<BenchFrfReport>("ringid bench --suite=frf --output=FILE");
}

std::string InputsMarkdown() {
  DatasetFields format1, format2, format3;
  format2.format = kDatasetFormat2;
  format3.format = kDatasetFormat3;
  UffMapFields map2;
  map2.format = kUffMapFormat2;
  return std::string("# The input files of ringid\n\n") +
         "Made by `ringid inputs` from the files' own field lists; a test keeps this file\n"
         "equal to its output. The rules these types cannot say (ranges, names, what one\n"
         "field asks of another) are in [conventions.md](conventions.md) §3, §5 and §7. A\n"
         "reader refuses a missing, mistyped or unknown field, naming its path; an object keyed\n"
         "by name lists parameters (`known`, `initial`, `ties`, `priors`) or degrees of freedom\n"
         "(`shape`) by their names in [reference.md](reference.md).\n\n" +
         "## Modal dataset, format 1 (`" + kDatasetFormat1 + "`)\n\nRead by `--dataset`, written by "
         "`simulate --output`.\n\n" + InputSchema(format1) + "\n" +
         "## Modal dataset, format 2 (`" + kDatasetFormat2 + "`)\n\nSeveral conditions, rolling, "
         "priors (conventions.md §7); a condition's `modes` are required, `static` is format 3's.\n\n" +
         InputSchema(format2) + "\n" +
         "## Dataset, format 3 (`" + kDatasetFormat3 + "`)\n\nFormat 2's fields, each condition "
         "holding any of `modes`, `frf` (frequency response functions,\ncontract §9), `static` "
         "(static stiffnesses, standing only; contract §10) and `obstacle` (the axle's\nresponse "
         "to rolling over a profile over time, at speed; contract §11), at least one.\n\n" + InputSchema(format3) + "\n" +
         "## Parameter set (`" + kParameterSetFormat + "`)\n\nRead by `--parameters`, written by "
         "`identify --save_parameters` and `export`. A reader also takes a bare number for a\n"
         "value, a file without `format`, and an identify report (its `parameters`).\n\n" + InputSchema(ParameterSet{}) + "\n" +
         "## Truth file (`" + kTruthFormat + "`)\n\nWritten by `simulate --truth`, read by "
         "`LoadTruth` (datasets/parameter_files.h).\n\n" + InputSchema(Truth{}) + "\n" +
         "## Response dataset (`" + kResponseFormat + "`)\n\nRead by `forces --dataset` "
         "(contract §8, [forces.md](forces.md)): per drum condition, the complex amplitude of\n"
         "each measured axle channel (`axle_force_x`, `axle_force_z`, `axle_force_y`,\n"
         "`axle_moment_x`, `axle_moment_z`) at each lug order.\n\n" +
         InputSchema(ResponseDatasetFields{}) + "\n" +
         "## Lug forces (`" + kLugForcesFormat + "`)\n\nRead by `simulate --lug_forces`: the lug "
         "forces whose axle response it writes, per order the complex amplitude of `F_x`,\n"
         "`F_z` and `F_y` (N; a force left out is 0). An example: "
         "`datasets/examples/car_tire_lug_forces.json`.\n\n" + InputSchema(LugForcesFields{}) + "\n" +
         "## UFF map (`" + kUffMapFormat + "`)\n\nRead by `import --map` ([uff.md](uff.md)): "
         "each channel a UFF node's direction (1..3 x, y, z; 4..6\nrotations; negative: the "
         "opposite sense) as a degree of freedom, with a sign; the\nlabels of modes the user "
         "knows, by dataset 55's mode number; the parameters of\n`--parameters` written `known` "
         "(the rest `initial`).\n\n" + InputSchema(UffMapFields{}) + "\n" +
         "## UFF map, format 2 (`" + kUffMapFormat2 + "`)\n\nFormat 1's fields, `channels` "
         "optional, and the FRFs' (dataset 58) places ([uff.md](uff.md)):\n`points` put a node on "
         "the belt or the rim (`point_m` in ringid's axes, m; absent: the node's\ndataset-15 "
         "coordinates); `axes` are ringid's x, y, z as signed lab axes; `units` name the\nunits "
         "of every FRF's response and reference where the file's do not; `averages` go with\n"
         "the file's coherence functions. At least one of `points` and `channels`.\n\n" +
         InputSchema(map2) + "\n" +
         "## FRF spec (`" + kFrfSpecFormat + "`)\n\nRead by `simulate --frf` "
         "([conventions.md](conventions.md) §9): an FRF test's layout, whose values the\nmodel "
         "gives. `inputs` and `outputs` as in a dataset's `frf` block; the lines as `frequencies_hz` "
         "or\nas `lines_hz` (`from`, `to`, `step` in Hz), one of the two; `functions` the (output, "
         "input)\npairs measured (absent: every output with every input); `noise` the sd of re "
         "and of im per\nline relative to |H| (absent: " + Number(SimulateOptions().frf_noise) + "; 0: none). Examples: "
         "`datasets/examples/hammer_spec.json`,\n`datasets/examples/drum_spec.json`.\n\n" +
         InputSchema(FrfSpecFields{}) + "\n" +
         "## Obstacle spec (`" + kObstacleSpecFormat + "`)\n\nRead by `simulate --obstacle` "
         "(contract §11; [the obstacles guide](guides/obstacles.md)): a drum test\nover a cleat or a lugged "
         "tread, whose values the model gives. One condition per speed of\n`speeds_m_s` (m/s, "
         "each > 0), named `obstacle_V`; the `profile` as in a dataset's `obstacle`\nblock; the "
         "contact centre at `position_at_t0_m` at t = 0; samples at k / `sample_rate_hz`\nfor k "
         "below round(`duration_s` x `sample_rate_hz`); `outputs` the channels by name\n(" +
         TimeOutputChoices() + "); `noise` each channel's sigma relative to the\npeak-to-peak of "
         "its noise-free series, 0 to 1 (absent: " + Number(kDefaultObstacleNoise) + "; 0: none, and\n"
         "sigma then the default's share). Speeds 0.001 to 200 m/s, at most 100. An "
         "example:\n`datasets/examples/cleat_spec.json`.\n\n" +
         InputSchema(ObstacleSpecFields{}) + "\n" +
         "## Lug profile (`" + kLugProfileFormat + "`)\n\nRead by `predict --lug_profile` "
         "(contract §11; [the obstacles guide](guides/obstacles.md)): a\nlugged tread rolled out, "
         "a `lugs` profile as in a dataset's `obstacle` block. An example:\n"
         "`datasets/examples/cross_stitch_lugs.json`.\n\n" +
         InputSchema(LugProfileFields{});
}

}  // namespace ringid
