// Typed reports: each kind the tool writes reads back into its struct and
// writes again byte for byte; the reader is strict; provenance is true.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <vector>
#include <string>

#include <gtest/gtest.h>

#include "apps/reports.h"
#include "apps/reference_doc.h"
#include "apps/schema_doc.h"
#include "datasets/frf_spec.h"
#include "datasets/obstacle.h"
#include "datasets/parameter_files.h"
#include "datasets/response_dataset.h"
#include "datasets/uff_dataset.h"
#include "estimation/fit.h"
#include "estimation/starts.h"
#include "model/effects.h"
#include "report/extract_report.h"
#include "report/schema.h"
#include "report/report.h"
#include "tests/round_trip.h"
#include "tests/test_support.h"

namespace {

using ringid::Json;
using ringid::testing::Exists;
using ringid::testing::ReadFile;
using ringid::testing::Ringid;
using ringid::testing::Scratch;

using ringid::testing::SourcePath;

template <class R>
void ExpectRoundTrip(const std::string& path) {
  ASSERT_TRUE(Exists(path));
  const std::string written = ReadFile(path);
  std::string error;
  const std::string again = ringid::testing::ReadAndWriteAgain<R>(written, &error);
  ASSERT_EQ(error, "") << path;
  EXPECT_EQ(again, written) << path;
}

std::string Made(const std::string& command, const std::string& out) {
  const std::string path = Scratch(out);
  std::remove(path.c_str());
  const auto r = Ringid(command + " --output=" + path);
  EXPECT_TRUE(r.status == 0 || r.status == 1) << command << ": " << r.err;
  return path;
}

TEST(ReportTest, IdentifyRoundTripsByteForByte) {
  ExpectRoundTrip<ringid::IdentifyReport>(
      Made("identify --dataset=" + SourcePath("datasets/paper/table1.json"), "identify.json"));
}

TEST(ReportTest, IdentifyWithShapesAndDampingRoundTripsByteForByte) {
  ExpectRoundTrip<ringid::IdentifyReport>(
      Made("identify --starts=1 --shape_convention=paper --dataset=" +
               SourcePath("datasets/paper/inertia_recovery.json"),
           "identify-shapes.json"));
}

// The provenance says how the Jacobians were taken, as the command asked.
TEST(ReportTest, ProvenanceRecordsTheDerivativeMode) {
  for (const char* mode : {"numeric", "analytic"}) {
    const Json j = Json::parse(ReadFile(Made(std::string("identify --starts=1 --derivatives=") +
                                                 mode + " --dataset=" +
                                                 SourcePath("datasets/paper/table1.json"),
                                             std::string("identify-") + mode + ".json")));
    EXPECT_EQ(j["provenance"]["derivatives"], mode);
  }
}

TEST(ReportTest, PredictRoundTripsByteForByte) {
  ExpectRoundTrip<ringid::PredictReport>(
      Made("predict --parameters=" + SourcePath("datasets/paper/parameters.json"), "predict.json"));
}

TEST(ReportTest, IdentifiabilityRoundTripsByteForByte) {
  ExpectRoundTrip<ringid::IdentifiabilityReport>(Made(
      "identifiability --starts=1 --derivatives=analytic --dataset=" + SourcePath("datasets/paper/table1.json"),
      "identifiability.json"));
}

TEST(ReportTest, CompareRoundTripsByteForByte) {
  ExpectRoundTrip<ringid::CompareReport>(
      Made("compare --starts=2 --dataset=" + SourcePath("datasets/paper/table1.json"),
           "compare.json"));
}

TEST(ReportTest, DiagnoseAndCampaignRoundTripByteForByte) {
  const std::string dir = Scratch("campaign-data");
  const std::string out = Scratch("campaign-reports");
  std::filesystem::create_directories(dir);
  const auto sim = Ringid("simulate --parameters=" + SourcePath("datasets/paper/parameters.json") +
                          " --effects=lug_coupling --shift=0.05 --output=" + dir +
                          "/lug.json --truth=" + Scratch("lug-truth.json"));
  ASSERT_EQ(sim.status, 0) << sim.err;
  const auto r = Ringid("diagnose --dataset=" + dir + " --output_dir=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  ExpectRoundTrip<ringid::DiagnoseReport>(out + "/lug.json");
  ExpectRoundTrip<ringid::CampaignReport>(out + "/campaign.json");
  // The fields of docs/conventions.md §6, written out by hand.
  const Json lug = Json::parse(ReadFile(out + "/lug.json"));
  for (const char* key : {"gap_before", "where", "ranking", "verdict"}) EXPECT_TRUE(lug.contains(key)) << key;
  for (const Json& w : lug["where"]) EXPECT_TRUE(w.contains("label") && w.contains("worst_component"));
  for (const Json& f : lug["ranking"]) {
    for (const char* key : {"effect", "gap_after", "shrink", "evidence"}) EXPECT_TRUE(f.contains(key)) << key;
  }
  EXPECT_EQ(lug["verdict"]["effect"], "lug_coupling");
  EXPECT_TRUE(lug["verdict"]["indistinguishable"].is_array());
  // Effects are read by name, "none" included; anything else is refused.
  Json diagnosis = Json::parse(ReadFile(out + "/lug.json"));
  ringid::DiagnoseReport report;
  std::string error;
  ASSERT_TRUE(ringid::ReadReport(diagnosis, &report, &error)) << error;
  EXPECT_EQ(report.body.result.verdict, ringid::FindEffect("lug_coupling"));
  diagnosis["verdict"]["effect"] = "none";
  ASSERT_TRUE(ringid::ReadReport(diagnosis, &report, &error)) << error;
  EXPECT_EQ(report.body.result.verdict, nullptr);
  diagnosis["verdict"]["effect"] = "wobble";
  EXPECT_FALSE(ringid::ReadReport(diagnosis, &report, &error));
  EXPECT_EQ(error.rfind("verdict.effect: unknown name 'wobble' (expected none, anisotropic_sidewall", 0),
            0u)
      << error;
}

TEST(ReportTest, TheProvenanceNamesEachInputWithItsSha256) {
  const std::string table1 = SourcePath("datasets/paper/table1.json");
  const std::string path = Made("identify --starts=1 --dataset=" + table1, "provenance.json");
  // sha256sum is an independent implementation of the digest.
  const std::string digest_file = Scratch("table1.sha256");
  ASSERT_EQ(std::system(("sha256sum '" + table1 + "' > " + digest_file).c_str()), 0);
  const std::string expected = ReadFile(digest_file).substr(0, 64);
  const Json report = Json::parse(ReadFile(path));
  const Json& p = report["provenance"];
  ASSERT_EQ(p["inputs"].size(), 1u);
  EXPECT_EQ(p["inputs"][0]["role"], "dataset");
  EXPECT_EQ(p["inputs"][0]["path"], table1);
  EXPECT_EQ(p["inputs"][0]["sha256"], expected);
  EXPECT_EQ(p["command_line"][1], "identify");
  EXPECT_EQ(p["seed"], 1);
  EXPECT_EQ(report["schema_version"], ringid::kReportSchemaVersion);
}

TEST(ReportTest, TheReaderNamesTheFieldThatIsWrong) {
  const Json good = Json::parse(ReadFile(Made(
      "identify --starts=1 --dataset=" + SourcePath("datasets/paper/table1.json"), "strict.json")));
  const struct {
    const char* what;
    std::function<void(Json*)> change;
    const char* error;
  } cases[] = {
      {"unknown field", [](Json* j) { (*j)["modes"][0]["extra"] = 1; }, "modes[0].extra: unknown key"},
      {"missing field", [](Json* j) { (*j)["covariance"].erase("rank"); }, "covariance.rank: missing"},
      {"wrong type", [](Json* j) { (*j)["cost"] = "low"; }, "cost: must be a number (found string)"},
      {"unknown label", [](Json* j) { (*j)["modes"][0]["label"] = "wobble"; },
       "modes[0].label: unknown name 'wobble'"},
      {"unknown parameter", [](Json* j) { (*j)["parameters"]["k_bq"] = (*j)["parameters"]["k_bx"]; },
       "parameters.k_bq: unknown name 'k_bq'"},
      {"other kind", [](Json* j) { (*j)["report"] = "predict"; }, "report: a predict report, not identify"},
      {"old schema", [](Json* j) { j->erase("schema_version"); }, "schema_version: missing"},
  };
  for (const auto& c : cases) {
    Json broken = good;
    c.change(&broken);
    ringid::IdentifyReport report;
    std::string error;
    EXPECT_FALSE(ringid::ReadReport(broken, &report, &error)) << c.what;
    EXPECT_EQ(error.rfind(c.error, 0), 0u) << c.what << ": " << error;
  }
}

TEST(ReportTest, AFailedRenamePutsBackTheFilesRenamedBeforeIt) {
  const std::string dir = Scratch("rollback");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir + "/blocked");
  const std::string first = dir + "/first.json";
  std::ofstream(first) << "old";
  // The second target is a non-empty directory: its temporary file is
  // written, but the rename onto it fails.
  std::ofstream(dir + "/blocked/keep") << "x";
  std::string error;
  EXPECT_FALSE(ringid::WriteFilesAtomically({{first, "new"}, {dir + "/blocked", "b"}}, &error));
  EXPECT_NE(error.find("blocked"), std::string::npos) << error;
  EXPECT_EQ(ReadFile(first), "old");
  const std::string fresh = dir + "/fresh.json";
  EXPECT_FALSE(ringid::WriteFilesAtomically({{fresh, "new"}, {dir + "/blocked", "b"}}, &error));
  EXPECT_FALSE(Exists(fresh));
  int entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 2) << "temporary or backup files were left behind";
}

