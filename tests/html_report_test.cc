// ringid report: every kind of JSON report as one self-contained HTML page
// with its figures drawn by gnuplot; the error contract (exit status,
// docs/conventions.md §6); each page in Chromium: a screenshot, and its
// figures whole in the parsed DOM.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <iostream>
#include <map>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "datasets/response_dataset.h"
#include "datasets/synthetic.h"
#include "model/forced_response.h"
#include "estimation/statistics.h"
#include "model/rigid_ring_model.h"
#include "tests/browser_check.h"
#include "apps/html/pages.h"
#include "report/report.h"
#include "validation/extract_suite.h"
#include "validation/suites.h"
#include "tests/test_support.h"

namespace {

using json = ringid::Json;
using ringid::testing::Chromium;
using ringid::testing::Exists;
using ringid::testing::ReadFile;
using ringid::testing::Ringid;
using ringid::testing::RunResult;
using ringid::testing::Scratch;

using ringid::testing::SourcePath;

bool HaveGnuplot() { return ringid::testing::HaveProgram("gnuplot"); }

// `command` through the shell; exit status and stderr.
RunResult Shell(const std::string& command) {
  const std::string err = Scratch("shell_stderr.txt");
  const int raw = std::system((command + " > /dev/null 2> " + err).c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, ReadFile(err)};
}

int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t i = text.find(what); i != std::string::npos; i = text.find(what, i + 1)) ++n;
  return n;
}

json ReadJson(const std::string& path) {
  std::ifstream in(path);
  return json::parse(in);
}

// A page: the report it was made from and its HTML.
struct Made {
  std::string report_path;
  json report;
  std::string html_path;
  std::string html;
};

// Renders `report_path` (already written) with `ringid report`.
Made Render(const std::string& report_path) {
  Made m;
  m.report_path = report_path;
  m.report = ReadJson(report_path);
  m.html_path = report_path + ".html";
  std::remove(m.html_path.c_str());
  const RunResult r = Ringid("report --input=" + report_path + " --output=" + m.html_path);
  EXPECT_EQ(r.status, 0) << r.err;
  m.html = ReadFile(m.html_path);
  return m;
}

// Runs `ringid ARGS --output=NAME.json` (in the source tree for bench) and
// renders the report.
Made Make(const std::string& name, const std::string& args, bool in_source = false) {
  const std::string out = Scratch(name + ".json");
  std::remove(out.c_str());
  const std::string command = (in_source ? "cd " + SourcePath("") + " && " : std::string()) +
                              RINGID_BINARY + " " + args + " --output=" + out;
  const RunResult r = Shell(command);
  EXPECT_EQ(r.status, 0) << command << ": " << r.err;
  return Render(out);
}

// A dataset simulated from the paper's parameters (full modal data).
std::string Simulate(const std::string& name, const std::string& extra = "") {
  const std::string out = Scratch(name + ".json");
  const RunResult r =
      Ringid("simulate --parameters=" + SourcePath("datasets/paper/parameters.json") +
             " --seed=3 --set=m_a=15 " + extra + " --output=" + out + " --truth=" +
             Scratch("truth_" + std::to_string(std::hash<std::string>()(name)) + ".json"));
  EXPECT_EQ(r.status, 0) << r.err;
  return out;
}

