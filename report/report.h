// The typed reports ringid writes: one envelope (kind, schema version,
// provenance) around one body per kind. Each body lists its fields once in
// Serialize; the JSON writer and reader (model/archive.h) follow that list,
// so a report written, read and written again is byte-identical.
#ifndef RINGID_REPORT_REPORT_H_
#define RINGID_REPORT_REPORT_H_

#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "estimation/compare.h"
#include "estimation/diagnose.h"
#include "estimation/forces.h"
#include "estimation/identifiability.h"
#include "estimation/identify.h"
#include "estimation/status.h"
#include "datasets/obstacle.h"
#include "model/campbell.h"
#include "model/lug_excitation.h"
#include "model/modal.h"
#include "model/archive.h"

namespace ringid {

// Raised whenever a field is renamed, removed or changes meaning.
inline constexpr int kReportSchemaVersion = 17;

enum class ReportKind {
  kIdentify, kPredict, kIdentifiability, kCompare, kDiagnose, kCampaign, kForces,
  kExtract,  // operations/extract_report.h
  kPoles,    // report/poles_report.h
  // validation/
  kBenchPaper, kBenchSynthetic, kBenchConditioning, kBenchDiagnosis, kBenchRolling, kBenchSpeed,
  kBenchForces, kBenchStatic, kBenchFrf, kBenchExtract,
};
template <>
struct EnumNames<ReportKind> {
  static constexpr std::array<const char*, 19> kNames = {
      "identify", "predict", "identifiability", "compare", "diagnose", "campaign", "forces",
      "extract", "poles", "bench_paper", "bench_synthetic", "bench_conditioning", "bench_diagnosis",
      "bench_rolling", "bench_speed", "bench_forces", "bench_static", "bench_frf", "bench_extract"};
};

struct InputFile {
  std::string role;    // the flag it came from, e.g. "dataset"
  std::string path;
  std::string sha256;  // of the bytes read; "" where it could not be read

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("role", &role);
    a->Visit("path", &path);
    a->Visit("sha256", &sha256);
  }
};

// What made the report: enough to run it again and to know it is the same.
struct Provenance {
  std::string ringid_version;
  std::vector<std::string> command_line;
  std::vector<InputFile> inputs;
  std::optional<long> seed;          // of random starts or noise, where used
  Derivatives derivatives = ResidualOptions().derivatives;  // how Jacobians were taken
  // A campaign's: the flags that decide its results, NAME=VALUE; a report
  // is resumed only under the same.
  std::optional<std::vector<std::string>> options;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("ringid_version", &ringid_version);
    a->Visit("command_line", &command_line);
    a->Visit("inputs", &inputs);
    a->Visit("seed", &seed);
    a->Visit("derivatives", &derivatives);
    a->VisitIfSet("options", &options);
  }
};

// SHA-256 of a file's bytes in hex; "" where it cannot be read.
std::string FileSha256(const std::string& path);

// The provenance of this process: version, argv, and each input's SHA-256.
Provenance MakeProvenance(int argc, const char* const* argv,
                          const std::vector<std::pair<std::string, std::string>>& role_paths,
                          std::optional<long> seed);

// An analysis of one dataset: identify, identifiability, compare, diagnose.
template <class Result>
struct DatasetBody {
  std::string dataset;  // the dataset's name
  Result result;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("dataset", &dataset);
    result.Serialize(a);
  }
};

struct PredictedMode {
  ModeLabel label = ModeLabel::kVertical;
  double model_hz = 0;        // damped (docs/conventions.md §2)
  double damping_ratio = 0;
  double label_energy_share = 0;
  std::map<Dof, std::complex<double>> shape;  // non-zero components
  std::map<Dof, double> paper_eigenvector;    // Tables 4-5 convention

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("label", &label);
    a->Derived("plane", LabelPlane(label));
    a->Visit("model_hz", &model_hz);
    a->Visit("damping_ratio", &damping_ratio);
    a->Visit("label_energy_share", &label_energy_share);
    a->Visit("shape", &shape);
    a->Visit("paper_eigenvector", &paper_eigenvector);
  }
};

// The modes rolling at one speed (predict --speeds).
struct SpeedModes {
  std::optional<std::string> condition;  // a dataset's condition, by name
  double speed_m_s = 0;
  std::map<ModeLabel, std::pair<double, double>> modes;  // label -> (Hz, damping ratio)