// Every field path of `j` under `path`, arrays as "[]".
void Paths(const Json& j, const std::string& path, std::vector<std::string>* out) {
  if (j.is_object()) {
    for (const auto& [key, value] : j.items()) {
      const std::string p = path.empty() ? key : path + "." + key;
      out->push_back(p);
      Paths(value, p, out);
    }
  } else if (j.is_array()) {
    for (const Json& item : j) {
      if (item.is_object()) Paths(item, path + "[]", out);
    }
  }
}

// Whether `path` is documented in `schema`, a keyed segment read as <name>
// or <key>.
bool Documented(const std::string& schema, const std::string& path) {
  if (schema.find("- `" + path + "`:") != std::string::npos) return true;
  for (size_t dot = path.find('.'); dot != std::string::npos; dot = path.find('.', dot + 1)) {
    if (path[dot + 1] == '<') continue;  // read as a key already
    const size_t end = path.find_first_of(".[", dot + 1);
    for (const char* key : {"<name>", "<key>"}) {
      const std::string keyed = path.substr(0, dot + 1) + key +
                                (end == std::string::npos ? "" : path.substr(end));
      if (keyed != path && Documented(schema, keyed)) return true;
    }
  }
  return false;
}

TEST(ReportTest, TheSchemaDocumentsEveryFieldAReportWrites) {
  const std::string identify = Made("identify --starts=1 --shape_convention=paper --dataset=" +
                                        SourcePath("datasets/paper/inertia_recovery.json"),
                                    "schema-identify.json");
  const std::string compare =
      Made("compare --starts=2 --dataset=" + SourcePath("datasets/paper/table1.json"), "schema-compare.json");
  const std::string predict =
      Made("predict --parameters=" + SourcePath("datasets/paper/parameters.json"), "schema-predict.json");
  const struct {
    std::string path;
    std::string schema;
  } reports[] = {{identify, ringid::ReportSchema<ringid::IdentifyReport>()},
                 {compare, ringid::ReportSchema<ringid::CompareReport>()},
                 {predict, ringid::ReportSchema<ringid::PredictReport>()}};
  for (const auto& r : reports) {
    std::vector<std::string> paths;
    Paths(Json::parse(ReadFile(r.path)), "", &paths);
    ASSERT_GT(paths.size(), 20u) << r.path;
    for (const std::string& p : paths) EXPECT_TRUE(Documented(r.schema, p)) << r.path << ": " << p;
  }
  // A path the report does not have is not documented by accident.
  EXPECT_FALSE(Documented(reports[0].schema, "modes[].frequency"));
}