// What every page must be: one document, self-contained, figures whole and
// numbered, each with a caption.
void ExpectWellFormed(const std::string& html, int figures) {
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("</html>"), std::string::npos);
  EXPECT_EQ(Count(html, "<svg"), figures);
  EXPECT_EQ(Count(html, "</svg>"), figures);
  EXPECT_EQ(Count(html, "<figcaption>"), figures);
  for (int i = 1; i <= figures; ++i) {
    EXPECT_NE(html.find("Figure " + std::to_string(i) + "."), std::string::npos) << i;
  }
  EXPECT_EQ(html.find("<?xml"), std::string::npos);
  EXPECT_EQ(html.find("<!DOCTYPE svg"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  // The only URLs are the SVG and XLink namespaces.
  for (const std::string scheme : {"http://", "https://"}) {
    for (size_t i = html.find(scheme); i != std::string::npos; i = html.find(scheme, i + 1)) {
      const std::string url = html.substr(i, 40);
      EXPECT_TRUE(url.rfind("http://www.w3.org/2000/svg", 0) == 0 ||
                  url.rfind("http://www.w3.org/1999/xlink", 0) == 0)
          << url;
    }
  }
}

// The text of the SVG figures only.
std::string Figures(const std::string& html) {
  std::string out;
  for (size_t i = html.find("<svg"); i != std::string::npos; i = html.find("<svg", i + 1)) {
    out += html.substr(i, html.find("</svg>", i) - i);
  }
  return out;
}

// Mode labels as the figures show them.
std::string Shown(std::string label) {
  std::replace(label.begin(), label.end(), '_', ' ');
  return label;
}

// ------------------------------------------------------------ the pages

Made IdentifyPaper() {
  return Make("identify", "identify --dataset=" + SourcePath("datasets/paper/table1.json"));
}

Made IdentifyShapes() {
  return Make("identify_shapes", "identify --starts=1 --dataset=" +
                                     Simulate("shapes", "--static=vertical,lateral"));
}

// The shipped hammer test (28 FRFs) identified from its initial values, one
// start; made once per process.
Made IdentifyFrf() {
  static const Made made =
      Make("identify_frf", "identify --starts=1 --derivatives=analytic --dataset=" +
                               SourcePath("datasets/examples/car_tire_hammer_frf.json"));
  return made;
}

Made Identifiability() {
  return Make("identifiability",
              "identifiability --starts=1 --derivatives=analytic --dataset=" + Simulate("profiled"));
}

Made Compare() {
  return Make("compare", "compare --starts=3 --dataset=" + SourcePath("datasets/paper/table1.json"));
}

Made Diagnose() {
  return Make("diagnose",
              "diagnose --dataset=" + Simulate("lug", "--effects=lug_coupling --shift=0.05"));
}

Made Predict() {
  return Make("predict", "predict --parameters=" + SourcePath("datasets/paper/parameters.json"));
}

// Forces from a response at 6 and 12 m/s (orders 1-3, every channel, 10 %
// noise) of the paper's tire, with the parameters and covariance of an
// identification on the drum.
Made Forces() {
  using namespace ringid;  // NOLINT: the library's types, in this one maker
  const std::string data = Simulate("forces_modes", "--speeds=0,6,12");
  const Made fit = Make("forces_fit", "identify --starts=1 --derivatives=analytic --dataset=" + data);
  ResponseDataset d;
  d.name = "drum";
  std::mt19937_64 rng(4);
  std::string why;
  EXPECT_TRUE(SimulateResponses(
      RigidRingModel(), ringid::testing::PaperIdentified(), 20, {6, 12}, 3,
      {AxleChannel::kForceX, AxleChannel::kForceZ, AxleChannel::kForceY, AxleChannel::kMomentX,
       AxleChannel::kMomentZ},
      [](int k) { return std::array<Complex, kNumLugForces>{300.0 / k, 900.0 / k, 150.0 / k}; },
      0.1, &rng, &d, &why))
      << why;
  const std::string response = Scratch("forces_response.json");
  std::ofstream(response) << ResponseDatasetToJson(d);
  return Make("forces", "forces --parameters=" + fit.report_path + " --dataset=" + response);
}

// The paper's tire from 2 to 12 m/s with 20 lugs per revolution.
Made PredictAtSpeeds() {
  return Make("predict_speeds", "predict --parameters=" + SourcePath("datasets/paper/parameters.json") +
                                    " --speeds=2,3,4,5,6,7,8,9,10,11,12 --lugs_per_revolution=20");
}

Made Campaign() {
  const std::string dir = Scratch("campaign");
  ::mkdir(dir.c_str(), 0700);
  const std::string dataset = Simulate("campaign/case000", "--effects=lug_coupling --shift=0.05");
  const std::string reports = Scratch("campaign_reports");
  const RunResult r = Ringid("diagnose --dataset=" + dir + " --output_dir=" + reports);
  EXPECT_EQ(r.status, 0) << r.err;
  return Render(reports + "/campaign.json");
}

// A format-2 dataset (docs/conventions.md §7): the example car tire standing
// and rolling on a drum at 6 m/s, simulated with the knowns and starting
// values `ringid simulate` gives. With priors: a tight one on r_e0 (the prior
// decides it) and a wide one on k_bx (the data do).
std::string RollingDataset(const std::string& name, bool priors) {
  using ringid::Param;
  const ringid::Parameters truth = ringid::ExampleCarTire();
  ringid::Dataset d;
  d.name = name;
  d.format = 2;
  d.conditions = {{"standing", 0.0, {}, {}}, {"drum_6", 6.0, {}, {}}};
  std::mt19937_64 rng(7);
  ringid::SetEngineerPriors(truth, 0.1, &rng, &d);
  if (priors) {
    d.priors[Param::r_e0] = {ringid::PriorDistribution::kLognormal, truth[Param::r_e0], 1.001};
    d.priors[Param::k_bx] = {ringid::PriorDistribution::kLognormal, truth[Param::k_bx], 100};
  }
  std::string why;
  EXPECT_TRUE(ringid::Simulate(ringid::RigidRingModel(), truth, ringid::SimulateOptions{}, &rng,
                               &d, &why))
      << why;
  const std::string path = Scratch(name + "_dataset.json");
  std::ofstream(path) << ringid::DatasetToJson(d);
  return path;
}

// That dataset identified (one start) and rendered; made once per process.
Made IdentifyRolling(bool priors = false) {
  static std::map<bool, Made> made;
  const auto it = made.find(priors);
  if (it != made.end()) return it->second;
  const std::string name = priors ? "identify_rolling_priors" : "identify_rolling";
  return made[priors] =
             Make(name, "identify --starts=1 --dataset=" + RollingDataset(name, priors));
}

Made Bench(const std::string& suite) {
  return Make("bench_" + suite, "bench --suite=" + suite + " --replicates=2", true);
}

// The diagnosis suite takes minutes; a report of its kind for two withheld
// effects, written as the suite writes it.
Made BenchDiagnosis() {
  ringid::DiagnosisSuite suite;
  suite.accuracy = 0.75;
  suite.named = 1;
  suite.no_effect_cases = 2;
  suite.absorbed_and_explained = 1;
  suite.mean_shrink_when_named = 1.0;
  suite.seconds_per_diagnosis = 1.5;
  suite.effects = {"none", "hub_compliance", "lug_coupling"};
  suite.confusion = {{"none", {{"none", 2}}},
                     {"hub_compliance", {{"none", 1}, {"hub_compliance", 3}}},
                     {"lug_coupling", {{"lug_coupling", 4}}}};
  ringid::DiagnosisCase c;
  c.name = "none-0";
  c.truth = c.verdict = "none";
  c.correct = true;
  c.gap_p_value = 0.9;
  c.seconds = 1.2;
  suite.cases.push_back(c);
  const std::string path = Scratch("bench_diagnosis.json");
  std::ofstream(path) << ringid::ReportText(ringid::BenchDiagnosisReport{{}, suite});
  return Render(path);
}

// The frf suite takes an hour; a report of its kind, one tire per variant,
// written as the suite writes it.
Made BenchFrf() {
  ringid::FrfSuite suite;
  suite.start_factor = 3;
  suite.starts = 6;
  suite.frf_noise = 0.02;
  for (const char* name : {"standing", "standing_drum"}) {
    ringid::FrfVariant v;
    v.name = name;
    v.tires = v.best_found = v.masses_within = 1;
    v.intervals = 20;
    v.coverage_95 = 0.95;
    v.seconds_per_fit = 2.5;
    ringid::StaticParameter k;
    k.param = ringid::Param::k_bx;
    k.yes = k.intervals = 1;
    k.coverage_95 = 1;
    v.parameters.push_back(k);
    suite.variants.push_back(v);
  }
  const std::string path = Scratch("bench_frf.json");
  std::ofstream(path) << ringid::ReportText(ringid::BenchFrfReport{{}, suite});
  return Render(path);
}

// The extract suite fits every tire's FRFs to name its modes (seconds each);
// a report of its kind, two tires per variant, written as the suite writes it.
Made BenchExtract() {
  ringid::ExtractSuite suite;
  suite.start_factor = 3;
  suite.frf_noise = 0.02;
  for (const char* name : {"standing", "close_pair"}) {
    ringid::ExtractVariant v;
    v.name = name;
    v.tires = 2;
    v.modes = v.found = v.frequency_within = v.damping_within = 14;
    v.worst_frequency = 0.004;
    v.worst_damping = 0.08;
    v.intervals = 14;
    v.frequency_covered = v.damping_covered = 13;
    v.frequency_bias_sd = 0.1;
    v.damping_bias_sd = -0.2;
    v.seconds_per_tire = 3.5;
    v.frequency_misses_expected = 0.4;
    v.damping_misses_expected = 0.2;
    v.misses = {{1, "yaw", 53.14, 0.0595, 54.2, 0.1509, 0.14, 0.0023},
                {0, "lateral", 63.29, 0.0411, std::nullopt, std::nullopt, std::nullopt, std::nullopt}};
    suite.variants.push_back(v);
  }
  const std::string path = Scratch("bench_extract.json");
  std::ofstream(path) << ringid::ReportText(ringid::BenchExtractReport{{}, suite});
  return Render(path);
}

// extract of a drum at 10 m/s (datasets/examples/drum_spec.json: two
// blocks, two stabilisation diagrams, a real pole), its --report; made once.
Made ExtractDrum() {
  static const Made made = [] {
    const std::string dataset = Scratch("extract_drum_frf.json"), out = Scratch("extract_drum.json");
    std::remove(out.c_str());
    const RunResult sim = Ringid("simulate --parameters=" + SourcePath("datasets/examples/car_tire.json") +
                                 " --frf=" + SourcePath("datasets/examples/drum_spec.json") +
                                 " --speeds=10 --output=" + dataset + " --truth=" +
                                 Scratch("extract_drum_truth.json"));
    EXPECT_EQ(sim.status, 0) << sim.err;
    const RunResult r = Ringid("extract --dataset=" + dataset + " --output=" +
                               Scratch("extract_drum_modes.json") + " --report=" + out);
    EXPECT_EQ(r.status, 0) << r.err;
    return Render(out);
  }();
  return made;
}

// extract of the example hammer test (28 FRFs, 2 % noise), its --report;
// made once.
Made Extract() {
  static const Made made = [] {
    const std::string out = Scratch("extract.json");
    std::remove(out.c_str());
    const RunResult r =
        Ringid("extract --dataset=" + SourcePath("datasets/examples/car_tire_hammer_frf.json") +
               " --output=" + Scratch("extract_modes.json") + " --report=" + out);
    EXPECT_EQ(r.status, 0) << r.err;
    return Render(out);
  }();
  return made;
}

// poles of the example hammer file with its map (the file's coherence: sigma
// given), its --report; made once.
Made Poles() {
  static const Made made = [] {
    const std::string out = Scratch("poles_report.json");
    std::remove(out.c_str());
    const RunResult r =
        Ringid("poles --uff=" + SourcePath("datasets/examples/car_tire_hammer.uff") + " --map=" +
               SourcePath("datasets/examples/car_tire_hammer_map.json") + " --output=" +
               Scratch("poles.json") + " --report=" + out);
    EXPECT_EQ(r.status, 0) << r.err;
    return Render(out);
  }();
  return made;
}

// The speed suite, timed briefly in process (the command times each case for
// about half a second) and written as the suite writes it; made once.
Made BenchSpeed() {
  static const Made made = [] {
    ringid::SuiteOptions o;
    o.source_dir = RINGID_SOURCE_DIR;
    o.speed_batches = 3;
    o.speed_seconds_per_case = 0.01;
    ringid::SpeedSuite suite;
    const ringid::Status s = ringid::RunSpeedSuite(o, &suite);
    EXPECT_TRUE(s.ok()) << s.message;
    const std::string path = Scratch("bench_speed.json");
    std::ofstream(path) << ringid::ReportText(ringid::BenchSpeedReport{{}, suite});
    return Render(path);
  }();
  return made;
}

// `made`'s report changed by `change`, written beside it and rendered.
Made Changed(const Made& made, const std::string& name, const std::function<void(json*)>& change) {
  json report = made.report;
  change(&report);
  const std::string path = Scratch(name + ".json");
  std::ofstream(path) << report.dump(2);
  return Render(path);
}

// --------------------------------------------------------------- tests

TEST(HtmlReportTest, IdentifyOfThePaperDrawsTheFrequencies) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = IdentifyPaper();
  // Table 1 has no shapes and leaves 9 directions free (rank 7 of 16): no
  // MAC and no standard deviation, so only the frequency figure.
  for (const json& mode : m.report["modes"]) ASSERT_TRUE(mode["mac_all"].empty());
  ExpectWellFormed(m.html, 1);
  EXPECT_NE(m.html.find("No MAC figure"), std::string::npos);
  EXPECT_NE(m.html.find("No interval figure"), std::string::npos);
  const std::string svg = Figures(m.html);
  ASSERT_EQ(m.report["modes"].size(), 7u);
  for (const json& mode : m.report["modes"]) {
    EXPECT_NE(m.html.find(mode["label"].get<std::string>()), std::string::npos);
    EXPECT_NE(svg.find(">" + Shown(mode["label"]) + "<"), std::string::npos) << mode["label"];
  }
  for (const auto& [name, p] : m.report["parameters"].items()) {
    EXPECT_NE(m.html.find("<td>" + name + "</td>"), std::string::npos) << name;
  }
  EXPECT_NE(svg.find("frequency (Hz)"), std::string::npos);
  EXPECT_NE(svg.find("model − measured (Hz)"), std::string::npos);
}