  template <class Archive>
  void Serialize(Archive* a) {
    a->VisitIfSet("condition", &condition);
    a->Visit("speed_m_s", &speed_m_s);
    a->Visit("modes", &modes);
  }
};

// How a note on where the parameters came from is printed (predict, export,
// import): a note, not an error ("ringid: ...").
inline constexpr char kParameterNotePrefix[] = "parameters: ";

struct PredictBody {
  Status status;
  std::vector<PredictedMode> modes;
  std::vector<ModeLabel> overdamped;  // labels whose roots are real
  // With --speeds: the modes at each speed; with --lugs_per_revolution too,
  // where the lug orders meet them (model/campbell.h).
  std::optional<std::vector<SpeedModes>> speeds;
  std::optional<int> lugs_per_revolution;
  std::optional<double> r_e0;  // the orders' slope: k lugs V / (2 pi r_e0)
  std::optional<int> max_order;  // the critical speeds are those of orders 1 to this
  std::optional<std::vector<CriticalSpeed>> critical_speeds;
  // With --dataset of several conditions: the modes of each (`modes` are the
  // first's).
  std::optional<std::vector<SpeedModes>> conditions;
  // Where the parameters came from: a .tir's derived values and warnings.
  std::optional<std::vector<std::string>> parameter_notes;
  // With --lug_profile and --speeds: the tread's lugs, and at each speed the
  // forces per lug order they put on the ring and the axle's response.
  std::optional<ObstacleProfileFields> lug_profile;
  std::optional<std::vector<LugExcitation>> lug_excitation;

  static PredictBody From(const ModalSolution& solution);
  // The modes as a table (mode, plane, Hz, zeta) and the overdamped labels;
  // the modes by speed and the critical speeds where there are.
  std::string FullReport() const;
  template <class Archive>
  void Serialize(Archive* a) {
    status.Serialize(a);
    a->Visit("modes", &modes);
    a->Visit("overdamped", &overdamped);
    a->VisitIfSet("speeds", &speeds);
    a->VisitIfSet("lugs_per_revolution", &lugs_per_revolution);
    a->VisitIfSet("r_e0", &r_e0);
    a->VisitIfSet("max_order", &max_order);
    a->VisitIfSet("critical_speeds", &critical_speeds);
    a->VisitIfSet("conditions", &conditions);
    a->VisitIfSet("parameter_notes", &parameter_notes);
    a->VisitIfSet("lug_profile", &lug_profile);
    a->VisitIfSet("lug_excitation", &lug_excitation);
  }
};

// The lug excitation as its tables show it (text and page): per order the
// amplitudes of F_x, F_z, F_y and of the outputs, and the mean forces, each
// below 1e-9 of its column's largest shown as 0 (round-off).
inline constexpr int kLugColumns = 3 + kNumTimeOutputs;
std::vector<std::array<double, kLugColumns>> ShownAmplitudes(const LugExcitation& e);
std::array<double, 3> ShownMeans(const LugExcitation& e);

// One dataset of a campaign: its report file and the summary's columns.
struct CampaignRow {
  std::string dataset;      // the file
  std::string report_file;
  Status status;
  double seconds = 0;
  // identify
  std::optional<double> cost, relative_error_in_plane_eq19, relative_error_out_of_plane_eq20;
  std::optional<bool> converged;
  // diagnose
  std::optional<const Effect*> verdict;  // nullptr: none
  std::optional<std::vector<const Effect*>> indistinguishable;
  std::optional<double> gap_before, gap_after, shrink;
  // identify: the fitted values (the first condition's, for per-condition ones)
  std::optional<std::map<Param, double>> parameters;
  // --keep_going: where the dataset failed to load ("" where it failed to fit)
  std::optional<std::string> field;
  std::optional<bool> resumed;  // its report was kept from an earlier run

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("dataset", &dataset);
    a->Visit("report_file", &report_file);
    status.Serialize(a);
    a->VisitIfSet("field", &field);
    a->VisitIfSet("resumed", &resumed);
    a->Visit("seconds", &seconds);
    a->VisitIfSet("cost", &cost);
    a->VisitIfSet("relative_error_in_plane_eq19", &relative_error_in_plane_eq19);
    a->VisitIfSet("relative_error_out_of_plane_eq20", &relative_error_out_of_plane_eq20);
    a->VisitIfSet("converged", &converged);
    a->VisitIfSet("verdict", &verdict);
    a->VisitIfSet("indistinguishable", &indistinguishable);
    a->VisitIfSet("gap_before", &gap_before);
    a->VisitIfSet("gap_after", &gap_after);
    a->VisitIfSet("shrink", &shrink);
    a->VisitIfSet("parameters", &parameters);
  }
};