// Measured FRFs: each function's chi2, FRAC and curves (`frfs`, schema 9)
// round trip, and every path they write is documented.
TEST(ReportTest, IdentifyOfFrfsRoundTripsByteForByteAndIsDocumented) {
  const std::string path =
      Made("identify --starts=1 --derivatives=analytic --band=10,150 --dataset=" +
               SourcePath("datasets/examples/car_tire_hammer_frf.json"),
           "identify-frf.json");
  ExpectRoundTrip<ringid::IdentifyReport>(path);
  const Json j = Json::parse(ReadFile(path));
  ASSERT_EQ(j["frfs"].size(), 28u);
  EXPECT_EQ(j["frfs"][0]["lines"], 71);  // 10, 12, ..., 150 Hz
  std::vector<std::string> paths;
  Paths(j, "", &paths);
  const std::string schema = ringid::ReportSchema<ringid::IdentifyReport>();
  for (const std::string& p : paths) EXPECT_TRUE(Documented(schema, p)) << p;
}

// extract --report (schema 11): the diagram, the poles and each function's
// curves round trip, and every path they write is documented; a pole's
// standard errors too, where an estimator gives them.
TEST(ReportTest, ExtractRoundTripsByteForByteAndIsDocumented) {
  const std::string path = Scratch("extract-report.json");
  std::remove(path.c_str());
  const auto r = Ringid("extract --dataset=" + SourcePath("datasets/examples/car_tire_hammer_frf.json") +
                        " --output=" + Scratch("extract-report-modes.json") + " --report=" + path);
  ASSERT_EQ(r.status, 0) << r.err;
  ExpectRoundTrip<ringid::ExtractReport>(path);
  const Json j = Json::parse(ReadFile(path));
  EXPECT_EQ(j["report"], "extract");
  ASSERT_EQ(j["conditions"].size(), 1u);
  EXPECT_EQ(j["conditions"][0]["functions"].size(), 28u);
  ASSERT_EQ(j["conditions"][0]["blocks"].size(), 1u);  // every output at every input
  EXPECT_EQ(j["conditions"][0]["blocks"][0]["inputs"].size(), 4u);
  EXPECT_EQ(j["conditions"][0]["blocks"][0]["outputs"].size(), 7u);
  EXPECT_EQ(j["conditions"][0]["blocks"][0]["diagram"].size(), 30u);  // orders 1 to --max_model_order
  std::vector<std::string> paths;
  Paths(j, "", &paths);
  const std::string schema = ringid::ReportSchema<ringid::ExtractReport>();
  for (const std::string& p : paths) EXPECT_TRUE(Documented(schema, p)) << p;
  ringid::ExtractReport report;
  std::string error;
  ASSERT_TRUE(ringid::ReadReport(j, &report, &error)) << error;
  ASSERT_FALSE(report.body.poles.empty());
  report.body.poles[0].frequency_sigma_hz = 0.01;
  report.body.poles[0].damping_sigma = 0.001;
  ringid::testing::ExpectRoundTrip(report);
  const Json sigmas = ringid::JsonWriter::ToJson(report);
  EXPECT_EQ(sigmas["poles"][0]["frequency_sigma_hz"], 0.01);
  EXPECT_TRUE(Documented(schema, "poles[].frequency_sigma_hz"));
  EXPECT_TRUE(Documented(schema, "poles[].damping_sigma"));
}