TEST(HtmlReportTest, IdentifyWithShapesDrawsMacAndIntervals) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = IdentifyShapes();
  int with_std = 0;
  for (const auto& [name, p] : m.report["parameters"].items()) {
    with_std += p["free"].get<bool>() && p["std"].is_number();
  }
  ASSERT_GT(with_std, 0);
  ExpectWellFormed(m.html, 3);
  const std::string svg = Figures(m.html);
  // Every MAC of the first mode is printed in its cell, to two decimals.
  const json& mac = m.report["modes"][0]["mac_all"];
  ASSERT_FALSE(mac.empty());
  for (const auto& [label, value] : mac.items()) {
    char cell[16];
    std::snprintf(cell, sizeof cell, "%.2f", value.get<double>());
    EXPECT_NE(svg.find(std::string(">") + cell + "<"), std::string::npos) << label << " " << cell;
  }
  for (const auto& [name, p] : m.report["parameters"].items()) {
    if (p["free"].get<bool>() && p["std"].is_number()) {
      EXPECT_NE(svg.find(">" + name + "<"), std::string::npos) << name;
    }
  }
  EXPECT_NE(svg.find("interval / value (log scale)"), std::string::npos);
  // The static stiffnesses, measured against fitted, in their own table.
  ASSERT_EQ(m.report["measurements"].size(), 2u);
  for (const json& s : m.report["measurements"]) {
    EXPECT_NE(m.html.find("<td>" + s["name"].get<std::string>() + "</td>"), std::string::npos)
        << s["name"];
  }
}

TEST(HtmlReportTest, IdentifiabilityDrawsSpectrumCorrelationAndProfiles) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = Identifiability();
  ExpectWellFormed(m.html, 3);
  const std::string svg = Figures(m.html);
  for (const auto& [name, p] : m.report["parameters"].items()) {
    EXPECT_NE(m.html.find("<td>" + name + "</td>"), std::string::npos) << name;
    if (p["profile"]["curve_value_delta_chi2"].size() >= 2) {  // a panel titled with its name
      EXPECT_NE(svg.find(">" + name + "<"), std::string::npos) << name;
    }
  }
  // ringid's profiles are in Δχ² = 2 Δcost, with the 95 % threshold 3.84.
  EXPECT_NE(svg.find("Δχ² = 2 Δcost"), std::string::npos);
  EXPECT_NE(m.html.find("threshold 3.84"), std::string::npos);
  EXPECT_NE(svg.find("rank " + std::to_string(m.report["rank"].get<int>()) + " of " +
                     std::to_string(m.report["coordinates"].size())),
            std::string::npos);
}

// A side that ends at a jump (estimation/identifiability.h) is said as one
// in the interval's cell, not shown as a bound nor as "open".
TEST(HtmlReportTest, IdentifiabilitySaysAJumpBesideTheBound) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made made = Identifiability();
  ASSERT_TRUE(made.report["parameters"].is_object());
  const std::string name = made.report["parameters"].begin().key();
  const Made m = Changed(made, "identifiability_jump", [&](json* r) {
    json& p = (*r)["parameters"][name];
    p["profile"]["lower"] = nullptr;
    p["profile"]["lower_jump_at"] = 12340.0;
    p["profile_95"][0] = nullptr;
  });
  EXPECT_NE(m.html.find("[jumps to another optimum at 1.234e+04, "), std::string::npos)
      << name;
}

TEST(HtmlReportTest, CompareDrawsCostsAndConvergence) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = Compare();
  ExpectWellFormed(m.html, 2);
  const std::string svg = Figures(m.html);
  EXPECT_NE(svg.find("Levenberg–Marquardt"), std::string::npos);
  EXPECT_NE(svg.find("Downhill Simplex"), std::string::npos);
  // With histories, one line per start and method.
  ASSERT_EQ(m.report["methods"]["lm"]["histories_evaluations_cost"].size(), 3u);
  EXPECT_NE(m.html.find("one line per start"), std::string::npos);
  EXPECT_NE(svg.find("model evaluations"), std::string::npos);
}

TEST(HtmlReportTest, DiagnoseDrawsMisfitRankingAndShrink) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = Diagnose();
  const json& verdict = m.report["verdict"];
  ExpectWellFormed(m.html, 3);
  const std::string svg = Figures(m.html);
  for (const json& w : m.report["where"]) {
    EXPECT_NE(m.html.find("<td>" + w["label"].get<std::string>() + "</td>"), std::string::npos);
    EXPECT_NE(svg.find(">" + Shown(w["label"]) + "<"), std::string::npos) << w["label"];
  }
  for (const json& f : m.report["ranking"]) {
    if (!f["fitted"].get<bool>()) continue;  // not fitted: not drawn
    EXPECT_NE(svg.find(">" + f["effect"].get<std::string>() + "<"), std::string::npos)
        << f["effect"];
  }
  EXPECT_NE(m.html.find(verdict["explanation"].get<std::string>()), std::string::npos);
  if (verdict["effect"] != "none") {  // before and after, one panel each
    EXPECT_NE(svg.find("after: with " + verdict["effect"].get<std::string>()), std::string::npos);
  }
  // What absorbs an effect's parameter whatever its size (standing, no prior
  // on k_cz: the sidewall's dk_bz acts on z_b as k_cz does) is in its row.
  int absorbed = 0;
  for (const json& f : m.report["ranking"]) {
    for (const auto& [name, by] : f["absorbed_by"].items()) {
      std::string text = name + ": ";
      for (size_t k = 0; k < by.size(); ++k) text += (k ? ", " : "") + by[k].get<std::string>();
      EXPECT_NE(m.html.find(text), std::string::npos) << text;
      ++absorbed;
    }
  }
  EXPECT_GE(absorbed, 1);
}

// Static stiffnesses (dataset format 3) get their own misfit table.
TEST(HtmlReportTest, DiagnoseListsEachStaticStiffnessMisfit) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m =
      Make("diagnose_static", "diagnose --derivatives=analytic --dataset=" +
                                  Simulate("static", "--static=vertical,longitudinal,lateral"));
  ASSERT_EQ(m.report["where_else"].size(), 3u);
  for (const json& w : m.report["where_else"]) {
    EXPECT_NE(m.html.find("<td>" + w["name"].get<std::string>() + "</td>"), std::string::npos)
        << w["name"];
  }
  EXPECT_NE(m.html.find("Other measurements: baseline misfit"), std::string::npos);
}

// The SVG of the figure with id `id`, or "".
std::string FigureSvg(const std::string& html, const std::string& id) {
  const size_t at = html.find("<figure id=\"" + id + "\">");
  if (at == std::string::npos) return "";
  const size_t begin = html.find("<svg", at), end = html.find("</svg>", at);
  return begin == std::string::npos || end == std::string::npos ? ""
                                                                 : html.substr(begin, end - begin);
}

// Measured FRFs: each function's row with its FRAC and chi-square, and its
// figure of magnitude, phase and residuals with that chi-square and FRAC in
// the caption; no other figure (no modes).
TEST(HtmlReportTest, IdentifyOfFrfsTablesAndDrawsEachFunction) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = IdentifyFrf();
  const json& frfs = m.report["frfs"];
  ASSERT_EQ(frfs.size(), 28u);
  ExpectWellFormed(m.html, 29);  // and the parameters' intervals
  EXPECT_NE(m.html.find("<h2>Frequency response functions</h2>"), std::string::npos);
  EXPECT_NE(m.html.find("<th>FRAC</th>"), std::string::npos);
  for (size_t k = 0; k < frfs.size(); ++k) {
    const json& f = frfs[k];
    if (f["frac"].is_number()) {  // null where the model's function is zero
      char frac[32];
      std::snprintf(frac, sizeof frac, "%.4f", f["frac"].get<double>());
      EXPECT_NE(m.html.find(std::string("<td class=\"n\">") + frac + "</td>"), std::string::npos)
          << frac;
    }
    const std::string svg = FigureSvg(m.html, "identify-frf-" + std::to_string(k + 1));
    ASSERT_FALSE(svg.empty()) << k;
    EXPECT_NE(svg.find("|H| (per N)"), std::string::npos);
    EXPECT_NE(svg.find("phase (°)"), std::string::npos);
    EXPECT_NE(svg.find("(fitted − measured) / σ"), std::string::npos);
    const std::string name =
        f["condition"].get<std::string>() + " " + f["output"].get<std::string>() + "/" +
        f["input"].get<std::string>();
    EXPECT_NE(m.html.find("FRF " + name + " (χ² "), std::string::npos) << name;
  }
}