struct CampaignBody {
  ReportKind command = ReportKind::kIdentify;  // identify or diagnose
  std::string shard;  // I/N; "merged" for `ringid merge`
  int jobs = 1;
  double seconds = 0;
  std::vector<CampaignRow> datasets;
  // The whole campaign's datasets, every shard's, in order, and the flags
  // that decide its results: what `ringid merge` checks shards against.
  std::vector<std::string> campaign_datasets;
  std::vector<std::string> options;
  int resumed = 0;  // reports kept from an earlier run, not fitted again
  int failed = 0;   // rows whose dataset failed to load or to fit

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("command", &command);
    a->Visit("shard", &shard);
    a->Visit("jobs", &jobs);
    a->Visit("seconds", &seconds);
    a->Visit("datasets", &datasets);
    a->Visit("campaign_datasets", &campaign_datasets);
    a->Visit("options", &options);
    a->Visit("resumed", &resumed);
    a->Visit("failed", &failed);
  }
};

// What a diagnose campaign's gap columns hold, under its table and in its
// page's figure.
inline constexpr char kCampaignGapMeaning[] =
    "gap: chi-square in excess of its degrees of freedom, max(0, chi-square - dof), 0 for a fit "
    "as good as the noise; before: the calibrated baseline's, after: with the effect of the "
    "verdict added; shrink: 1 - after / before";

// The campaign as a Markdown table, one row per dataset (shrink in %); a
// diagnose campaign's with kCampaignGapMeaning under it.
std::string CampaignTable(const CampaignBody& campaign);

template <ReportKind K, class Body>
struct Report {
  static constexpr ReportKind kKind = K;
  Provenance provenance;
  Body body;

  template <class Archive>
  void Serialize(Archive* a) {
    ReportKind kind = K;
    int version = kReportSchemaVersion;
    a->Visit("report", &kind);
    a->Visit("schema_version", &version);
    a->Visit("provenance", &provenance);
    body.Serialize(a);
  }
};

// Names: a *Result is what the library returns (IdentifyResult, ...); a
// *Report is the file written, that result in the envelope above.
using IdentifyReport = Report<ReportKind::kIdentify, DatasetBody<IdentifyResult>>;
using PredictReport = Report<ReportKind::kPredict, PredictBody>;
using IdentifiabilityReport =
    Report<ReportKind::kIdentifiability, DatasetBody<IdentifiabilityResult>>;
using CompareReport = Report<ReportKind::kCompare, DatasetBody<ComparisonResult>>;
using DiagnoseReport = Report<ReportKind::kDiagnose, DatasetBody<DiagnosisResult>>;
using CampaignReport = Report<ReportKind::kCampaign, CampaignBody>;
using ForcesReport = Report<ReportKind::kForces, DatasetBody<ForcesResult>>;

// The report as JSON text (two-space indent, a final newline). Strings that
// are not UTF-8 (paths from a command line) get U+FFFD, never an exception.
template <class R>
std::string ReportText(const R& report) {
  return JsonWriter::ToJson(report).dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

// The kind and version a JSON report says it is; false with a one-line
// error naming the field when it is not a ringid report of this schema.
bool ReportHeader(const Json& json, ReportKind* kind, std::string* error);

// Reads a report of kind R::kKind, every field strictly: a missing, mistyped
// or unknown field is an error naming its path.
template <class R>
bool ReadReport(const Json& json, R* report, std::string* error) {
  ReportKind kind;
  if (!ReportHeader(json, &kind, error)) return false;
  if (kind != R::kKind) {
    *error = std::string("report: a ") + ToString(kind) + " report, not " + ToString(R::kKind);
    return false;
  }
  error->clear();
  return JsonReader::FromJson(json, "", report, error);
}

}  // namespace ringid

#endif  // RINGID_REPORT_REPORT_H_