TEST(ReportTest, DocsReportsMdIsTheGeneratedSchema) {
  EXPECT_EQ(ReadFile(SourcePath("docs/reports.md")), ringid::ReportsMarkdown())
      << "run: build/ringid schema > docs/reports.md";
}

TEST(ReportTest, DocsInputsMdIsTheGeneratedFieldList) {
  EXPECT_EQ(ReadFile(SourcePath("docs/inputs.md")), ringid::InputsMarkdown())
      << "run: build/ringid inputs > docs/inputs.md";
}

// Each input file's section gives the `format` to write, the string its
// reader checks (it said "string", or "derived from the fields above").
TEST(ReportTest, DocsInputsMdGivesEachFilesFormatToWrite) {
  const std::string md = ringid::InputsMarkdown();
  const std::vector<std::string> formats = {
      ringid::kDatasetFormat1, ringid::kDatasetFormat2, ringid::kDatasetFormat3, ringid::kParameterSetFormat,
      ringid::kTruthFormat,    ringid::kResponseFormat, ringid::kLugForcesFormat,
      ringid::kUffMapFormat,   ringid::kUffMapFormat2, ringid::kFrfSpecFormat,
      ringid::kObstacleSpecFormat, ringid::kLugProfileFormat};
  size_t lines = 0;
  for (size_t at = md.find("- `format`: "); at != std::string::npos;
       at = md.find("- `format`: ", at + 1)) {
    ++lines;
  }
  EXPECT_EQ(lines, formats.size()) << md;
  for (const std::string& f : formats) {
    EXPECT_NE(md.find("- `format`: `\"" + f + "\"` (this string exactly)\n"), std::string::npos)
        << f;
  }
}