// extract: the stabilisation diagram, a row per physical pole, each
// function's FRAC in its table and its panel among the small multiples, and
// the functions of the largest chi-square per value in full.
TEST(HtmlReportTest, ExtractDrawsTheDiagramAndEachFunctionAgainstItsSynthesis) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = Extract();
  ExpectWellFormed(m.html, 5);  // the diagram, one figure of 28 panels, three in full
  const std::string diagram = FigureSvg(m.html, "extract-c0-diagram");
  ASSERT_FALSE(diagram.empty());
  for (const char* what : {"model order", "frequency (Hz)", "physical pole", "not stable",
                           "stable (frequency, damping, vector)"}) {
    EXPECT_NE(diagram.find(what), std::string::npos) << what;
  }
  const auto cell = [](double v, const char* format) {
    char text[32];
    std::snprintf(text, sizeof text, format, v);
    return std::string("<td class=\"n\">") + text + "</td>";
  };
  ASSERT_EQ(m.report["poles"].size(), 7u);
  for (const json& p : m.report["poles"]) {
    EXPECT_NE(m.html.find(cell(p["frequency_hz"].get<double>(), "%.3f")), std::string::npos);
  }
  const json& functions = m.report["conditions"][0]["functions"];
  ASSERT_EQ(functions.size(), 28u);
  const std::string panels = FigureSvg(m.html, "extract-c0-frfs-1");
  ASSERT_FALSE(panels.empty());
  std::vector<std::pair<double, size_t>> per_value;
  for (size_t k = 0; k < functions.size(); ++k) {
    const json& f = functions[k];
    EXPECT_NE(m.html.find(cell(f["frac"].get<double>(), "%.6f")), std::string::npos) << k;
    const std::string name = f["output"].get<std::string>() + " / " + f["input"].get<std::string>();
    EXPECT_NE(panels.find(name), std::string::npos) << name;
    per_value.push_back({-f["chi2"].get<double>() / f["values"].get<double>(), k});
  }
  std::stable_sort(per_value.begin(), per_value.end());
  for (int i = 0; i < 3; ++i) {
    const std::string svg =
        FigureSvg(m.html, "extract-c0-frf-" + std::to_string(per_value[i].second + 1));
    ASSERT_FALSE(svg.empty()) << per_value[i].second;
    EXPECT_NE(svg.find("LSFD synthesis"), std::string::npos);
    EXPECT_NE(svg.find("(synthesised − measured) / σ"), std::string::npos);
  }
}

// poles: a row per pole with its standard errors, the condition's line, its
// diagram and its functions against their synthesis.
TEST(HtmlReportTest, PolesDrawsEachPoleWithItsErrorsAndTheDiagram) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = Poles();
  const json& poles = m.report["poles"]["poles"];
  ASSERT_EQ(poles.size(), 2u);
  for (const json& p : poles) {
    char cell[64];
    std::snprintf(cell, sizeof cell, "<td class=\"n\">%.4f</td>", p["frequency_hz"].get<double>());
    EXPECT_NE(m.html.find(cell), std::string::npos) << cell;
    std::snprintf(cell, sizeof cell, "<td class=\"n\">%.3g</td>", p["frequency_sigma_hz"].get<double>());
    EXPECT_NE(m.html.find(cell), std::string::npos) << cell;
  }
  EXPECT_NE(m.html.find("noise given"), std::string::npos);
  const std::string diagram = FigureSvg(m.html, "extract-c0-diagram");
  ASSERT_FALSE(diagram.empty());
  EXPECT_NE(diagram.find("physical pole"), std::string::npos);
  EXPECT_FALSE(FigureSvg(m.html, "extract-c0-frfs-1").empty());
}

// At speed, a drum's two blocks (in-plane, out-of-plane) each get their
// stabilisation diagram, titled by their inputs and outputs.
TEST(HtmlReportTest, ExtractAtSpeedDrawsADiagramPerBlock) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = ExtractDrum();
  ASSERT_EQ(m.report["conditions"][0]["blocks"].size(), 2u);
  EXPECT_FALSE(FigureSvg(m.html, "extract-c0-diagram").empty());
  EXPECT_FALSE(FigureSvg(m.html, "extract-c0-diagram-2").empty());
  EXPECT_NE(m.html.find("inputs contact_x, contact_z to outputs axle_x, axle_z"), std::string::npos);
  EXPECT_NE(m.html.find("inputs contact_y to outputs axle_y, axle_mx, axle_mz"), std::string::npos);
  EXPECT_EQ(m.report["conditions"][0]["real_poles_per_s"].size(), 1u);
}

TEST(HtmlReportTest, IdentifyAtSpeedDrawsACampbellFigure) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = IdentifyRolling();
  ASSERT_FALSE(m.report["speed_curves"].empty());
  ASSERT_EQ(m.report["modes"].size(), 14u);  // seven modes in each of two conditions
  for (const json& mode : m.report["modes"]) {
    ASSERT_TRUE(mode.contains("condition")) << mode;
    ASSERT_TRUE(mode.contains("speed_m_s")) << mode;
    EXPECT_EQ(mode["speed_m_s"].get<double>(), mode["condition"] == "drum_6" ? 6.0 : 0.0);
  }
  const int figures = Count(m.html, "<figure");
  ExpectWellFormed(m.html, figures);
  const std::string svg = FigureSvg(m.html, "identify-campbell");
  ASSERT_FALSE(svg.empty());
  EXPECT_NE(svg.find("forward speed (m/s)"), std::string::npos);
  EXPECT_NE(svg.find("frequency (Hz)"), std::string::npos);
  EXPECT_NE(svg.find("damping ratio"), std::string::npos);
  // Each mode's curve is in the key; each condition's speed is marked.
  for (const json& curve : m.report["speed_curves"]) {
    EXPECT_NE(svg.find(">" + Shown(curve["label"]) + "<"), std::string::npos) << curve["label"];
  }
  EXPECT_NE(svg.find(">drum 6<"), std::string::npos);
  EXPECT_NE(m.html.find("drum_6 (6 m/s)"), std::string::npos);
  // The modes table names each mode's condition and speed.
  EXPECT_NE(m.html.find("<th>condition</th>"), std::string::npos);
  EXPECT_NE(m.html.find("<th>speed (m/s)</th>"), std::string::npos);
  EXPECT_EQ(Count(m.html, "<td>drum_6</td>"), 7);
  // The frequency figure tells the conditions apart.
  EXPECT_NE(Figures(m.html).find(">drum 6 vertical<"), std::string::npos);
}

TEST(HtmlReportTest, IdentifyCampbellFigureIsWholeInChromium) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  RINGID_REQUIRE_TOOL(!Chromium().empty(), "chromium");
  const Made m = IdentifyRolling();
  ASSERT_NE(m.html.find("<figure id=\"identify-campbell\">"), std::string::npos);
  const int figures = Count(m.html, "<figure");
  EXPECT_EQ(figures, Count(m.html, "<svg"));
  const auto check = ringid::testing::CheckFiguresInChromium(m.html_path, figures);
  ASSERT_TRUE(check.ran) << check.error;
  std::string problems;
  for (const std::string& line : check.problems) problems += line + "\n";
  EXPECT_TRUE(check.problems.empty()) << problems;
}

TEST(HtmlReportTest, StandingDataHaveNoCampbellFigureNorConditionColumn) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = IdentifyPaper();
  ASSERT_TRUE(m.report["speed_curves"].empty());
  EXPECT_EQ(m.html.find("identify-campbell"), std::string::npos);
  EXPECT_EQ(m.html.find("<th>condition</th>"), std::string::npos);
}

// The report's warnings (issue 21) head the page: Table 1 has 7 frequencies for
// 16 free parameters. Without warnings there is no section.
TEST(HtmlReportTest, IdentifyHeadsThePageWithItsWarnings) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = IdentifyPaper();
  const json& warnings = m.report["warnings"];
  ASSERT_FALSE(warnings.empty());
  const size_t section = m.html.find("<h2>Warnings</h2>");
  ASSERT_NE(section, std::string::npos);
  EXPECT_LT(section, m.html.find("<h2>Summary</h2>"));
  for (const json& w : warnings) {
    EXPECT_NE(m.html.find(w.get<std::string>()), std::string::npos) << w;
  }
  EXPECT_NE(m.html.find("for 16 free parameters: they cannot set them all"), std::string::npos);
  const Made none = Changed(m, "unwarned_identify", [](json* r) { (*r)["warnings"] = json::array(); });
  EXPECT_EQ(none.html.find("<h2>Warnings</h2>"), std::string::npos);
}