TEST(ReportTest, DocsReferenceMdIsTheGeneratedReference) {
  EXPECT_EQ(ReadFile(SourcePath("docs/reference.md")), ringid::ReferenceMarkdown())
      << "run: build/ringid reference > docs/reference.md";
}

// docs/development.md states figures of the code: each is said as built here
// from its constant (whitespace and line breaks aside), so that changing the
// constant without the text fails. It had said 0.001 for kStopChiSquare
// (1e-4) and schema 4 (5).
std::string Figure(double v) {  // 1e+12 as 1e12
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  std::string s = text;
  const size_t e = s.find("e+");
  if (e != std::string::npos) s.erase(e + 1, s.find_first_not_of("+0", e + 1) - e - 1);
  return s;
}
std::string Word(int n) {
  const char* words[] = {"zero", "one", "two", "three", "four", "five", "six",
                         "seven", "eight", "nine", "ten", "eleven", "twelve"};
  return n >= 0 && n <= 12 ? words[n] : std::to_string(n);
}

TEST(ReportTest, DocsDevelopmentMdStatesTheCodesFigures) {
  using namespace ringid;  // NOLINT
  std::string doc;
  for (const char c : ReadFile(SourcePath("docs/development.md"))) {
    if (!std::isspace(static_cast<unsigned char>(c))) {
      doc += c;
    } else if (!doc.empty() && doc.back() != ' ') {
      doc += ' ';
    }
  }
  const std::string sizes = ReadFile(SourcePath("scripts/check_sizes.py"));
  const auto script = [&](const std::string& name) {  // "NAME = VALUE" on a line of its own
    const size_t at = sizes.find("\n" + name + " = ");
    if (at == std::string::npos) return std::string("(no " + name + ")");
    const size_t from = at + name.size() + 4;
    return sizes.substr(from, sizes.find('\n', from) - from);
  };
  const IdentifyOptions identify;
  const UncertaintyOptions uncertainty;
  const std::string stop = Figure(kStopChiSquare);
  const std::vector<std::string> says = {
      "`schema_version` (" + std::to_string(kReportSchemaVersion) + ", `kReportSchemaVersion`)",
      "Schema " + std::to_string(kReportSchemaVersion) + " (",  // what the current one changed
      "less than " + stop + " in χ² (`kStopChiSquare`)",
      "the last " + std::to_string(internal::kShrinkingGains) + " successful steps",
      "each at most " + Figure(internal::kGainShrink) + " times the one before",
      "at least " + Figure(internal::kSlowestShrink) + ", `kSlowestShrink`) adds up to less than " +
          stop + " in χ²",
      "tolerances of " + Figure(internal::kCeresTolerance) + " (`kCeresTolerance`)",
      "(" + std::to_string(identify.starts) + " by default,",
      "at least " + Figure(internal::kOwnership) + " per row, `kOwnership`",
      "up to " + Word(internal::kMatchRounds) + " times (`kMatchRounds`)",
      "within a factor " + Figure(identify.start_factor) + " (`IdentifyOptions::start_factor`)",
      "bounds of a factor " + Figure(identify.bound_factor) + " around the start "
          "(`IdentifyOptions::bound_factor`",
      "(within " + Figure(kSameOptimumChiSquare) + ", `kSameOptimumChiSquare`)",
      "for at most " + std::to_string(internal::kDirectIterations) +
          " iterations (`kDirectIterations`",
      "(p ≥ " + Figure(kPoorFitP) + " on the residuals less the free coordinates",
      "more than " + Figure(100 * kStartsDisagree) + " % (`kStartsDisagree`",
      "is above " + Figure(uncertainty.practical_relative_std) +
          " (`UncertaintyOptions::practical_relative_std`)",
      "wider than a factor of " + Figure(std::round(uncertainty.PracticalBand(true).second)) +
          " either way",
      "over " + Word(kNumDofs) + " degrees of freedom",
      "The " + Word(static_cast<int>(EffectCatalogue().size())) + " effects",
      "files up to " + std::to_string(kMaxFileBytes >> 20) + " MiB",
      "nested at most " + std::to_string(kMaxJsonDepth) + " deep",
      "at most " + std::to_string(kMaxModes) + " modes",
      "at most " + std::to_string(kNumDofs) + " shape components",
      "outside " + Figure(kMinModeFrequencyHz) + "–" + Figure(kMaxModeFrequencyHz) + " Hz",
      "beyond " + Figure(kMaxParameterMagnitude) + " in magnitude",
      "generates " + std::to_string(ringid::testing::MalformedDatasets().size()) + " malformed",
      "over " + script("MAX_FILE_LINES") + " lines and no function body over " +
          script("MAX_FUNCTION_LINES"),
  };
  for (const std::string& text : says) {
    EXPECT_NE(doc.find(text), std::string::npos) << "docs/development.md should say: " << text;
  }
}