// The interval shown is the report's interval_95, symmetric in the
// coordinate fitted: value x exp(+-1.96 std/value) for a positive parameter
// (fitted in its log), value +- 1.96 std for k_xy (lug_coupling, fitted in
// N/m, may be negative). The page applied the first to every parameter.
TEST(HtmlReportTest, IdentifyShowsTheReportsIntervalForEveryKindOfParameter) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  // Started off k_xy = 0, where the misfit is flat in k_xy (it enters squared).
  json data = json::parse(ReadFile(Simulate("lug", "--effects=lug_coupling --shift=0.05")));
  const json truth = json::parse(
      ReadFile(Scratch("truth_" + std::to_string(std::hash<std::string>()("lug")) + ".json")));
  data["initial"]["k_xy"] = 1.3 * truth["parameters"]["k_xy"]["value"].get<double>();
  const std::string started = Scratch("lug_started.json");
  std::ofstream(started) << data.dump(2);
  const Made m = Make("identify_lug", "identify --starts=1 --derivatives=analytic "
                                      "--effects=lug_coupling --dataset=" + started);
  for (const auto& [name, positive] : {std::pair{"k_xy", false}, std::pair{"k_bx", true}}) {
    const json& p = m.report["parameters"][name];
    ASSERT_TRUE(p["std"].is_number()) << name;
    const double v = p["value"], s = p["std"];
    const double lo = positive ? v * std::exp(-ringid::kNormal95 * s / v) : v - ringid::kNormal95 * s;
    const double hi = positive ? v * std::exp(ringid::kNormal95 * s / v) : v + ringid::kNormal95 * s;
    ASSERT_EQ(p["interval_95"].size(), 2u) << name;
    EXPECT_NEAR(p["interval_95"][0].get<double>(), lo, 1e-9 * (std::abs(lo) + std::abs(v))) << name;
    EXPECT_NEAR(p["interval_95"][1].get<double>(), hi, 1e-9 * (std::abs(hi) + std::abs(v))) << name;
    char cell[128];
    std::snprintf(cell, sizeof cell, "<td class=\"n\">[%.4g, %.4g]</td>",
                  p["interval_95"][0].get<double>(), p["interval_95"][1].get<double>());
    EXPECT_NE(m.html.find(cell), std::string::npos) << name << ": " << cell;
  }
}

// The interval figure draws, per parameter, the band its interval lies in
// when it is classed yes, from the classification's own threshold: a
// relative standard deviation of at most 0.354 (UncertaintyOptions), so
// exp(+-1.96 x 0.354) = [0.49966, 2.00136] fitted in the log, 1 +- 0.69383
// fitted linearly (an effect parameter). The page drew a factor 2 for every
// parameter, which a linear one classed yes (std/value 0.30: 0.41 to 1.59)
// crosses.
TEST(HtmlReportTest, IdentifyDrawsTheBandOfClassYesFromTheClassifiersThreshold) {
  using namespace ringid;  // NOLINT
  IdentifyReport report;
  IdentifyResult& r = report.body.result;
  const auto add = [&](Param p, double value, double relative_std, bool log) {
    ParameterEstimate q;
    q.key.param = p;
    q.value = value;
    q.free = true;
    q.std = relative_std * value;
    const double z = 1.959963984540054;
    const double half = z * relative_std;
    q.interval_95 = log ? std::pair{value * std::exp(-half), value * std::exp(half)}
                        : std::pair{value * (1 - half), value * (1 + half)};
    q.identifiable =
        relative_std <= 0.354 ? Identifiability::kYes : Identifiability::kPracticallyNo;
    r.estimates.push_back(q);
  };
  add(Param::k_bx, 3e5, 0.30, true);
  add(Param::k_by, 2e5, 0.40, true);
  add(Param::s_h, 1e-7, 0.30, false);
  add(Param::k_xy, 1e4, 0.40, false);
  html::Page page;
  html::IdentifyPage(report, &page);
  const html::Figure* f = nullptr;
  for (const html::Page::Block& b : page.blocks()) {
    if (b.figure && b.figure->name == "identify-parameters") f = &*b.figure;
  }
  ASSERT_NE(f, nullptr);
  // The rows of the data file a plot clause titled `title` reads.
  const auto rows = [&](const std::string& title) {
    const size_t at = f->script.find("title '" + title + "'");
    EXPECT_NE(at, std::string::npos) << title << " in\n" << f->script;
    if (at == std::string::npos) return std::vector<std::vector<double>>{};
    const size_t d = f->script.rfind(" d", at);
    const size_t index = std::stoul(f->script.substr(d + 2));
    std::vector<std::vector<double>> out;
    std::istringstream lines(f->data.at(index));
    for (std::string line; std::getline(lines, line);) {
      std::istringstream values(line);
      out.emplace_back(std::istream_iterator<double>(values), std::istream_iterator<double>());
    }
    return out;
  };
  const std::vector<std::vector<double>> bands = rows("yes within");
  ASSERT_EQ(bands.size(), 4u);
  const double log_band[] = {0.49966, 2.00136}, linear_band[] = {1 - 0.69383, 1 + 0.69383};
  for (int i = 0; i < 4; ++i) {
    const double* band = i < 2 ? log_band : linear_band;
    ASSERT_EQ(bands[i].size(), 3u);
    EXPECT_EQ(bands[i][0], i);
    EXPECT_NEAR(bands[i][1], band[0], 2e-5) << i;
    EXPECT_NEAR(bands[i][2], band[1], 2e-5) << i;
  }
  // Each interval lies within its band exactly when it is classed yes.
  for (const auto& [title, inside] : {std::pair{"yes", true}, std::pair{"practically_no", false}}) {
    const std::vector<std::vector<double>> drawn = rows(title);
    ASSERT_EQ(drawn.size(), 2u) << title;
    for (const std::vector<double>& row : drawn) {
      const std::vector<double>& band = bands.at(static_cast<size_t>(row.at(0)));
      EXPECT_EQ(row[1] >= band[1] && row[2] <= band[2], inside) << title << " " << row[0];
    }
  }
  EXPECT_NE(f->caption.find("at most 0.354"), std::string::npos) << f->caption;
}

// diagnose --level sets the level of every likelihood-ratio test; each
// ranking row (every effect refitted: --screen=1) carries its threshold, the chi-square quantile at that level
// (tables: 6.635, 9.210, 11.345 for 1-3 degrees of freedom at 0.01), and the
// page says the level it was drawn at. Out of (0, 1) it is refused.
TEST(HtmlReportTest, DiagnoseThresholdsAreTheReportsAtItsLevel) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = Make("diagnose_level", "diagnose --level=0.01 --screen=1 --derivatives=analytic --dataset=" +
                                            Simulate("lug", "--effects=lug_coupling --shift=0.05"));
  EXPECT_EQ(m.report["verdict"]["level"].get<double>(), 0.01);
  const std::map<int, double> table = {{1, 6.635}, {2, 9.210}, {3, 11.345}};
  int checked = 0;
  for (const json& row : m.report["ranking"]) {
    if (!row["fitted"].get<bool>()) continue;
    const int extra = row["evidence"]["extra_parameters"];
    ASSERT_TRUE(table.count(extra)) << row["effect"];
    EXPECT_NEAR(row["evidence"]["likelihood_ratio_threshold"].get<double>(), table.at(extra), 2e-3)
        << row["effect"];
    ++checked;
  }
  EXPECT_GE(checked, 4);
  EXPECT_NE(m.html.find("gives p = 0.01 for the effect"), std::string::npos);
  for (const char* level : {"0", "1", "1.5", "-0.1"}) {
    const RunResult r = Ringid(std::string("diagnose --level=") + level +
                               " --dataset=" + SourcePath("datasets/paper/table1.json"));
    EXPECT_EQ(r.status, 2) << level;
    EXPECT_NE(r.err.find("--level"), std::string::npos) << r.err;
  }
}

// Table 1's fit breaks rules of docs/plausibility.md: each flag is listed
// before the modes; a fit within every range says so.
TEST(HtmlReportTest, IdentifyListsThePlausibilityFlags) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = IdentifyPaper();
  const json& flags = m.report["plausibility"];
  ASSERT_FALSE(flags.empty());
  const size_t section = m.html.find("<h2>Plausibility</h2>");
  ASSERT_NE(section, std::string::npos);
  EXPECT_LT(section, m.html.find("<h2>Modes</h2>"));
  for (const json& flag : flags) {
    EXPECT_NE(m.html.find("<td>" + flag["rule"].get<std::string>() + "</td>"), std::string::npos)
        << flag["rule"];
    std::string names;
    for (const json& p : flag["parameters"]) {
      names += (names.empty() ? "" : ", ") + p.get<std::string>();
    }
    EXPECT_NE(m.html.find("<td>" + names + "</td>"), std::string::npos) << names;
  }
  EXPECT_EQ(m.html.find("every value within its plausible range"), std::string::npos);
  // Without flags: one line saying so, and no section.
  const Made none = Changed(m, "plausible_identify", [](json* r) {
    (*r)["plausibility"] = json::array();
  });
  EXPECT_EQ(none.html.find("<h2>Plausibility</h2>"), std::string::npos);
  EXPECT_NE(none.html.find("every value within its plausible range (docs/plausibility.md)"),
            std::string::npos);
}

// What decided a parameter with a prior (docs/reports.md): the prior where
// it keeps over half its variance, the data where under a tenth is left.
std::string DecidedBy(double prior_share) {
  return prior_share > 0.5 ? "the prior" : prior_share < 0.1 ? "the data" : "data and prior";
}
std::string DecidedByName(double prior_share) {
  return prior_share > 0.5 ? "prior" : prior_share < 0.1 ? "data" : "data_and_prior";
}

TEST(HtmlReportTest, IdentifyWithPriorsSaysWhatDecidedEachParameter) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = IdentifyRolling(true);
  const json& parameters = m.report["parameters"];
  ASSERT_TRUE(parameters["r_e0"].contains("prior_share"));
  ASSERT_TRUE(parameters["k_bx"].contains("prior_share"));
  EXPECT_EQ(DecidedBy(parameters["r_e0"]["prior_share"].get<double>()), "the prior");
  EXPECT_EQ(DecidedBy(parameters["k_bx"]["prior_share"].get<double>()), "the data");
  EXPECT_NE(m.html.find("<th>decided by</th>"), std::string::npos);
  // The row of each parameter with a prior ends with the words.
  const size_t table = m.html.find("<h2>Parameters</h2>");
  ASSERT_NE(table, std::string::npos);
  for (const auto& [name, p] : parameters.items()) {
    if (!p.contains("prior_share")) continue;
    EXPECT_EQ(p["decided_by"], DecidedByName(p["prior_share"].get<double>())) << name;
    const size_t row = m.html.find("<tr><td>" + name + "</td>", table);
    ASSERT_NE(row, std::string::npos) << name;
    const std::string tr = m.html.substr(row, m.html.find("</tr>", row) - row);
    char z[64];
    std::snprintf(z, sizeof z, "<td class=\"n\">%+.1f</td>", p["prior_z"].get<double>());
    const std::string words = "<td>" + DecidedBy(p["prior_share"].get<double>()) + "</td>" + z;
    ASSERT_GE(tr.size(), words.size());
    EXPECT_EQ(tr.substr(tr.size() - words.size()), words) << name;
  }
  // Data and priors agree here; a prior 5 sigma off is named as a conflict.
  EXPECT_EQ(m.html.find("prior and data disagree"), std::string::npos);
  const Made conflict = Changed(m, "prior_conflict_identify", [](json* r) {
    (*r)["parameters"]["k_bx"]["prior_z"] = -5.0;
  });
  EXPECT_NE(conflict.html.find("prior and data disagree (beyond 3 prior sigma): k_bx is 5.0 "
                               "prior sigma below its prior"),
            std::string::npos);
  // A parameter on a bound of its box is named above the table.
  EXPECT_EQ(m.html.find("on a bound of its box"), std::string::npos);
  const Made bound = Changed(m, "on_bound_identify", [](json* r) {
    (*r)["parameters"]["k_bx"]["on_bound"] = "lower";
  });
  EXPECT_NE(bound.html.find("on a bound of its box, so not an interior optimum"), std::string::npos);
  EXPECT_NE(bound.html.find("k_bx (lower)"), std::string::npos);
  // And in words above the table.
  EXPECT_NE(m.html.find("decided by their priors (posterior variance over 50 % of the prior "
                        "variance): r_e0"),
            std::string::npos);
  EXPECT_NE(m.html.find("decided by the data despite a prior (under 10 % of the prior variance "
                        "left): k_bx"),
            std::string::npos);
  // Without priors: no such column.
  EXPECT_EQ(IdentifyRolling().html.find("<th>decided by</th>"), std::string::npos);
}

TEST(HtmlReportTest, PredictIsTablesOnly) {
  // No figure, so no gnuplot needed.
  const Made m = Predict();
  ExpectWellFormed(m.html, 0);
  for (const json& mode : m.report["modes"]) {
    EXPECT_NE(m.html.find("<td>" + mode["label"].get<std::string>() + "</td>"), std::string::npos);
  }
  EXPECT_NE(m.html.find("72.133"), std::string::npos);  // Table 3's vertical mode, 72.1 Hz
}

TEST(HtmlReportTest, PredictAtSpeedsDrawsTheCampbellDiagramAndListsTheCriticalSpeeds) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = PredictAtSpeeds();
  ExpectWellFormed(m.html, 1);
  ASSERT_EQ(m.report["speeds"].size(), 11u);
  ASSERT_GT(m.report["critical_speeds"].size(), 0u);
  for (const json& c : m.report["critical_speeds"]) {
    char speed[32];
    std::snprintf(speed, sizeof speed, "%.3f", c["speed_m_s"].get<double>());
    EXPECT_NE(m.html.find(speed), std::string::npos) << speed;
  }
  EXPECT_NE(m.html.find("Critical speeds"), std::string::npos);
}

// The lug excitation's table: a row per speed and order, each amplitude as
// the report holds it (|complex| of forces and response).
TEST(HtmlReportTest, PredictWithALugProfileTablesEachOrdersForcesAndResponse) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = Make("predict_lugs", "predict --parameters=" +
                                          SourcePath("datasets/examples/car_tire.json") +
                                          " --lug_profile=" +
                                          SourcePath("datasets/examples/cross_stitch_lugs.json") +
                                          " --speeds=6,12 --max_order=3");
  ExpectWellFormed(m.html, 1);
  EXPECT_NE(m.html.find("Lug excitation"), std::string::npos);
  ASSERT_EQ(m.report["lug_excitation"].size(), 2u);
  for (const json& at : m.report["lug_excitation"]) {
    ASSERT_EQ(at["orders"].size(), 3u);
    for (const json& k : at["orders"]) {
      if (k["order"].get<int>() % 2 == 0) continue;  // cross-stitch: F_y at odd orders only
      const json& fy = k["forces"]["F_y"];
      char text[32];
      std::snprintf(text, sizeof text, "%.4g", std::hypot(fy["re"].get<double>(), fy["im"].get<double>()));
      EXPECT_NE(m.html.find(std::string(">") + text + "<"), std::string::npos) << text;
    }
  }
}

// The forces page gives each condition's model range and flags the orders
// above it: the shipped response under car_tire.json, whose range ends at
// 1.5 x 117.888 Hz (drum_6: orders 3-5 above; drum_18: every order).
TEST(HtmlReportTest, ForcesFlagsTheOrdersAboveTheModelsRange) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = Make("forces_range", "forces --parameters=" +
                                          SourcePath("datasets/examples/car_tire.json") + " --dataset=" +
                                          SourcePath("datasets/examples/car_tire_lug_response.json"));
  ExpectWellFormed(m.html, 3);
  EXPECT_NE(m.html.find("model valid below (Hz)"), std::string::npos);
  EXPECT_NE(m.html.find("<td>drum_6</td><td class=\"n\">6</td><td class=\"n\">63.66</td>"
                        "<td class=\"n\">176.8</td><td>3, 4, 5</td>"),
            std::string::npos)
      << m.html;
  EXPECT_NE(m.html.find("<td>drum_18</td><td class=\"n\">18</td><td class=\"n\">191</td>"
                        "<td class=\"n\">176.8</td><td>1, 2, 3, 4, 5</td>"),
            std::string::npos);
  EXPECT_NE(m.html.find(">model range</th>"), std::string::npos);
  EXPECT_NE(m.html.find("<td class=\"n\">190.99</td><td>above</td>"), std::string::npos);
  EXPECT_NE(m.html.find("<td class=\"n\">63.66</td><td>within</td>"), std::string::npos);
  EXPECT_NE(m.html.find("dashed: the condition&#39;s model_valid_below_hz"), std::string::npos);
}

TEST(HtmlReportTest, CampaignOfDiagnosesDrawsTheGapsAndTheVerdicts) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = Campaign();
  ExpectWellFormed(m.html, 2);
  EXPECT_NE(Figures(m.html).find(">case000<"), std::string::npos);
  EXPECT_NE(m.html.find(m.report["datasets"][0]["verdict"].get<std::string>()), std::string::npos);
  // The verdicts figure counts each verdict: its bars are labelled by name.
  std::map<std::string, int> counts;
  for (const json& row : m.report["datasets"]) {
    ++counts[row.contains("verdict") && !row["verdict"].is_null() ? row["verdict"].get<std::string>() : "none"];
  }
  for (const auto& [verdict, n] : counts) {
    EXPECT_NE(Figures(m.html).find(">" + Shown(verdict) + "<"), std::string::npos) << verdict;
  }
}