// The fields docs/conventions.md §6 promises other people's scripts, written
// out here by hand, found in reports the tool writes.
TEST(ReportTest, ReportsCarryTheFieldsOfTheContract) {
  const auto has = [](const Json& j, const std::vector<std::string>& keys, const std::string& what) {
    for (const std::string& k : keys) EXPECT_TRUE(j.contains(k)) << what << ": " << k;
  };
  const Json identify = Json::parse(ReadFile(Made("identify --starts=1 --shape_convention=paper --dataset=" +
                                                      SourcePath("datasets/paper/inertia_recovery.json"),
                                                  "contract-identify.json")));
  has(identify, {"method", "converged", "cost", "evaluations", "seconds", "parameters", "covariance", "modes"},
      "identify");
  for (const auto& [name, p] : identify["parameters"].items()) {
    has(p, {"value", "free", "std", "identifiable"}, "identify parameters." + name);
    EXPECT_TRUE(p["identifiable"] == "yes" || p["identifiable"] == "practically_no" || p["identifiable"] == "no");
  }
  has(identify["covariance"], {"names", "matrix", "rank"}, "identify covariance");
  for (const Json& m : identify["modes"]) has(m, {"label", "measured_hz", "model_hz", "mac"}, "identify modes");

  const Json predict = Json::parse(
      ReadFile(Made("predict --parameters=" + SourcePath("datasets/paper/parameters.json"), "contract-predict.json")));
  ASSERT_EQ(predict["modes"].size(), 7u);
  for (const Json& m : predict["modes"]) {
    has(m, {"label", "plane", "model_hz", "damping_ratio", "shape"}, "predict modes");
    EXPECT_FALSE(m["shape"].empty());
    for (const auto& [dof, value] : m["shape"].items()) EXPECT_TRUE(ringid::ParseDof(dof)) << dof;
  }

  const Json identifiability = Json::parse(ReadFile(
      Made("identifiability --starts=1 --derivatives=analytic --dataset=" + SourcePath("datasets/paper/table1.json"), "contract-ident.json")));
  has(identifiability, {"rank", "condition_number", "singular_values", "parameters", "combinations"},
      "identifiability");
  for (const auto& [name, p] : identifiability["parameters"].items()) {
    has(p, {"identifiable", "reason", "std", "wald_95", "profile_95"}, "identifiability parameters." + name);
  }
  ASSERT_FALSE(identifiability["combinations"].empty());
  for (const Json& c : identifiability["combinations"]) has(c, {"text", "singular_value"}, "combinations");

  const Json compare = Json::parse(ReadFile(
      Made("compare --starts=2 --dataset=" + SourcePath("datasets/paper/table1.json"), "contract-compare.json")));
  for (const char* method : {"lm", "simplex"}) {
    has(compare["methods"][method], {"starts", "success_rate", "final_costs", "evaluations", "seconds_per_fit"},
        std::string("compare ") + method);
  }
}

}  // namespace