TEST(HtmlReportTest, BenchPaperDrawsTable3) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = Bench("paper");
  ExpectWellFormed(m.html, 1);
  const std::string svg = Figures(m.html);
  for (const json& row : m.report["table3"]) {
    EXPECT_NE(svg.find(">" + Shown(row["label"]) + "<"), std::string::npos) << row["label"];
  }
  EXPECT_NE(svg.find("model − paper (Hz)"), std::string::npos);
}

TEST(HtmlReportTest, BenchConditioningDrawsRankPerVariant) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = Bench("conditioning");
  ExpectWellFormed(m.html, 1);
  const std::string svg = Figures(m.html);
  for (const json& v : m.report["variants"]) {
    EXPECT_NE(svg.find(">" + v["data"].get<std::string>() + "<"), std::string::npos) << v["data"];
  }
  EXPECT_NE(svg.find(">" + std::to_string(m.report["variants"][0]["classes"].size()) + " free<"),
            std::string::npos);
}

TEST(HtmlReportTest, BenchSyntheticDrawsCoverage) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = Bench("synthetic");
  ExpectWellFormed(m.html, 1);
  const std::string svg = Figures(m.html);
  for (const json& t : m.report["tires"]) {
    EXPECT_NE(svg.find(">" + t["tire"].get<std::string>() + "<"), std::string::npos) << t["tire"];
  }
  EXPECT_NE(svg.find("nominal 95 %"), std::string::npos);
}

TEST(HtmlReportTest, BenchDiagnosisDrawsTheConfusionCounts) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = BenchDiagnosis();
  ExpectWellFormed(m.html, 1);
  const std::string svg = Figures(m.html);
  // Nine cells, each count printed once in the heat map.
  for (const std::string count : {"1", "2", "3", "4"}) {
    EXPECT_EQ(Count(svg, ">" + count + "<"), 1) << count;
  }
  EXPECT_EQ(Count(svg, ">0<"), 5);
  for (const std::string effect : {"none", "hub_compliance", "lug_coupling"}) {
    EXPECT_GE(Count(svg, ">" + effect + "<"), 2) << effect;  // a row and a column
  }
}

TEST(HtmlReportTest, BenchSpeedDrawsNumericAndAnalyticTimes) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = BenchSpeed();
  ExpectWellFormed(m.html, 1);
  const std::string svg = Figures(m.html);
  for (const auto& [name, row] : m.report["rows"].items()) {
    EXPECT_TRUE(row["numeric_seconds"].is_number()) << name;
    EXPECT_NE(svg.find(">" + Shown(name) + "<"), std::string::npos) << name;
    EXPECT_NE(m.html.find(">" + name + "<"), std::string::npos) << name;  // the table's row
  }
  EXPECT_NE(svg.find(">numeric<"), std::string::npos);
  EXPECT_NE(svg.find(">analytic<"), std::string::npos);
  EXPECT_NE(m.html.find("Targets (issue 13)"), std::string::npos);
}

TEST(HtmlReportTest, FiguresDirHoldsEachFigureAsAFile) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made m = IdentifyPaper();
  const std::string dir = Scratch("figures");
  ::mkdir(dir.c_str(), 0700);
  const RunResult r = Ringid("report --input=" + m.report_path + " --output=" + Scratch("f.html") +
                             " --figures_dir=" + dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string svg = ReadFile(dir + "/identify-frequencies.svg");
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find(">rotation in phase<"), std::string::npos);
  // A directory that cannot be made (its parent is a file) is refused up
  // front; one that is missing is made (CliTest.EveryOutputIsCheckedBeforeAnyWork).
  const RunResult bad =
      Ringid("report --input=" + m.report_path + " --output=" + Scratch("g.html") +
             " --figures_dir=" + Scratch("f.html") + "/figures");
  EXPECT_EQ(bad.status, 2);
  EXPECT_FALSE(Exists(Scratch("g.html")));
}

TEST(HtmlReportTest, BadInputIsOneLineExitTwoAndNoOutput) {
  const std::string dir = Scratch("");
  const Made predict = Predict();
  const std::string good = predict.report_path;
  json unknown_field = predict.report, mistyped = predict.report;
  unknown_field["modes"][0]["extra"] = 1;
  mistyped["modes"] = "x";
  const std::string unknown_field_text = unknown_field.dump(), mistyped_text = mistyped.dump();
  const struct {
    const char* name;
    const char* text;
    const char* field;
  } files[] = {
      {"malformed.json", "{\"report\": \"identify\",", ""},
      {"empty.json", "", ""},
      {"not_a_report.json", R"({"format": "ringid-modal-dataset/1", "modes": []})", "report"},
      {"unknown_kind.json", R"({"report": "frobnicate", "schema_version": 2})", "report"},
      {"old_schema.json", R"({"report": "predict", "modes": []})", "schema_version"},
      {"array.json", "[1, 2, 3]", ""},
      {"unknown_field.json", unknown_field_text.c_str(), "modes[0].extra: unknown key"},
      {"mistyped.json", mistyped_text.c_str(), "modes: must be an array"},
      {"deep.json", "", ""}};
  const std::string out = dir + "never.html";
  std::vector<std::pair<std::string, std::string>> cases;  // arguments, what stderr names
  for (const auto& f : files) {
    const std::string path = dir + f.name;
    std::ofstream(path) << (std::string(f.name) == "deep.json"
                                ? std::string(200, '[') + std::string(200, ']')
                                : std::string(f.text));
    cases.push_back({"report --input=" + path + " --output=" + out, path + ": " + f.field});
  }
  cases.push_back({"report --input=" + dir + "missing.json --output=" + out, dir + "missing.json"});
  cases.push_back({"report --input=" + good + " --output=" + out + " --bogus=1", "--bogus"});
  cases.push_back({"report --input=" + good, "--output"});
  cases.push_back({"report --output=" + out, "--input"});
  cases.push_back(
      {"report --input=" + good + " --output=/nonexistent-dir/x.html", "/nonexistent-dir/x.html"});
  for (const auto& [args, named] : cases) {
    std::remove(out.c_str());
    const RunResult r = Ringid(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_NE(r.err.find(named), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(Exists(out)) << args;
  }
  // An existing output is left as it was.
  std::ofstream(out) << "keep";
  EXPECT_EQ(Ringid("report --input=" + dir + "malformed.json --output=" + out).status, 2);
  EXPECT_EQ(ReadFile(out), "keep");
}

TEST(HtmlReportTest, MissingOrFailingGnuplotIsExitOneAndNoOutput) {
  const std::string dir = Scratch("");
  const std::string report = IdentifyPaper().report_path;
  const std::string out = dir + "no_gnuplot.html";
  std::remove(out.c_str());
  const std::string run =
      std::string(RINGID_BINARY) + " report --input=" + report + " --output=" + out;
  RunResult r = Shell("PATH=/nonexistent " + run);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("gnuplot not found"), std::string::npos) << r.err;
  EXPECT_FALSE(Exists(out));
  // A gnuplot that fails.
  const std::string bin = Scratch("fake_bin");
  ::mkdir(bin.c_str(), 0700);
  std::ofstream(bin + "/gnuplot") << "#!/bin/sh\necho 'line 1: broken' >&2\nexit 3\n";
  ::chmod((bin + "/gnuplot").c_str(), 0700);
  r = Shell("PATH=" + bin + " " + run);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("gnuplot failed: line 1: broken"), std::string::npos) << r.err;
  EXPECT_FALSE(Exists(out));
  // A report without figures needs no gnuplot.
  r = Shell("PATH=/nonexistent " + std::string(RINGID_BINARY) + " report --input=" +
            Predict().report_path + " --output=" + out);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(Exists(out));
}

// Values a report may carry at its edges: numbers that are not available
// (null), empty lists, a failed status.
TEST(HtmlReportTest, MissingNumbersAndEmptyListsRender) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  const Made identify = IdentifyPaper();
  const Made compare = Compare();
  const std::vector<Made> pages = {
      Changed(identify, "edge_identify_nulls",
              [](json* r) {
                (*r)["modes"][0]["model_hz"] = nullptr;
                (*r)["modes"][1]["measured_sigma_hz"] = nullptr;
                (*r)["start_costs"] = {nullptr};
                (*r)["covariance"]["matrix"] = json::array();
                for (auto& [name, p] : (*r)["parameters"].items()) p["std"] = nullptr;
              }),
      Changed(identify, "edge_identify_failed",
              [](json* r) {
                (*r)["status"] = "failed";
                (*r)["modes"] = json::array();
              }),
      Changed(compare, "edge_compare_nulls", [](json* r) {
        for (auto& [name, m] : (*r)["methods"].items()) {
          m["final_costs"][0] = nullptr;
          m["histories_evaluations_cost"][0] = {{1, nullptr}};
        }
      })};
  for (const Made& m : pages) {
    EXPECT_EQ(m.html.rfind("<!DOCTYPE html>", 0), 0u) << m.report_path;
    EXPECT_EQ(Count(m.html, "<svg"), Count(m.html, "</svg>")) << m.report_path;
  }
}

TEST(HtmlReportTest, TextFromTheReportIsEscaped) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  std::remove("/tmp/ringid-pwned");
  const Made identify = Changed(IdentifyPaper(), "escaped_identify", [](json* r) {
    (*r)["dataset"] = "<script>alert(1)</script>";
    (*r)["message"] = "a & b";
  });
  EXPECT_NE(identify.html.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
  EXPECT_NE(identify.html.find("a &amp; b"), std::string::npos);
  EXPECT_EQ(identify.html.find("<script"), std::string::npos);
  // Names that reach a figure's tics: the confusion matrix of the suite.
  const std::string nasty = "it's `touch /tmp/ringid-pwned` <b>&";
  ringid::DiagnosisSuite suite;
  suite.effects = {"none", nasty};
  suite.confusion = {{"none", {{"none", 1}}}, {nasty, {{nasty, 1}}}};
  const std::string path = Scratch("escaped_bench.json");
  std::ofstream(path) << ringid::ReportText(ringid::BenchDiagnosisReport{{}, suite});
  const Made bench = Render(path);
  EXPECT_FALSE(Exists("/tmp/ringid-pwned"));
  EXPECT_EQ(bench.html.find("<b>&"), std::string::npos);
  EXPECT_NE(Figures(bench.html).find("&lt;b>&amp;"), std::string::npos);  // a tic label in the SVG
}

// ---------------------------------------------------------------- Chromium

// Renders `m` in headless Chromium and checks a real picture came out.
// RINGID_SCREENS=DIR keeps the PNG there as KIND.png.
void Screenshot(const std::string& kind, const Made& m) {
  const std::string png = Scratch(kind + ".png");
  std::remove(png.c_str());
  const RunResult r = Shell("timeout 120 " + Chromium() +
                            " --headless --no-sandbox --disable-gpu --hide-scrollbars"
                            " --user-data-dir=" +
                            Scratch("chromium-" + kind) + " --screenshot=" + png +
                            " --window-size=1200,3000 file://" + m.html_path);
  ASSERT_TRUE(Exists(png)) << r.err;
  const std::string bytes = ReadFile(png);
  ASSERT_GT(bytes.size(), 24u);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  const auto be32 = [&](size_t at) {
    return (static_cast<unsigned char>(bytes[at]) << 24) |
           (static_cast<unsigned char>(bytes[at + 1]) << 16) |
           (static_cast<unsigned char>(bytes[at + 2]) << 8) |
           static_cast<unsigned char>(bytes[at + 3]);
  };
  EXPECT_EQ(be32(16), 1200u);  // IHDR width and height
  EXPECT_EQ(be32(20), 3000u);
  // A blank 1200 x 3000 page compresses to a few kB; tables and figures do not.
  EXPECT_GT(bytes.size(), 30000u) << png;
  if (const char* keep = std::getenv("RINGID_SCREENS")) {
    std::ifstream in(png, std::ios::binary);
    std::ofstream(std::string(keep) + "/" + kind + ".png", std::ios::binary) << in.rdbuf();
  }
}

// What Chromium shows wrong with the `figures` figures of the page at
// `html_path` (see tests/browser_check.h); fails the test when Chromium fails.
std::vector<std::string> BrowserProblems(const std::string& html_path, int figures) {
  const auto check = ringid::testing::CheckFiguresInChromium(html_path, figures);
  EXPECT_TRUE(check.ran) << check.error;
  return check.ran ? check.problems : std::vector<std::string>{};
}

std::string Lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) out += line + "\n";
  return out;
}

struct Kind {
  const char* name;
  std::function<Made()> make;
};

void PrintTo(const Kind& k, std::ostream* os) { *os << k.name; }

class ChromiumTest : public ::testing::TestWithParam<Kind> {};

TEST_P(ChromiumTest, PageRendersWithEveryFigureWhole) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  RINGID_REQUIRE_TOOL(!Chromium().empty(), "chromium");
  const Made m = GetParam().make();
  Screenshot(GetParam().name, m);
  const int figures = Count(m.html, "<figure");
  EXPECT_EQ(figures, Count(m.html, "<svg"));
  const auto problems = BrowserProblems(m.html_path, figures);
  EXPECT_TRUE(problems.empty()) << Lines(problems);
}

INSTANTIATE_TEST_SUITE_P(
    EveryKind, ChromiumTest,
    ::testing::Values(Kind{"identify", IdentifyShapes}, Kind{"identify_frf", IdentifyFrf},
                      Kind{"identifiability", Identifiability},
                      Kind{"compare", Compare}, Kind{"diagnose", Diagnose},
                      Kind{"predict", Predict}, Kind{"campaign", Campaign},
                      Kind{"forces", Forces}, Kind{"predict_speeds", PredictAtSpeeds},
                      Kind{"extract", Extract}, Kind{"extract_drum", ExtractDrum},
                      Kind{"poles", Poles},
                      Kind{"bench_paper", [] { return Bench("paper"); }},
                      Kind{"bench_synthetic", [] { return Bench("synthetic"); }},
                      Kind{"bench_conditioning", [] { return Bench("conditioning"); }},
                      Kind{"bench_diagnosis", BenchDiagnosis},
                      Kind{"bench_rolling", [] { return Bench("rolling"); }},
                      Kind{"bench_speed", BenchSpeed},
                      Kind{"bench_forces", [] { return Bench("forces"); }},
                      Kind{"bench_static", [] { return Bench("static"); }},
                      Kind{"bench_frf", BenchFrf},
                      Kind{"bench_extract", BenchExtract}),
    [](const ::testing::TestParamInfo<Kind>& info) { return std::string(info.param.name); });

// A page of one figure: Table 1 identified (frequencies only: no shape for
// a MAC figure, no parameter with a std for intervals).
Made OneFigurePage() { return IdentifyPaper(); }

TEST(ChromiumCheckTest, FindsNothingWrongWithAWholePage) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  RINGID_REQUIRE_TOOL(!Chromium().empty(), "chromium");
  const Made m = OneFigurePage();
  const auto problems = BrowserProblems(m.html_path, 1);
  EXPECT_TRUE(problems.empty()) << Lines(problems);
}

// One way to break a figure: the text of its SVG, "<svg" to "</svg>", in
// and out.
struct Corruption {
  const char* name;
  std::function<std::string(const std::string&)> apply;
};

void PrintTo(const Corruption& c, std::ostream* os) { *os << c.name; }

class BrokenFigureTest : public ::testing::TestWithParam<Corruption> {};

TEST_P(BrokenFigureTest, ChromiumCheckFindsIt) {
  RINGID_REQUIRE_TOOL(HaveGnuplot(), "gnuplot");
  RINGID_REQUIRE_TOOL(!Chromium().empty(), "chromium");
  const Made m = OneFigurePage();
  const size_t start = m.html.find("<svg"), end = m.html.find("</svg>") + 6;
  ASSERT_NE(start, std::string::npos);
  const std::string svg = m.html.substr(start, end - start);
  ASSERT_NE(svg.find("</defs>"), std::string::npos);
  const std::string broken = m.html.substr(0, start) + GetParam().apply(svg) + m.html.substr(end);
  ASSERT_NE(broken, m.html);
  // Text checks of the page alone would pass it.
  EXPECT_NE(broken.find("<path"), std::string::npos);
  EXPECT_EQ(Count(broken, "<figure"), 1);
  const std::string path = Scratch(std::string("broken_") + GetParam().name + ".html");
  std::ofstream(path) << broken;
  const auto check = ringid::testing::CheckFiguresInChromium(path, 1);
  ASSERT_TRUE(check.ran) << check.error;
  const auto& problems = check.problems;
  EXPECT_FALSE(problems.empty());
  std::cout << GetParam().name << ":\n" << Lines(problems);
}

INSTANTIATE_TEST_SUITE_P(
    ThreeWays, BrokenFigureTest,
    ::testing::Values(
        // Cut in the middle of its text, as by a short write.
        Corruption{"truncated",
                   [](const std::string& svg) { return svg.substr(0, svg.size() / 2); }},
        // Cut at the start of a tag in its middle: the HTML parser closes it
        // neatly, the XML parser does not.
        Corruption{
            "truncated_at_a_tag",
            [](const std::string& svg) { return svg.substr(0, svg.rfind("\n<", svg.size() / 2)); }},
        // Well-formed, but with nothing drawn: only the symbol definitions
        // (paths themselves) are left.
        Corruption{"nothing_plotted",
                   [](const std::string& svg) {
                     return svg.substr(0, svg.find("</defs>") + 7) + "\n</g>\n</svg>";
                   }}),
    [](const ::testing::TestParamInfo<Corruption>& info) { return std::string(info.param.name); });

}  // namespace
