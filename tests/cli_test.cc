// The ringid tool end to end: reports, and the error contract (exit status,
// docs/conventions.md §6).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <fstream>
#include <map>
#include <utility>
#include <string>
#include <vector>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "apps/progress.h"
#include "apps/reports.h"
#include "datasets/synthetic.h"
#include "datasets/tir.h"
#include "datasets/tir_parameters.h"
#include "model/rigid_ring_model.h"
#include "model/spelling.h"
#include "tests/test_support.h"

namespace {

using ringid::testing::Exists;
using ringid::testing::ReadFile;
using ringid::testing::Ringid;
using ringid::testing::RunResult;
using ringid::testing::Scratch;
using ringid::testing::StartRingid;
using ringid::testing::WaitFor;

using ringid::testing::SourcePath;

TEST(CliTest, IdentifyWritesTheContractReport) {
  const std::string out = Scratch("identify.json");
  std::remove(out.c_str());
  const RunResult r = Ringid("identify --dataset=" + SourcePath("datasets/paper/table1.json") +
                       " --output=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(out);
  const nlohmann::json j = nlohmann::json::parse(in);
  for (const char* key : {"method", "converged", "cost", "evaluations", "seconds",
                          "parameters", "covariance", "modes"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["parameters"]["K_cx"]["identifiable"], "no");
  EXPECT_TRUE(j["parameters"]["K_cx"]["std"].is_null());
  EXPECT_EQ(j["covariance"]["rank"], 7);
  EXPECT_EQ(j["modes"].size(), 7u);
}

TEST(CliTest, PredictReproducesTable3Vertical) {
  const std::string out = Scratch("predict.json");
  const RunResult r = Ringid("predict --parameters=" + SourcePath("datasets/paper/parameters.json") +
                       " --output=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(out);
  const nlohmann::json j = nlohmann::json::parse(in);
  bool found = false;
  for (const auto& m : j["modes"]) {
    if (m["label"] == "vertical") {
      found = true;
      EXPECT_NEAR(m["model_hz"].get<double>(), 72.1, 0.1);
    }
  }
  EXPECT_TRUE(found);
}

TEST(CliTest, BadInputIsOneLineExitTwoAndNoReport) {
  const std::string dir = Scratch("");
  const std::string bad = dir + "bad_dataset.json";
  std::ofstream(bad) << R"({"format":"ringid-modal-dataset/1","name":"x",)"
                        R"("modes":[{"label":"vertical","frequency_hz":-3}]})";
  const std::string partial = dir + "partial_parameters.json";
  std::ofstream(partial) << R"({"format":"ringid-parameters/1","parameters":{"m_b":{"value":2.4}}})";
  const std::string out = dir + "never_written.json";
  std::remove(out.c_str());
  const std::string cases[] = {
      "identify --dataset=" + bad + " --output=" + out,
      "identify --dataset=/nonexistent.json --output=" + out,
      "identify --dataset=" + SourcePath("datasets/paper/table1.json") + " --bogus=1 --output=" + out,
      "identify --dataset=" + SourcePath("datasets/paper/table1.json") + " --starts=abc --output=" + out,
      "identify --dataset=" + SourcePath("datasets/paper/table1.json") + " --method=newton --output=" + out,
      "identify --dataset=" + SourcePath("datasets/paper/table1.json") + " --threads=-1 --output=" + out,
      "diagnose --dataset=" + SourcePath("datasets/paper/table1.json") + " --threads=100000 --output=" + out,
      "predict --parameters=" + bad + " --output=" + out,
      "predict --dataset=" + bad + " --output=" + out,
      "predict --parameters=" + partial + " --output=" + out,
      "frobnicate",
  };
  for (const std::string& c : cases) {
    const RunResult r = Ringid(c);
    EXPECT_EQ(r.status, 2) << c;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c << ": " << r.err;
    EXPECT_FALSE(Exists(out)) << c;
  }
  const RunResult r = Ringid("identify --dataset=" + bad);
  EXPECT_NE(r.err.find("bad_dataset.json"), std::string::npos);
  EXPECT_NE(r.err.find("modes[0].frequency_hz"), std::string::npos);
}

// --fix holds a parameter at its initial value and --bounds replaces its box,
// on every fitting command; a bad item, an unknown or non-free parameter, or
// a start outside the bounds is exit 2 with one line naming it.
TEST(CliTest, FixAndBoundsReachEveryFittingCommandAndBadOnesAreRefused) {
  const std::string table1 = SourcePath("datasets/paper/table1.json");
  const std::string out = Scratch("fixed.json");
  std::remove(out.c_str());
  RunResult r = Ringid("identify --dataset=" + table1 + " --fix=t_0 --output=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(ReadFile(out));
  EXPECT_FALSE(j["parameters"]["t_0"]["free"].get<bool>());
  EXPECT_DOUBLE_EQ(j["parameters"]["t_0"]["value"].get<double>(), 0.00135);
  r = Ringid("identify --dataset=" + table1 + " --bounds=t_0:0.001:0.05 --output=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(ReadFile(out));
  const double t_0 = j["parameters"]["t_0"]["value"].get<double>();
  EXPECT_GE(t_0, 0.001 * (1 - 1e-12));
  EXPECT_LE(t_0, 0.05 * (1 + 1e-12));
  // The example car tire's k_cz is 2e5 N/m; bounds above it, around the
  // start of 2.5e5, hold the fit on the lower one.
  r = Ringid("identify --dataset=" + SourcePath("datasets/examples/car_tire_rolling.json") +
             " --starts=1 --bounds=k_cz:220000:300000 --output=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  j = nlohmann::json::parse(ReadFile(out));
  EXPECT_NEAR(j["parameters"]["k_cz"]["value"].get<double>(), 220000, 1);
  EXPECT_EQ(j["parameters"]["k_cz"]["on_bound"], "lower");
  std::remove(out.c_str());
  const std::pair<std::string, std::string> cases[] = {
      {"--fix=t_0x", "--fix: unknown parameter 't_0x'"},
      {"--fix=m_b", "--fix: m_b is not free in"},
      {"--fix=c_bz", "(it is tied)"},
      {"--bounds=t_0:1", "--bounds: bad item 't_0:1'"},
      {"--bounds=t_0:0.1:0.01", "bounds: t_0 needs finite LO < HI, LO > 0"},
      {"--bounds=t_0:0:0.01", "LO > 0"},
      {"--bounds=t_0:0.1:0.2", "the initial value of t_0 (0.00135) lies outside 0.1..0.2"},
      {"--bounds=m_b:1:3", "bounds: m_b is not free"},
      {"--bounds=x_y:1:3", "--bounds: unknown parameter 'x_y'"},
  };
  for (const char* command : {"identify", "identifiability", "compare", "diagnose"}) {
    for (const auto& [flag, words] : cases) {
      const std::string c = std::string(command) + " --dataset=" + table1 + " " + flag +
                            " --output=" + out;
      r = Ringid(c);
      EXPECT_EQ(r.status, 2) << c;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c << ": " << r.err;
      EXPECT_NE(r.err.find(words), std::string::npos) << c << ": " << r.err;
      EXPECT_FALSE(Exists(out)) << c;
    }
  }
}

TEST(CliTest, EveryMalformedDatasetIsRefusedByEveryCommand) {
  const std::string dir = Scratch("");
  const std::string out = dir + "malformed_report.json";
  int n = 0;
  for (const auto& bad : ringid::testing::MalformedDatasets()) {
    const std::string file = dir + "malformed_" + std::to_string(n++) + ".json";
    std::ofstream(file, std::ios::binary) << bad.text;
    for (const std::string command : {"identify", "predict"}) {
      std::remove(out.c_str());
      const RunResult r = Ringid(command + " --dataset=" + file + " --output=" + out);
      EXPECT_EQ(r.status, 2) << bad.what << " (" << command << ")";
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << bad.what << ": " << r.err;
      EXPECT_NE(r.err.find(file), std::string::npos) << bad.what << ": " << r.err;
      EXPECT_NE(r.err.find(bad.field), std::string::npos) << bad.what << ": " << r.err;
      EXPECT_FALSE(Exists(out)) << bad.what;
    }
    std::remove(file.c_str());
  }
}

TEST(CliTest, AnInterruptedRunLeavesNoReport) {
  const std::string out = Scratch("interrupted.json");
  std::remove(out.c_str());
  // 100000 starts take minutes; SIGINT arrives after half a second.
  const std::string cmd = "timeout -s INT 0.5 " + std::string(RINGID_BINARY) +
                          " identify --starts=100000 --dataset=" +
                          SourcePath("datasets/paper/table1.json") + " --output=" + out +
                          " > /dev/null 2>&1";
  const int raw = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 124);  // timeout: the command was interrupted
  EXPECT_FALSE(Exists(out));
  EXPECT_FALSE(Exists(out + ".ringid-probe"));
}

TEST(CliTest, UnwritableOutputIsRefusedBeforeTheRun) {
  const RunResult r = Ringid("identify --dataset=" + SourcePath("datasets/paper/table1.json") +
                       " --output=/nonexistent-dir/report.json");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("/nonexistent-dir/report.json"), std::string::npos);
}

// A dataset and its truth (or a report and its figures) appear together or
// not at all: a failure on the second file leaves no first file behind.
TEST(CliTest, SeveralFilesAreWrittenAllOrNone) {
  const std::string dir = Scratch("all_or_none");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string first = dir + "/dataset.json";
  const std::string second = dir + "/missing-dir/truth.json";
  std::string error;
  EXPECT_FALSE(ringid::WriteFilesAtomically({{first, "a"}, {second, "b"}}, &error));
  EXPECT_NE(error.find(second), std::string::npos) << error;
  EXPECT_FALSE(Exists(first));
  EXPECT_TRUE(std::filesystem::is_empty(dir)) << "a temporary file was left behind";

  const std::string other = dir + "/truth.json";
  ASSERT_TRUE(ringid::WriteFilesAtomically({{first, "a"}, {other, "b"}}, &error)) << error;
  EXPECT_EQ(ReadFile(first), "a");
  EXPECT_EQ(ReadFile(other), "b");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator()), 2);

  // One path for two outputs (--output equal to --save_parameters): refused,
  // and the file already there is left as it was.
  EXPECT_FALSE(ringid::WriteFilesAtomically({{first, "c"}, {dir + "/./dataset.json", "d"}}, &error));
  EXPECT_NE(error.find("named for two outputs"), std::string::npos) << error;
  EXPECT_EQ(ReadFile(first), "a");
}

// Format 2 (docs/conventions.md §7) from the command line.

nlohmann::json LoadJson(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// Issue 21: values no rigid ring can have are refused before any solve (exit 2,
// one line naming the file and field, nothing written). On the template, the
// longitudinal mode typed 100x too high paired the wrong modes with exit 0, the
// lateral one typed as 7750 Hz was fitted by an absurd stiffness with exit 0,
// 1e30 Hz ended in Ceres' "consecutive invalid steps" (exit 1) and
// k_bx = 1e300 in "fewer model modes than measured shapes".
TEST(CliTest, ValuesNoRigidRingCanHaveAreRefusedBeforeAnySolve) {
  const std::string dir = Scratch("");
  const std::string out = dir + "absurd_report.json";
  const nlohmann::json base = LoadJson(SourcePath("datasets/template.json"));
  ASSERT_EQ(base["modes"][0]["label"], "longitudinal");
  ASSERT_EQ(base["modes"][3]["label"], "lateral");
  const struct { const char* pointer; double value; const char* field; } cases[] = {
      {"/modes/0/frequency_hz", 3554, "modes[0].frequency_hz: 3554 Hz is outside 1-1000 Hz"},
      {"/modes/3/frequency_hz", 7750, "modes[3].frequency_hz: 7750 Hz is outside 1-1000 Hz"},
      {"/modes/0/frequency_hz", 1e30, "modes[0].frequency_hz: 1e+30 Hz is outside"},
      {"/initial/k_bx", 1e300, "initial.k_bx: is absurd: beyond 1e+12 in magnitude"},
      {"/known/m_b", 2e12, "known.m_b: is absurd"}};
  for (const auto& c : cases) {
    nlohmann::json j = base;
    j[nlohmann::json::json_pointer(c.pointer)] = c.value;
    const std::string file = dir + "absurd.json";
    std::ofstream(file) << j.dump(1);
    for (const std::string command : {"identify", "diagnose", "predict"}) {
      std::remove(out.c_str());
      const RunResult r = Ringid(command + " --dataset=" + file + " --output=" + out);
      EXPECT_EQ(r.status, 2) << c.field << " (" << command << "): " << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
      EXPECT_NE(r.err.find(file + ": " + c.field), std::string::npos) << r.err;
      EXPECT_FALSE(Exists(out)) << c.field;
    }
  }
  // The same of a parameter set and of --set, for predict and simulate.
  const std::string set = dir + "absurd_set.json";
  nlohmann::json p = LoadJson(SourcePath("datasets/examples/car_tire.json"));
  p["parameters"]["k_bx"] = 1e300;
  std::ofstream(set) << p.dump(1);
  for (const std::string args :
       {"predict --parameters=" + set, "simulate --parameters=" + set + " --truth=" + out + ".t",
        "predict --parameters=" + SourcePath("datasets/examples/car_tire.json") + " --set=k_bx=1e13"}) {
    std::remove(out.c_str());
    const RunResult r = Ringid(args + " --output=" + out);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("k_bx"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("absurd"), std::string::npos) << r.err;
    EXPECT_FALSE(Exists(out)) << args;
  }
}

// `ringid simulate` of the example car tire with `flags`, into Scratch(name).
std::string SimulateCarTire(const std::string& name, const std::string& flags) {
  const std::string out = Scratch(name);
  const RunResult r = Ringid("simulate --parameters=" + SourcePath("datasets/examples/car_tire.json") +
                             " " + flags + " --output=" + out + " --truth=" + out + ".truth");
  EXPECT_EQ(r.status, 0) << flags << ": " << r.err;
  return out;
}

// The modes of `dataset`'s condition `name`, by label.
std::map<std::string, nlohmann::json> ModesOf(const nlohmann::json& dataset, const std::string& name) {
  std::map<std::string, nlohmann::json> modes;
  for (const auto& c : dataset["conditions"]) {
    if (c["name"] != name) continue;
    for (const auto& m : c["modes"]) modes[m["label"].get<std::string>()] = m;
  }
  return modes;
}

TEST(CliTest, SimulateAtSeveralSpeedsWritesFormat2ThatIdentifies) {
  const std::string data = SimulateCarTire("rolling.json", "--speeds=0,6,12");
  const nlohmann::json d = LoadJson(data);
  EXPECT_EQ(d["format"], "ringid-modal-dataset/2");
  ASSERT_EQ(d["conditions"].size(), 3u);
  const char* names[] = {"standing", "drum_6", "drum_12"};
  const double speeds[] = {0, 6, 12};
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(d["conditions"][i]["name"], names[i]);
    EXPECT_EQ(d["conditions"][i]["speed_m_s"].get<double>(), speeds[i]);
    EXPECT_EQ(d["conditions"][i]["modes"].size(), 7u) << names[i];
  }
  EXPECT_FALSE(d.contains("modes"));
  // Rolling damps the longitudinal mode through the slip states (tenfold at
  // 12 m/s, far beyond the 10 % damping noise) and shifts frequencies by
  // about 1 % (four times the frequency noise).
  const auto standing = ModesOf(d, "standing"), drum_12 = ModesOf(d, "drum_12");
  ASSERT_EQ(standing.size(), 7u);
  ASSERT_EQ(drum_12.size(), 7u);
  EXPECT_GT(drum_12.at("longitudinal")["damping_ratio"].get<double>(),
            3 * standing.at("longitudinal")["damping_ratio"].get<double>());
  double largest_shift = 0;
  for (const auto& [label, m] : standing) {
    const double f0 = m["frequency_hz"].get<double>();
    largest_shift = std::max(largest_shift,
                             std::abs(drum_12.at(label)["frequency_hz"].get<double>() / f0 - 1));
  }
  EXPECT_GT(largest_shift, 0.005);

  const std::string report = Scratch("rolling_report.json");
  std::remove(report.c_str());
  const RunResult r = Ringid("identify --starts=1 --dataset=" + data + " --output=" + report);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = LoadJson(report);
  ASSERT_EQ(j["modes"].size(), 21u);
  std::map<std::string, int> per_condition;
  for (const auto& m : j["modes"]) {
    ASSERT_TRUE(m.contains("condition")) << m.dump();
    ++per_condition[m["condition"].get<std::string>()];
  }
  EXPECT_EQ(per_condition, (std::map<std::string, int>{{"standing", 7}, {"drum_6", 7}, {"drum_12", 7}}));
  // Rolling data separate K from sigma: simulate writes the relaxation
  // lengths as unknowns, and the fit finds them near the truth.
  const ringid::Parameters truth = ringid::ExampleCarTire();
  for (const char* sigma : {"sigma_cx", "sigma_cy"}) {
    EXPECT_FALSE(d["known"].contains(sigma)) << sigma;
    ASSERT_TRUE(d["initial"].contains(sigma)) << sigma;
    const auto& fitted = j["parameters"][sigma];
    EXPECT_EQ(fitted["identifiable"], "yes") << fitted.dump();
    const double truth_value = truth[*ringid::ParseParam(sigma)];
    EXPECT_LT(std::abs(fitted["value"].get<double>() - truth_value),
              4 * fitted["std"].get<double>()) << fitted.dump();
  }
  // Asked, it writes them known at the truth.
  const nlohmann::json fixed = LoadJson(SimulateCarTire("rolling_fixed.json", "--speeds=0,6 --fix=sigma_cx,sigma_cy"));
  EXPECT_EQ(fixed["known"]["sigma_cx"].get<double>(), truth[ringid::Param::sigma_cx]);
  EXPECT_FALSE(fixed["initial"].contains("sigma_cy"));
}

// predict --dataset of several conditions gives each condition's modes: the
// model at the condition's speed, the slip damping growing with speed.
TEST(CliTest, PredictOnAFormat2DatasetGivesTheModesOfEveryCondition) {
  const std::string rolling = SourcePath("datasets/examples/car_tire_rolling.json");
  const std::string out = Scratch("predict_conditions.json");
  std::remove(out.c_str());
  const RunResult r = Ringid("predict --dataset=" + rolling + " --output=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("modes by condition"), std::string::npos) << r.out;
  const nlohmann::json j = LoadJson(out);
  ASSERT_EQ(j["conditions"].size(), 3u) << j.dump();
  ringid::Dataset d;
  ringid::LoadError e;
  ASSERT_TRUE(ringid::LoadDataset(rolling, &d, &e)) << e.OneLine();
  for (int c = 0; c < 3; ++c) {
    const nlohmann::json& at = j["conditions"][c];
    EXPECT_EQ(at["condition"], d.conditions[c].name);
    EXPECT_EQ(at["speed_m_s"].get<double>(), d.conditions[c].speed_m_s);
    const ringid::ModalSolution s =
        ringid::RigidRingModel().Solve(ringid::InitialParameters(d, c), d.conditions[c].speed_m_s);
    ASSERT_TRUE(s.ok);
    EXPECT_EQ(at["modes"].size(), s.modes.size());
    for (const ringid::Mode& m : s.modes) {
      const nlohmann::json& mode = at["modes"][ringid::LabelName(m.label)];
      EXPECT_NEAR(mode[0].get<double>(), m.frequency_hz, 1e-9) << ringid::LabelName(m.label);
    }
  }
  const auto zeta = [&](int c) { return j["conditions"][c]["modes"]["longitudinal"][1].get<double>(); };
  EXPECT_GT(zeta(2), 3 * zeta(0));  // 12 m/s against standing
}

TEST(CliTest, Format2DatasetThroughIdentifiabilityCompareAndReport) {
  const std::string data = SimulateCarTire("rolling_b.json", "--speeds=0,6,12");
  const std::string identify = Scratch("rolling_b_identify.json");
  const std::string identifiability = Scratch("rolling_b_identifiability.json");
  const std::string compare = Scratch("rolling_b_compare.json");
  const std::pair<std::string, std::string> runs[] = {
      {"identify", identify}, {"identifiability", identifiability}, {"compare", compare}};
  for (const auto& [command, out] : runs) {
    std::remove(out.c_str());
    const RunResult r = Ringid(command + " --starts=1 --dataset=" + data + " --output=" + out);
    EXPECT_EQ(r.status, 0) << command << ": " << r.err;
    EXPECT_TRUE(Exists(out)) << command;
  }
  RINGID_REQUIRE_TOOL(ringid::testing::HaveProgram("gnuplot"), "gnuplot");
  for (const auto& [command, out] : runs) {
    const std::string html = Scratch("rolling_b_" + command + ".html");
    std::remove(html.c_str());
    const RunResult r = Ringid("report --input=" + out + " --output=" + html);
    EXPECT_EQ(r.status, 0) << command << ": " << r.err;
    EXPECT_EQ(ReadFile(html).rfind("<!DOCTYPE html>", 0), 0u) << command;
  }
}

// Each defect of a format-2 file: exit 2, one line naming the file and the
// field, no report, from every command that reads a dataset.
TEST(CliTest, BadFormat2InputIsOneLineExitTwoAndNoReport) {
  auto dataset = [](const std::string& known, const std::string& priors,
                    const std::string& second_name, const std::string& second_speed,
                    const std::string& first_known) {
    const std::string modes = R"("modes":[{"label":"vertical","frequency_hz":80.5}])";
    return R"({"format":"ringid-modal-dataset/2","name":"bad",)"
           R"("known":)" + known + R"(,"per_condition":["F_cz0"],"priors":)" + priors +
           R"(,"conditions":[{"name":"standing","speed_m_s":0,"known":)" + first_known + "," +
           modes + R"(},{"name":")" + second_name + R"(","speed_m_s":)" + second_speed +
           R"(,"known":{"F_cz0":3000},)" + modes + "}]}";
  };
  const std::string known = R"({"m_b":7.7})";
  const std::string priors = R"({"K_cx":{"distribution":"lognormal","median":8e4,"factor_95":3}})";
  const std::string load = R"({"F_cz0":3000})";
  struct Case {
    std::string what, text, field;
  };
  const Case cases[] = {
      {"duplicate condition name", dataset(known, priors, "standing", "6", load),
       "conditions[1].name"},
      {"negative speed", dataset(known, priors, "drum_6", "-6", load), "conditions[1].speed_m_s"},
      {"prior on an unknown parameter",
       dataset(known, R"({"k_nonsense":{"distribution":"normal","mean":1,"sigma":0.1}})",
               "drum_6", "6", load),
       "priors.k_nonsense"},
      {"per-condition value of a shared parameter",
       dataset(known, priors, "drum_6", "6", R"({"F_cz0":3000,"k_bx":2e6})"),
       "conditions[0].known.k_bx"},
  };
  const std::string dir = Scratch("");
  const std::string out = dir + "format2_never_written.json";
  int n = 0;
  for (const Case& c : cases) {
    const std::string file = dir + "bad_format2_" + std::to_string(n++) + ".json";
    std::ofstream(file, std::ios::binary) << c.text;
    for (const std::string command :
         {"identify", "identifiability", "compare", "diagnose", "predict"}) {
      std::remove(out.c_str());
      const RunResult r = Ringid(command + " --dataset=" + file + " --output=" + out);
      EXPECT_EQ(r.status, 2) << c.what << " (" << command << ")";
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.what << ": " << r.err;
      EXPECT_NE(r.err.find(file), std::string::npos) << c.what << ": " << r.err;
      EXPECT_NE(r.err.find(c.field), std::string::npos) << c.what << ": " << r.err;
      EXPECT_FALSE(Exists(out)) << c.what << " (" << command << ")";
    }
  }
}

TEST(CliTest, BadSpeedsOrLoadsAreRefusedNamingTheFlag) {
  const std::string out = Scratch("bad_speeds.json");
  const std::string truth = Scratch("bad_speeds_truth.json");
  const std::pair<std::string, std::string> cases[] = {
      {"--speeds=-6", "--speeds"},     {"--speeds=0,-6", "--speeds"},
      {"--speeds=abc", "--speeds"},    {"--speeds=6km", "--speeds"},
      {"--speeds=6,,12", "--speeds"},  {"--speeds=", "--speeds"},
      {"--speeds=nan", "--speeds"},    {"--speeds=6,6", "--speeds"},
      {"--loads=0", "--loads"},        {"--loads=-3000", "--loads"},
      {"--loads=3kN", "--loads"},      {"--loads=", "--loads"},
  };
  for (const auto& [flag, name] : cases) {
    std::remove(out.c_str());
    std::remove(truth.c_str());
    const RunResult r = Ringid("simulate --parameters=" + SourcePath("datasets/examples/car_tire.json") +
                               " " + flag + " --output=" + out + " --truth=" + truth);
    EXPECT_EQ(r.status, 2) << flag;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << flag << ": " << r.err;
    EXPECT_EQ(r.err.rfind("ringid: " + name + ":", 0), 0u) << flag << ": " << r.err;
    EXPECT_FALSE(Exists(out)) << flag;
    EXPECT_FALSE(Exists(truth)) << flag;
  }
}

TEST(CliTest, SimulateWithoutSpeedsStillWritesFormat1) {
  // The same file name in two directories, so that the dataset names agree.
  const std::string dir = Scratch("format1");
  for (const std::string sub : {"/default", "/zero"}) {
    std::filesystem::create_directories(dir + sub);
  }
  const std::string plain = SimulateCarTire("format1/default/tire.json", "--seed=5");
  const std::string zero = SimulateCarTire("format1/zero/tire.json", "--seed=5 --speeds=0");
  const nlohmann::json d = LoadJson(plain);
  EXPECT_EQ(d["format"], "ringid-modal-dataset/1");
  EXPECT_EQ(d["modes"].size(), 7u);
  EXPECT_FALSE(d.contains("conditions"));
  EXPECT_EQ(ReadFile(plain), ReadFile(zero));
}

TEST(CliTest, SimulateNamesConditionsAndMakesTheLoadPerCondition) {
  const nlohmann::json one = LoadJson(SimulateCarTire("drum.json", "--speeds=12.5"));
  EXPECT_EQ(one["format"], "ringid-modal-dataset/2");  // a speed format 1 cannot hold
  ASSERT_EQ(one["conditions"].size(), 1u);
  EXPECT_EQ(one["conditions"][0]["name"], "drum_12.5");

  const std::string data = SimulateCarTire("loads.json", "--speeds=0,6 --loads=3000,4500.5");
  const nlohmann::json d = LoadJson(data);
  EXPECT_EQ(d["format"], "ringid-modal-dataset/2");
  EXPECT_EQ(d["per_condition"], nlohmann::json::array({"F_cz0"}));
  EXPECT_FALSE(d["known"].contains("F_cz0"));
  const std::pair<const char*, double> expected[] = {{"standing_3000N", 3000},
                                                     {"standing_4500.5N", 4500.5},
                                                     {"drum_6_3000N", 3000},
                                                     {"drum_6_4500.5N", 4500.5}};
  ASSERT_EQ(d["conditions"].size(), 4u);
  for (int i = 0; i < 4; ++i) {
    const auto& c = d["conditions"][i];
    EXPECT_EQ(c["name"], expected[i].first);
    EXPECT_EQ(c["speed_m_s"].get<double>(), i < 2 ? 0.0 : 6.0);
    EXPECT_EQ(c["known"]["F_cz0"].get<double>(), expected[i].second);
  }
  const nlohmann::json truth = LoadJson(data + ".truth");
  EXPECT_FALSE(truth["parameters"].contains("F_cz0"));
  EXPECT_EQ(truth["parameters"]["F_cz0@drum_6_4500.5N"]["value"].get<double>(), 4500.5);
  const RunResult r = Ringid("identify --starts=1 --dataset=" + data);
  EXPECT_EQ(r.status, 0) << r.err;
}

// The .tir interchange from the command line (docs/tir.md).

// --set=NAME=VALUE,... of every parameter of the standing model that `have`
// lacks, at its value in `from`, to 17 digits.
std::string SetTheRest(const ringid::Parameters& have, const ringid::Parameters& from) {
  std::string set;
  for (ringid::Param q : ringid::RigidRingModel().parameters()) {
    if (have.IsSet(q)) continue;
    char value[40];
    std::snprintf(value, sizeof value, "%.17g", from[q]);
    set += (set.empty() ? "--set=" : ",") + std::string(ringid::ParamName(q)) + "=" + value;
  }
  return set;
}

// predict's modes of `args`, by label: {frequency, damping ratio}.
std::map<std::string, std::pair<double, double>> PredictedModes(const std::string& args) {
  const std::string out = Scratch("tir_predict.json");
  std::remove(out.c_str());
  const RunResult r = Ringid("predict " + args + " --output=" + out);
  EXPECT_EQ(r.status, 0) << args << ": " << r.err;
  std::map<std::string, std::pair<double, double>> modes;
  if (r.status != 0) return modes;
  const nlohmann::json report = LoadJson(out);
  for (const auto& m : report["modes"]) {
    modes[m["label"].get<std::string>()] = {m["model_hz"].get<double>(),
                                            m["damping_ratio"].get<double>()};
  }
  return modes;
}

// A tire one has a .tir for: its standing modes from the .tir and --set of
// what a .tir cannot hold are the modes of the full parameter set, whether
// the .tir was written by export or is the public TNO belt (whose rest, the
// example car tire's, also supplies damping and k_cz).
TEST(CliTest, PredictReadsATirAndTheRestFromSetAsTheFullParameterSet) {
  const std::string car = SourcePath("datasets/examples/car_tire.json");
  const std::string tir = Scratch("car_tire.tir");
  std::remove(tir.c_str());
  const RunResult r = Ringid("export --parameters=" + car + " --format=tir --output=" + tir);
  ASSERT_EQ(r.status, 0) << r.err;
  ringid::Parameters full;
  ringid::LoadError e;
  ASSERT_TRUE(ringid::LoadParameterSet(car, &full, &e)) << e.OneLine();
  const auto expected = PredictedModes("--parameters=" + car);
  ASSERT_EQ(expected.size(), 7u);
  for (const std::string& file : {tir, SourcePath("datasets/examples/tno_205_60R15_belt.tir")}) {
    ringid::Parameters from_tir;
    ASSERT_TRUE(ringid::LoadParameters(file, {}, &from_tir, &e)) << e.OneLine();
    const auto modes = PredictedModes("--parameters=" + file + " " + SetTheRest(from_tir, full));
    ASSERT_EQ(modes.size(), 7u) << file;
    for (const auto& [label, m] : expected) {
      EXPECT_NEAR(modes.at(label).first, m.first, 1e-9 * m.first) << file << ": " << label;
      EXPECT_NEAR(modes.at(label).second, m.second, 1e-9) << file << ": " << label;
    }
  }
}

// forces reads a .tir as predict does: with --set of the rest, the forces of
// the full parameter set; without it, the line that asks for --set (the help
// said only predict and export read a .tir, and forces had no --set).
TEST(CliTest, ForcesReadsATirWithTheRestFromSet) {
  const std::string car = SourcePath("datasets/examples/car_tire.json");
  const std::string response = SourcePath("datasets/examples/car_tire_lug_response.json");
  const std::string tir = SourcePath("datasets/examples/tno_205_60R15_belt.tir");
  ringid::Parameters full, from_tir;
  ringid::LoadError e;
  ASSERT_TRUE(ringid::LoadParameterSet(car, &full, &e)) << e.OneLine();
  ASSERT_TRUE(ringid::LoadParameters(tir, {}, &from_tir, &e)) << e.OneLine();
  const std::string of_set = Scratch("forces_of_set.json"), of_tir = Scratch("forces_of_tir.json");
  RunResult r = Ringid("forces --parameters=" + car + " --dataset=" + response + " --output=" + of_set);
  ASSERT_EQ(r.status, 0) << r.err;
  r = Ringid("forces --parameters=" + tir + " " + SetTheRest(from_tir, full) + " --dataset=" +
             response + " --output=" + of_tir);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json a = nlohmann::json::parse(ReadFile(of_set));
  const nlohmann::json b = nlohmann::json::parse(ReadFile(of_tir));
  ASSERT_EQ(a["conditions"].size(), 3u);
  for (size_t c = 0; c < 3; ++c) {
    for (size_t k = 0; k < a["conditions"][c]["orders"].size(); ++k) {
      for (const char* f : {"F_x", "F_z", "F_y"}) {
        const auto& x = a["conditions"][c]["orders"][k]["forces"][f];
        const auto& y = b["conditions"][c]["orders"][k]["forces"][f];
        const double scale = x["abs"].get<double>();
        EXPECT_NEAR(y["re"].get<double>(), x["re"].get<double>(), 1e-9 * scale) << c << k << f;
        EXPECT_NEAR(y["im"].get<double>(), x["im"].get<double>(), 1e-9 * scale) << c << k << f;
      }
    }
  }
  r = Ringid("forces --parameters=" + tir + " --dataset=" + response);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("tno_205_60R15_belt.tir: I_ay: missing (the model needs it; a .tir describes "
                       "the tire, not the wheel"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("give --set=I_ay=VALUE"), std::string::npos) << r.err;
  // --set over an identify report, whose values carry the fit's covariance: refused.
  const std::string fit = Scratch("forces_tir_fit.json");
  r = Ringid("identify --starts=1 --dataset=" + SourcePath("datasets/paper/table1.json") +
             " --output=" + fit);
  ASSERT_EQ(r.status, 0) << r.err;
  r = Ringid("forces --parameters=" + fit + " --set=I_ay=0.4 --dataset=" + response);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--set: not over an identify report"), std::string::npos) << r.err;
}

// The help names the commands whose --parameters reads a .tir, in one
// sentence from the table of commands, in `ringid help` and in each
// --help of a command taking --parameters; each command it names does read
// one (it asks for what the belt-only .tir lacks) and simulate without
// --lug_forces, which it does not name, does not.
TEST(CliTest, TheHelpNamesTheCommandsThatReadATirAndTheyDo) {
  const auto OneLine = [](std::string text) {  // the wrapped help as one line
    for (size_t at; (at = text.find('\n')) != std::string::npos;) {
      size_t end = at + 1;
      while (end < text.size() && text[end] == ' ') ++end;
      text.replace(at, end - at, " ");
    }
    return text;
  };
  const std::string sentence =
      "--parameters of predict, simulate --lug_forces, extract, export, import and forces also "
      "reads the "
      "rigid-ring part of an MF-Swift FILE.tir (docs/tir.md), what a .tir cannot hold given by "
      "--set";
  EXPECT_NE(OneLine(Ringid("help").out).find("a .tir: " + sentence + "."), std::string::npos);
  for (const char* command : {"forces", "predict", "extract", "export", "import", "simulate"}) {
    EXPECT_NE(OneLine(Ringid(std::string(command) + " --help").out).find(sentence),
              std::string::npos)
        << command;
  }
  EXPECT_NE(Ringid("forces --help").out.find("--set=TEXT"), std::string::npos);
  const std::string tir = SourcePath("datasets/examples/tno_205_60R15_belt.tir");
  const std::string lugs = SourcePath("datasets/examples/car_tire_lug_forces.json");
  const std::string response = SourcePath("datasets/examples/car_tire_lug_response.json");
  const std::string lack = "tno_205_60R15_belt.tir: I_ay: missing";
  for (const std::string& args :
       {"predict --parameters=" + tir,
        "simulate --parameters=" + tir + " --lug_forces=" + lugs + " --speeds=6 --output=" +
            Scratch("tir_never.json"),
        "forces --parameters=" + tir + " --dataset=" + response}) {
    const RunResult r = Ringid(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_NE(r.err.find(lack), std::string::npos) << args << ": " << r.err;
  }
  RunResult r = Ringid("export --parameters=" + tir + " --format=json");
  EXPECT_EQ(r.status, 0) << r.err;
  // extract takes the values a .tir holds in place of the dataset's initial ones.
  r = Ringid("extract --parameters=" + tir + " --dataset=" +
             SourcePath("datasets/examples/car_tire_hammer_frf.json") + " --output=" +
             Scratch("tir_extract.json"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("parameters: no [VERTICAL] FNOMIN"), std::string::npos) << r.out;  // read
  r = Ringid("import --uff=" + SourcePath("datasets/examples/car_tire_lab.uff") + " --map=" +
             SourcePath("datasets/examples/car_tire_lab_map.json") + " --parameters=" + tir +
             " --output=" + Scratch("tir_import.json"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("parameters: no [VERTICAL] FNOMIN"), std::string::npos) << r.out;  // read
  EXPECT_NE(r.err.find("parameter I_ay is not finite"), std::string::npos) << r.err;
  r = Ringid("simulate --parameters=" + tir + " --output=" + Scratch("tir_sim.json") +
             " --truth=" + Scratch("tir_sim_truth.json"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("tno_205_60R15_belt.tir: [0]: not valid JSON"), std::string::npos) << r.err;
}

// The template holds sigma_cx known, so identify classes K_cx yes only given
// it; its report and its --save_parameters say so, and a .tir exported from
// either marks K_cx as undetermined in its header, the value of a key it
// does not enter unmarked.
TEST(CliTest, ExportFromIdentifyMarksTheValuesTheDataLeftUndetermined) {
  const std::string report = Scratch("template_identify.json");
  const std::string set = Scratch("template_set.json");
  std::remove(report.c_str());
  std::remove(set.c_str());
  RunResult r = Ringid("identify --dataset=" + SourcePath("datasets/template.json") +
                       " --starts=1 --derivatives=analytic --output=" + report +
                       " --save_parameters=" + set);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("K_cx: given sigma_cx = 0.1 m (known): the data measure K_cx/sigma_cx"),
            std::string::npos) << r.out;
  const nlohmann::json j = LoadJson(report);
  EXPECT_EQ(j["parameters"]["K_cx"]["condition"],
            "given sigma_cx = 0.1 m (known): the data measure K_cx/sigma_cx");
  EXPECT_EQ(j["parameters"]["K_cx"]["conditional_on"][0]["known"], "sigma_cx");
  EXPECT_TRUE(j["parameters"]["k_bx"]["condition"].is_null());
  EXPECT_EQ(LoadJson(set)["parameters"]["K_cx"]["identifiable"], "yes");
  for (const std::string& from : {report, set}) {
    const std::string tir = Scratch("template_export.tir");
    std::remove(tir.c_str());
    r = Ringid("export --parameters=" + from + " --format=tir --output=" + tir);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string text = ringid::testing::ReadFile(tir);
    EXPECT_NE(text.find("$ UNDETERMINED by the data: K_cx = "), std::string::npos) << text;
    EXPECT_NE(text.find("in LONGITUDINAL_STIFFNESS: given sigma_cx = 0.1 m (known)"),
              std::string::npos) << text;
    EXPECT_EQ(text.find("UNDETERMINED by the data: k_bx"), std::string::npos) << text;
    // Given by hand, a value is no longer the data's.
    r = Ringid("export --parameters=" + from + " --set=K_cx=9e4 --format=tir");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out.find("UNDETERMINED by the data: K_cx"), std::string::npos) << r.out;
  }
}

// export --format=json of a .tir: a parameter set a dataset's initial values
// can be copied from, holding what the .tir determines and nothing else.
TEST(CliTest, ExportOfATirAsJsonWritesTheParameterSetItDetermines) {
  const std::string tno = SourcePath("datasets/examples/tno_205_60R15_belt.tir");
  const std::string out = Scratch("tno_belt.json");
  std::remove(out.c_str());
  RunResult r = Ringid("export --parameters=" + tno + " --set=k_cz=2e5 --format=json --output=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = LoadJson(out);
  EXPECT_EQ(j["format"], "ringid-parameters/1");
  ringid::Parameters back, car;
  ringid::LoadError e;
  ASSERT_TRUE(ringid::LoadParameterSet(out, &back, &e)) << e.OneLine();
  ASSERT_TRUE(ringid::LoadParameterSet(SourcePath("datasets/examples/car_tire.json"), &car, &e));
  std::vector<std::string> names;
  for (auto it = j["parameters"].begin(); it != j["parameters"].end(); ++it) names.push_back(it.key());
  EXPECT_EQ(names, (std::vector<std::string>{"I_bx", "I_by", "I_bz", "k_bgamma", "k_bpsi",
                                             "k_btheta", "k_bx", "k_by", "k_bz", "k_cz", "m_b"}));
  for (const std::string& n : names) {
    const ringid::Param q = *ringid::ParseParam(n);
    EXPECT_DOUBLE_EQ(back[q], car[q]) << n;
  }
  // And back to a .tir: the same belt.
  const std::string again = Scratch("tno_belt_again.tir");
  std::remove(again.c_str());
  r = Ringid("export --parameters=" + out + " --format=tir --output=" + again);
  ASSERT_EQ(r.status, 0) << r.err;
  ringid::TirFile f;
  ASSERT_TRUE(ringid::LoadTir(again, &f, &e)) << e.OneLine();
  EXPECT_DOUBLE_EQ(*f.Find("STRUCTURAL", "FREQ_LAT")->number, 41.47);
  EXPECT_DOUBLE_EQ(*f.Find("VERTICAL", "VERTICAL_STIFFNESS")->number,
                   1 / (1 / car[ringid::Param::k_bz] + 1 / 2e5));
}

// Bad .tir files, bad flags and incomplete sets: exit 2, one line naming the
// file and the key or flag, nothing written.
TEST(CliTest, BadTirOrExportInputIsOneLineExitTwoAndNothingWritten) {
  const std::string dir = Scratch("");
  const std::string car = SourcePath("datasets/examples/car_tire.json");
  const std::string tno = SourcePath("datasets/examples/tno_205_60R15_belt.tir");
  const std::string good = ReadFile(tno);
  const auto with = [&](const std::string& name, const std::string& from, const std::string& to) {
    std::string text = good;
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    std::ofstream(dir + name, std::ios::binary) << text;
    return dir + name;
  };
  const std::string no_lat = with("no_lat.tir", "\nFREQ_LAT", "\n$FREQ_LAT");
  const std::string mm = with("mm.tir", "'meter'", "'mm'");
  const std::string syntax = with("syntax.tir", "= 7.698", "= 7.698 kg");
  const std::string partial = dir + "partial_belt.json";
  std::ofstream(partial) << R"({"format":"ringid-parameters/1","parameters":{"m_b":{"value":7.7}}})";
  const std::string out = dir + "never_written.tir";
  ringid::Parameters all_but_c_bx;  // the TNO belt and c_bx: --set gives the rest but c_bx
  ringid::LoadError e;
  ASSERT_TRUE(ringid::LoadParameters(tno, {}, &all_but_c_bx, &e)) << e.OneLine();
  all_but_c_bx[ringid::Param::c_bx] = 1;
  const std::pair<std::string, std::string> cases[] = {
      {"export --parameters=" + no_lat + " --format=json", "no_lat.tir: [STRUCTURAL] FREQ_LAT: missing"},
      {"predict --parameters=" + no_lat, "no_lat.tir: [STRUCTURAL] FREQ_LAT: missing"},
      {"predict --parameters=" + mm, "mm.tir: [UNITS] LENGTH (line 14): must be 'meter'"},
      {"export --parameters=" + syntax + " --format=tir",
       "syntax.tir: [INERTIA] BELT_MASS (line 21): not a number"},
      {"predict --parameters=" + tno, "tno_205_60R15_belt.tir: I_ay: missing (the model needs it; "
                                      "a .tir describes the tire, not the wheel: give the rim's own "
                                      "inertia (the tire's IYY - BELT_IYY, where the file gives them, "
                                      "is added)): give --set=I_ay=VALUE; also missing: F_cz0"},
      {"predict --parameters=" + tno + " " + SetTheRest(all_but_c_bx, ringid::ExampleCarTire()),
       "c_bx: missing (the model needs it; the .tir has no [STRUCTURAL] DAMP_LONG): give --set=c_bx=VALUE"},
      {"predict --parameters=/nonexistent.tir", "/nonexistent.tir: cannot open file"},
      {"export --parameters=" + car + " --format=xml",
       "--format: unknown format 'xml' (expected tir or json)"},
      {"export --parameters=" + car + " --format=tri",
       "--format: unknown format 'tri' (did you mean 'tir'? expected tir or json)"},
      {"export --parameters=" + car, "export needs --format=tir or json"},
      {"export --format=tir", "export needs --parameters=FILE"},
      {"export --parameters=" + partial + " --format=tir",
       "partial_belt.json: parameters.I_bx: missing (the .tir's [INERTIA] BELT_IXX needs it)"},
      {"export --parameters=" + car + " --format=tir --set=m_b=-1",
       "--set: m_b: bad value '-1' (a positive number)"},
      {"export --parameters=" + car + " --format=tir --set=k_nonsense=1",
       "--set: unknown parameter 'k_nonsense' (expected m_b, I_ay,"},
      {"export --parameters=" + car + " --format=tir --set=k_bxx=1",
       "--set: unknown parameter 'k_bxx' (did you mean 'k_bx'? expected m_b, I_ay,"},
      {"export --parameters=" + car + " --format=tir --set=k_bx=abc",
       "--set: k_bx: bad value 'abc' (a finite number)"},
      {"export --parameters=" + car + " --format=tir --dataset=x.json",
       "--dataset: not a flag of 'export' (it is one of predict,"},
      {"predict --parameters=" + car + " --set=s_h=-1",
       "--set: s_h: bad value '-1' (a number not negative)"},
      {"predict --parameters=" + car + " --effects=hub_compliance --set=s_h=1e-7",
       "--effects: hub_compliance needs m_a: give --set=m_a=VALUE"},
      {"predict --parameters=" + tno + " --effects=hub_compliance " +
           SetTheRest(all_but_c_bx, ringid::ExampleCarTire()) + ",c_bx=1",
       "--effects: hub_compliance needs m_a: give --set=m_a=VALUE"},
      {"simulate --parameters=" + car + " --set=m_b=0 --truth=" + out + ".truth",
       "--set: m_b: bad value '0' (a positive number)"},
  };
  for (const auto& [args, words] : cases) {
    std::remove(out.c_str());
    const RunResult r = Ringid(args + " --output=" + out);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    EXPECT_NE(r.err.find(words), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(Exists(out)) << args;
    EXPECT_FALSE(Exists(out + ".truth")) << args;
  }
  RunResult r = Ringid("export --parameters=" + car + " --format=tir --output=/nonexistent-dir/t.tir");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("/nonexistent-dir/t.tir"), std::string::npos) << r.err;
  // Outputs are checked up front as for every command: export never
  // overwrites its input.
  const std::string copy = dir + "export_input.json";
  std::ofstream(copy) << ReadFile(car);
  r = Ringid("export --parameters=" + copy + " --format=json --output=" + copy);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("is the --parameters input, which it would overwrite"), std::string::npos)
      << r.err;
  EXPECT_EQ(ReadFile(copy), ReadFile(car));
}

// A command line that helps (issue 14).

// Each command lists its flags with their defaults and meaning, from the
// flags' definitions, and the values a named flag takes from the library.
TEST(CliTest, EveryCommandExplainsItsFlagsOnHelp) {
  const std::map<std::string, std::vector<std::string>> expected = {
      {"predict", {"--parameters=TEXT  (default none)", "--effects=LIST", "--set=TEXT"}},
      {"identify", {"--dataset=TEXT  (default none)", "--starts=N  (default 6)",
                    "--method=lm|simplex  (default 'lm')",
                    "--shapes[=BOOL]  (default true; --noshapes for false)",
                    "--relative_sigma=X", "--save_parameters=TEXT", "--output_dir=TEXT",
                    "--effects=LIST  (default none)", "LIST is any of"}},
      {"identifiability", {"--dataset=TEXT", "--derivatives=numeric|analytic|auto  (default 'auto')"}},
      {"compare", {"--starts=N  (default 6)"}},
      {"simulate", {"--set=TEXT", "--shift=X  (default 0)", "--truth=TEXT",
                    "--speeds=TEXT  (default '0')"}},
      {"diagnose", {"--effects=LIST", "--jobs=N  (default 1)", "--shard=TEXT  (default '0/1')",
                    "--level=X  (default 0.001)"}},
      {"bench", {"--suite=paper|synthetic|conditioning|diagnosis|rolling|speed|forces|static|frf|extract  (default none)",
                 "--replicates=N  (default 200)"}},
      {"report", {"--input=TEXT", "--figures_dir=TEXT"}},
      {"export", {"--parameters=TEXT  (default none)", "--set=TEXT",
                  "--format=tir|json  (default none)", "--output=TEXT"}},
      {"schema", {"It takes no flags."}},
  };
  for (const auto& [command, lines] : expected) {
    const RunResult r = Ringid(command + " --help");
    EXPECT_EQ(r.status, 0) << command << ": " << r.err;
    EXPECT_EQ(r.err, "") << command;
    EXPECT_EQ(r.out.rfind("usage: ringid " + command, 0), 0u) << r.out;
    for (const std::string& line : lines) {
      EXPECT_NE(r.out.find(line), std::string::npos) << command << " --help lacks " << line
                                                     << ":\n" << r.out;
    }
    EXPECT_EQ(Ringid("help " + command).out, r.out) << command;
    EXPECT_EQ(Ringid(command + " -h").out, r.out) << command;
  }
  // Flags of other commands are not listed.
  EXPECT_EQ(Ringid("identify --help").out.find("--suite"), std::string::npos);
  // Help wins over the other flags, even bad ones.
  EXPECT_EQ(Ringid("identify --bogus=1 --help").status, 0);
  const RunResult all = Ringid("help");
  EXPECT_EQ(all.status, 0);
  EXPECT_NE(all.out.find("ringid COMMAND --help"), std::string::npos) << all.out;
  EXPECT_NE(all.out.find("ringid simulate --parameters=FILE --output=DATASET --truth=FILE"),
            std::string::npos) << all.out;
}

TEST(CliTest, AFlagsValueMayBeTheNextArgument) {
  const std::string table1 = SourcePath("datasets/paper/table1.json");
  const std::string out = Scratch("next_argument.json");
  std::remove(out.c_str());
  RunResult r = Ringid("identify --dataset " + table1 + " --starts 1 --noshapes --damping" +
                       " --output " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(ReadFile(out));
  const auto& inputs = j["provenance"]["inputs"];
  ASSERT_EQ(inputs.size(), 1u) << j["provenance"].dump();
  EXPECT_EQ(inputs[0]["path"], table1);
  EXPECT_EQ(j["starts"], 1);
  // --noshapes turns the shapes off: the example car tire's 21 modes then
  // give 42 residuals (frequency and damping) instead of 252, less one fitted
  // scale per shape.
  const std::string rolling = SourcePath("datasets/examples/car_tire_rolling.json");
  int dof[2];
  for (int shapes = 0; shapes < 2; ++shapes) {
    r = Ringid("identify --dataset " + rolling + " --starts 1 " +
               (shapes ? "--shapes" : "--noshapes") + " --output " + out);
    ASSERT_EQ(r.status, 0) << r.err;
    dof[shapes] = nlohmann::json::parse(ReadFile(out))["fit"]["degrees_of_freedom"].get<int>();
  }
  EXPECT_EQ(dof[1] - dof[0], 252 - 42 - 21);
  std::remove(out.c_str());
  // A boolean never takes the next argument, and --noNAME takes no value.
  const std::pair<std::string, std::string> cases[] = {
      {"--shapes false", "unexpected argument 'false' (a boolean takes --shapes=false, or "
                         "--shapes or --noshapes alone)"},
      {"--noshapes=true", "--noshapes: takes no value (or write --shapes=false)"},
      {"--starts", "--starts: needs a value (--starts=VALUE or --starts VALUE)"},
      {"--starts --shapes", "--starts: needs a value"},
      {"--starts abc", "--starts: bad value 'abc' (an integer expected)"},
      {"--nostarts", "--nostarts: unknown flag for 'identify'"},
      {"--starts 1 2", "unexpected argument '2'\n"},
      {"x", "unexpected argument 'x'\n"},
  };
  for (const auto& [flags, words] : cases) {
    r = Ringid("identify --dataset " + table1 + " " + flags + " --output=" + out);
    EXPECT_EQ(r.status, 2) << flags;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << flags << ": " << r.err;
    EXPECT_NE(r.err.find(words), std::string::npos) << flags << ": " << r.err;
    EXPECT_FALSE(Exists(out)) << flags;
  }
}

TEST(SpellingTest, ATypoIsNearAndAnotherWordIsNot) {
  EXPECT_EQ(ringid::EditDistance("dataset", "datset"), 1);
  EXPECT_EQ(ringid::EditDistance("label", "lable"), 1);  // two neighbours swapped
  EXPECT_EQ(ringid::EditDistance("", "abc"), 3);
  const std::vector<std::string> flags = {"dataset", "output", "starts", "seed"};
  EXPECT_EQ(ringid::NearestName("datset", flags), "dataset");
  EXPECT_EQ(ringid::NearestName("sed", flags), "seed");
  EXPECT_EQ(ringid::NearestName("frobnicate", flags), std::nullopt);
  EXPECT_EQ(ringid::NearestName("zb", {"x_b", "z_b"}), "z_b");
  EXPECT_EQ(ringid::NearestName("s", {"seed"}), std::nullopt);
  EXPECT_EQ(ringid::UnknownName("flag", "x", {"a", "b", "c"}), "unknown flag 'x' (expected a, b or c)");
  EXPECT_EQ(ringid::UnknownName("flag", "sedd", flags, false), "unknown flag 'sedd' (did you mean 'seed'?)");
}

// A misspelled name, wherever it is given, is answered with the nearest
// valid one and the valid ones.
TEST(CliTest, AMisspelledNameSuggestsTheNearestValidOne) {
  const std::string table1 = SourcePath("datasets/paper/table1.json");
  const std::string bad_label = Scratch("bad_label.json");
  std::ofstream(bad_label) << R"({"format":"ringid-modal-dataset/1","name":"x",)"
                              R"("modes":[{"label":"rotation_inphase","frequency_hz":30}]})";
  const std::string out = Scratch("misspelled.json");
  std::remove(out.c_str());
  const std::pair<std::string, std::string> cases[] = {
      {"identify --dataset=" + bad_label,
       bad_label + ": modes[0].label: unknown label 'rotation_inphase' (did you mean "
                   "'rotation_in_phase'? expected rotation_in_phase, rotation_anti_phase, "
                   "vertical, longitudinal, camber, yaw or lateral)"},
      {"identify --datset=" + table1,
       "--datset: unknown flag for 'identify' (did you mean --dataset?); see 'ringid identify "
       "--help'"},
      {"identify --noshape --dataset=" + table1, "(did you mean --noshapes?)"},
      {"identify --suite=paper --dataset=" + table1,
       "--suite: not a flag of 'identify' (it is one of bench)"},
      {"identfy --dataset=" + table1, "unknown command 'identfy' (did you mean 'identify'?"},
      {"identify --fix=t_0x --dataset=" + table1,
       "--fix: unknown parameter 't_0x' (did you mean 't_0'? expected m_b, I_ay,"},
      {"identify --bounds=k_bxx:1:2 --dataset=" + table1,
       "--bounds: unknown parameter 'k_bxx' (did you mean 'k_bx'?"},
      {"diagnose --effects=hub_complaince --dataset=" + table1,
       "--effects: unknown effect 'hub_complaince' (did you mean 'hub_compliance'? expected "
       "anisotropic_sidewall, hub_compliance,"},
      {"compare --method=lmm --dataset=" + table1,
       "--method: unknown value 'lmm' (did you mean 'lm'? expected lm or simplex)"},
      {"bench --suite=papr", "--suite: unknown suite 'papr' (did you mean 'paper'?"},
  };
  for (const auto& [command, words] : cases) {
    const RunResult r = Ringid(command + " --output=" + out);
    EXPECT_EQ(r.status, 2) << command;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << command << ": " << r.err;
    EXPECT_NE(r.err.find(words), std::string::npos) << command << ": " << r.err;
    EXPECT_FALSE(Exists(out)) << command;
  }
  const RunResult r = Ringid("help simulat");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "ringid: unknown command 'simulat' (did you mean 'simulate'? expected help, "
                   "predict, identify, identifiability, compare, simulate, extract, poles, diagnose, bench, "
                   "report, export, import, merge, forces, schema, inputs, reference or commands); see "
                   "'ringid help'\n");
}

// docs/commands.md is what the help of every command says.
TEST(CliTest, TheCommandReferenceIsWhatEachCommandsHelpSays) {
  const RunResult r = Ringid("commands");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(ReadFile(SourcePath("docs/commands.md")), r.out)
      << "run: build/ringid commands > docs/commands.md";
  EXPECT_NE(r.out.find(Ringid("identify --help").out), std::string::npos);
}

TEST(CliTest, AParameterSetGivenAsADatasetIsNamedAsOne) {
  const std::string set = SourcePath("datasets/paper/parameters.json");
  for (const std::string command : {"identify", "predict", "diagnose"}) {
    const RunResult r = Ringid(command + " --dataset=" + set);
    EXPECT_EQ(r.status, 2) << command;
    EXPECT_EQ(r.err, "ringid: " + set + ": format: this is a parameter set "
                     "(ringid-parameters/1), not a dataset; use --parameters\n") << command;
  }
}

// simulate: an effect needs its size and a size its effect; each defect is
// one line naming the flag and what is missing, and nothing is written.
TEST(CliTest, SimulateRefusesAnEffectWithoutASizeAndASizeWithoutItsEffect) {
  const std::string out = Scratch("sized.json"), truth = Scratch("sized_truth.json");
  const std::pair<std::string, std::string> cases[] = {
      {"--effects=lug_coupling",
       "ringid: --effects: lug_coupling has no size: give --set=k_xy=VALUE (not 0) or "
       "--shift=FRACTION\n"},
      {"--effects=lug_coupling --set=k_xy=0",
       "ringid: --effects: lug_coupling has no size: give --set=k_xy=VALUE (not 0) or "
       "--shift=FRACTION\n"},
      {"--set=s_h=1e-7",
       "ringid: --set: s_h is the size of the effect hub_compliance, which --effects does "
       "not list; add --effects=hub_compliance\n"},
      {"--effects=hub_compliance --set=s_hh=1e-7",
       "ringid: --set: unknown parameter 's_hh' (did you mean 's_h'? expected m_b, I_ay,"},
      {"--effects=hub_compliance --set=s_h=1e-7",
       "ringid: --effects: hub_compliance needs m_a: give --set=m_a=VALUE\n"},
      {"--effects=lug_coupling --set=k_xy=abc",
       "ringid: --set: k_xy: bad value 'abc' (a finite number)\n"},
      {"--effects=lug_coupling --set=k_xy=1e4 --shift=0.05",
       "ringid: --shift: sizes k_xy, which --set gives too; give one of them\n"},
      {"--shift=0.05", "ringid: --shift: needs exactly one effect in --effects"},
  };
  for (const auto& [flags, line] : cases) {
    std::remove(out.c_str());
    std::remove(truth.c_str());
    const RunResult r = Ringid("simulate --parameters=" + SourcePath("datasets/paper/parameters.json") +
                               " " + flags + " --output=" + out + " --truth=" + truth);
    EXPECT_EQ(r.status, 2) << flags;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << flags << ": " << r.err;
    EXPECT_EQ(r.err.rfind(line, 0), 0u) << flags << ": " << r.err;
    EXPECT_FALSE(Exists(out)) << flags;
    EXPECT_FALSE(Exists(truth)) << flags;
  }
  // Sized, they run; an effect's other parameter may be set without it.
  for (const std::string flags : {"--effects=lug_coupling --shift=0.05", "--set=m_a=15",
                                  "--effects=hub_compliance --set=s_h=2e-7,m_a=15"}) {
    const RunResult r = Ringid("simulate --parameters=" + SourcePath("datasets/paper/parameters.json") +
                               " " + flags + " --output=" + out + " --truth=" + truth);
    EXPECT_EQ(r.status, 0) << flags << ": " << r.err;
  }
}

// Every output is checked before any work, exit 2 and nothing written: a
// directory given as a file, one file named twice (however spelled), an
// output that would overwrite an input, and a --figures_dir that cannot be
// made. --figures_dir is made when missing, as --output_dir is.
TEST(CliTest, EveryOutputIsCheckedBeforeAnyWork) {
  const std::string table1 = SourcePath("datasets/paper/table1.json");
  const std::string dir = Scratch("outputs");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir + "/a_directory");
  const std::string copy = dir + "/table1.json";
  std::filesystem::copy_file(table1, copy);
  const std::string same = dir + "/same.json";
  const std::string file = dir + "/a_file";
  std::ofstream(file) << "x";
  const std::string report = Scratch("outputs_identify.json");
  RunResult r = Ringid("identify --starts=1 --dataset=" + table1 + " --output=" + report);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::pair<std::string, std::string> cases[] = {
      {"compare --starts=1 --dataset=" + table1 + " --output=" + dir + "/a_directory",
       "ringid: --output: " + dir + "/a_directory: is a directory, not a file\n"},
      {"identify --dataset=" + table1 + " --output=" + same + " --save_parameters=" + same,
       "ringid: --save_parameters: " + same + " is also --output; give each output its own "
       "file\n"},
      {"identify --dataset=" + table1 + " --output=" + same + " --save_parameters=" + dir +
           "/a_directory/../same.json",
       "ringid: --save_parameters: " + dir + "/a_directory/../same.json is also --output"},
      {"identify --dataset=" + copy + " --output=" + dir + "/./table1.json",
       "ringid: --output: " + dir + "/./table1.json is the --dataset input, which it would "
       "overwrite\n"},
      {"simulate --parameters=" + SourcePath("datasets/paper/parameters.json") + " --output=" + same +
           " --truth=" + same,
       "ringid: --truth: " + same + " is also --output"},
      {"bench --suite=paper --output=" + same + " --markdown=" + same,
       "ringid: --markdown: " + same + " is also --output"},
      {"identify --dataset=" + dir + " --output_dir=" + dir,
       "ringid: --output_dir: " + dir + "/table1.json, the report of " + dir +
           "/table1.json, would overwrite the dataset"},
      {"report --input=" + report + " --output=" + dir + "/page.html --figures_dir=" + file +
           "/figures",
       "ringid: --figures_dir: " + file + "/figures: " + file + " is not a directory\n"},
      {"report --input=" + report + " --output=" + dir + "/page.html --figures_dir=" + file,
       "ringid: --figures_dir: " + file + ": not a directory\n"},
  };
  for (const auto& [command, line] : cases) {
    r = Ringid(command);
    EXPECT_EQ(r.status, 2) << command;
    EXPECT_EQ(r.err.rfind(line, 0), 0u) << command << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << command << ": " << r.err;
    EXPECT_EQ(r.out, "") << command << ": the run went ahead";
  }
  EXPECT_FALSE(Exists(same));
  EXPECT_FALSE(Exists(dir + "/page.html"));
  EXPECT_TRUE(std::filesystem::is_empty(dir + "/a_directory"));
  EXPECT_EQ(ReadFile(copy), ReadFile(table1));

  RINGID_REQUIRE_TOOL(ringid::testing::HaveProgram("gnuplot"), "gnuplot");
  const std::string figures = dir + "/new/figures";
  r = Ringid("report --input=" + report + " --output=" + dir + "/page.html --figures_dir=" +
             figures);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(Exists(dir + "/page.html"));
  EXPECT_FALSE(std::filesystem::is_empty(figures));
}

// Ctrl-C or SIGTERM in the middle of a run: one line saying what was kept
// (nothing: reports are written whole at the end), exit 128 + the signal.
TEST(CliTest, AnInterruptedRunSaysWhatItKept) {
  const std::string dir = Scratch("interrupt");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::pair<int, std::string> signals[] = {{SIGINT, "SIGINT"}, {SIGTERM, "SIGTERM"}};
  for (const auto& [signo, name] : signals) {
    const std::string err = Scratch("interrupt_" + name + ".txt");
    const pid_t pid = StartRingid("bench --suite=synthetic --output=" + dir + "/bench.json --markdown=" +
                                dir + "/bench.md",
                            err);
    std::this_thread::sleep_for(std::chrono::milliseconds(700));
    ::kill(pid, signo);
    EXPECT_EQ(WaitFor(pid), 128 + signo) << name;
    EXPECT_EQ(ReadFile(err), "ringid: interrupted (" + name +
                                 "): nothing written (a report is written whole when its run "
                                 "ends)\n");
    EXPECT_TRUE(std::filesystem::is_empty(dir)) << name << ": a file was left behind";
  }
}

// An interrupted campaign keeps the reports it finished, each whole, and
// says which; its summary is not written.
TEST(CliTest, AnInterruptedCampaignNamesTheReportsItKept) {
  const std::string dir = Scratch("interrupted_campaign");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir + "/data");
  for (const char* name : {"a", "b", "c"}) {
    std::filesystem::copy_file(SourcePath("datasets/paper/table1.json"),
                               dir + "/data/" + name + ".json");
  }
  const std::string err = Scratch("interrupted_campaign.txt");
  const pid_t pid = StartRingid("identify --starts=60 --dataset=" + dir + "/data --output_dir=" + dir +
                              "/out",
                          err);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(3);
  while (!Exists(dir + "/out/a.json") && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(pid, SIGINT);
  ASSERT_EQ(WaitFor(pid), 130) << ReadFile(err);
  std::vector<std::string> kept;
  for (const auto& f : std::filesystem::directory_iterator(dir + "/out")) {
    kept.push_back(f.path().filename().string());
    EXPECT_NO_THROW(nlohmann::json::parse(ReadFile(f.path().string()))) << f.path();
  }
  std::sort(kept.begin(), kept.end());
  ASSERT_GE(kept.size(), 1u);
  ASSERT_LE(kept.size(), 2u) << "the campaign finished before the signal";
  EXPECT_EQ(kept[0], "a.json");
  std::string names;
  for (const std::string& k : kept) names += (names.empty() ? "" : ", ") + k;
  EXPECT_EQ(ReadFile(err), "ringid: interrupted (SIGINT): kept the " +
                               std::to_string(kept.size()) + " of 3 report(s) finished whole, in " +
                               dir + "/out: " + names + "; campaign.json not written\n");
}

// The paper's data are installed with the package and found from any
// directory: by the build tree's binary in its source tree, and by an
// installed binary beside itself (PREFIX/share/ringid), whatever the prefix.
TEST(CliTest, TheSuitesRunFromAnyDirectoryBuiltOrInstalled) {
  const std::string elsewhere = Scratch("elsewhere");
  std::filesystem::create_directories(elsewhere);
  RunResult r = Ringid("bench --suite=paper", elsewhere);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("Table 3 reproduced"), std::string::npos) << r.out;

  const std::string prefix = Scratch("prefix");
  std::filesystem::remove_all(prefix);
  const std::string install = std::string(RINGID_CMAKE) + " --install " + RINGID_BUILD_DIR +
                              " --prefix " + prefix + " > /dev/null";
  ASSERT_EQ(std::system(install.c_str()), 0) << install;
  for (const char* f : {"datasets/paper/table1.json", "datasets/paper/parameters.json",
                        "datasets/examples/car_tire.json"}) {
    EXPECT_TRUE(Exists(prefix + "/share/ringid/" + f)) << f;
  }
  const std::string installed = prefix + "/bin/ringid";
  const std::string out = Scratch("installed_bench.txt");
  const std::string run = "cd " + elsewhere + " && " + installed + " bench --suite=paper > " + out;
  ASSERT_EQ(std::system(run.c_str()), 0) << run;
  EXPECT_NE(ReadFile(out).find("Table 3 reproduced"), std::string::npos);
  // The installed binary reads the installed data, not the source tree's.
  const std::string help = "cd " + elsewhere + " && " + installed + " bench --help > " + out;
  ASSERT_EQ(std::system(help.c_str()), 0) << help;
  EXPECT_NE(ReadFile(out).find(prefix + "/share/ringid/datasets/paper"), std::string::npos)
      << ReadFile(out);
  std::filesystem::remove_all(prefix);
}


// identify and diagnose take a directory or a list of datasets as a
// campaign, which needs --output_dir; without it that is said, not "not valid
// JSON" of the directory. The other fitting commands say they read one file.
TEST(CliTest, ADirectoryOrListWithoutOutputDirIsSaidAsACampaign) {
  const std::string dir = Scratch("one_campaign");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(SourcePath("datasets/paper/table1.json"), dir + "/a.json");
  std::filesystem::copy_file(SourcePath("datasets/paper/table1.json"), dir + "/b.json");
  const std::string list = dir + "/a.json," + dir + "/b.json";
  for (const std::string command : {"identify", "diagnose"}) {
    for (const std::string& datasets : {dir, list}) {
      const RunResult r = Ringid(command + " --dataset=" + datasets);
      EXPECT_EQ(r.status, 2) << command << " " << datasets;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
      EXPECT_NE(r.err.find("--dataset: " + datasets + " is a "), std::string::npos) << r.err;
      EXPECT_NE(r.err.find("campaign: give --output_dir=DIR"), std::string::npos) << r.err;
    }
  }
  for (const std::string command : {"identifiability", "compare"}) {
    const RunResult r = Ringid(command + " --dataset=" + dir);
    EXPECT_EQ(r.status, 2) << command;
    EXPECT_NE(r.err.find("reads one dataset file"), std::string::npos) << r.err;
  }
}

// A file of another kind given as a dataset is named as what it is.
TEST(CliTest, AFileOfAnotherKindIsNamedAsWhatItIs) {
  const std::pair<std::string, std::string> cases[] = {
      {SourcePath("datasets/examples/car_tire_lab.uff"), "this is a UFF file, not a dataset; import"},
      {SourcePath("datasets/examples/tno_205_60R15_belt.tir"),
       "this is an MF-Swift tire property file (.tir), not a dataset; use --parameters"},
      {SourcePath("datasets/examples/car_tire_lab_map.json"),
       "this is a UFF map (ringid-uff-map/1), not a dataset; use import --map"},
      {SourcePath("datasets/examples/car_tire_lug_response.json"),
       "this is a response dataset (ringid-lug-response/1), not a dataset"},
  };
  for (const auto& [file, words] : cases) {
    const RunResult r = Ringid("identify --dataset=" + file);
    EXPECT_EQ(r.status, 2) << file;
    EXPECT_EQ(r.err.rfind("ringid: " + file + ": ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
  }
  // And a modal dataset where a response dataset belongs.
  const RunResult r = Ringid("forces --parameters=" + SourcePath("datasets/examples/car_tire.json") +
                             " --dataset=" + SourcePath("datasets/paper/table1.json"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("this is a modal dataset (ringid-modal-dataset/1), not a response dataset "
                       "(ringid-lug-response/1)"),
            std::string::npos)
      << r.err;
}

// --max_iterations reaches every fitting command; a fit it cuts short says
// "not converged" and what to try, and the same fit with the default
// iterations converges (so the advice is right).
TEST(CliTest, MaxIterationsIsAFlagAndNotConvergedSaysWhatToTry) {
  const std::string table1 = SourcePath("datasets/paper/table1.json");
  RunResult r = Ringid("identify --starts=1 --max_iterations=2 --dataset=" + table1);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("(lm): not converged"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("warning: not converged: the best start used all its 2 "
                       "Levenberg-Marquardt iterations (--max_iterations)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("--max_iterations=8"), std::string::npos) << r.out;
  r = Ringid("identify --starts=1 --dataset=" + table1);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("(lm): converged"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("not converged"), std::string::npos) << r.out;
  for (const std::string command : {"identify", "identifiability", "compare", "diagnose"}) {
    r = Ringid(command + " --max_iterations=0 --dataset=" + table1);
    EXPECT_EQ(r.status, 2) << command;
    EXPECT_EQ(r.err, "ringid: --max_iterations: must be at least 1\n") << command;
    r = Ringid(command + " --help");
    EXPECT_NE(r.out.find("--max_iterations"), std::string::npos) << command;
  }
}

// Notes on where the parameters came from are notes, as predict and import
// print them ("parameters: ..."), not errors ("ringid: ...").
TEST(CliTest, ExportPrintsItsNotesAsNotesNotErrors) {
  const std::string tno = SourcePath("datasets/examples/tno_205_60R15_belt.tir");
  const std::string out = Scratch("noted.json");
  for (const std::string& to : {std::string(), " --output=" + out}) {
    const RunResult r = Ringid("export --parameters=" + tno + " --set=k_cz=2e5 --format=json" + to);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string notes = to.empty() ? r.err : r.out;  // stdout is the file without --output
    EXPECT_NE(notes.find("parameters: "), std::string::npos) << notes;
    EXPECT_EQ(r.err.find("ringid: "), std::string::npos) << r.err;
  }
}

// The terminal's parameter tables give each value's unit (the paper's Table
// 2: N/m for the sidewall's translational stiffnesses, N m/rad for its
// rotational ones, N s/m for its dampers, N for the slip stiffness, m for the
// radii).
TEST(CliTest, TheParameterTablesGiveUnits) {
  const std::string dataset = SourcePath("datasets/template.json");
  const std::map<std::string, std::string> units = {
      {"k_bx", "N/m"}, {"k_btheta", "N m/rad"}, {"c_bx", "N s/m"}, {"K_cx", "N"}, {"r_e0", "m"}};
  for (const std::string command : {"identify", "identifiability"}) {
    const RunResult r = Ringid(command + " --starts=1 --derivatives=analytic --dataset=" + dataset);
    ASSERT_LE(r.status, 1) << r.err;
    EXPECT_NE(r.out.find(" unit "), std::string::npos) << r.out;
    for (const auto& [name, unit] : units) {
      const size_t at = r.out.find("\n  " + name + " ");
      ASSERT_NE(at, std::string::npos) << command << " " << name;
      const std::string line = r.out.substr(at + 1, r.out.find('\n', at + 1) - at - 1);
      EXPECT_NE(line.find(" " + unit + " "), std::string::npos) << command << ": " << line;
    }
  }
}

// A delayed progress (kProgressAfterSeconds for a single run) draws nothing
// before its time, then its line (redrawn while no step comes) and a last one;
// one that ends sooner leaves nothing on the terminal.
TEST(CliTest, ADelayedProgressShowsOnlyOnceItsTimeHasCome) {
  const int master = posix_openpt(O_RDWR | O_NOCTTY);
  ASSERT_GE(master, 0);
  ASSERT_EQ(grantpt(master), 0);
  ASSERT_EQ(unlockpt(master), 0);
  const int terminal = ::open(ptsname(master), O_RDWR | O_NOCTTY);
  ASSERT_GE(terminal, 0);
  std::fflush(stderr);
  const int saved = ::dup(2);
  ::dup2(terminal, 2);  // Progress draws on stderr, when it is a terminal
  const auto shown = [&] {
    std::string text;
    char buffer[4096];
    pollfd p{master, POLLIN, 0};
    while (::poll(&p, 1, 50) > 0) {
      const ssize_t n = ::read(master, buffer, sizeof buffer);
      if (n <= 0) break;
      text.append(buffer, n);
    }
    return text;
  };
  {
    ringid::Progress quick("quick", 0, 0.4);
    quick.Set(1, 4);
    quick.Set(4, 4);
  }
  const std::string after_quick = shown();
  std::string early, late;
  {
    ringid::Progress slow("slow", 0, 0.4);
    slow.Set(1, 4);
    early = shown();
    std::this_thread::sleep_for(std::chrono::milliseconds(700));  // no step: the ticker draws
    late = shown();
    slow.Set(4, 4);
  }
  const std::string last = shown();
  std::fflush(stderr);
  ::dup2(saved, 2);
  ::close(saved);
  ::close(terminal);
  ::close(master);
  EXPECT_EQ(after_quick, "");
  EXPECT_EQ(early, "");
  EXPECT_NE(late.find("slow: 1/4"), std::string::npos) << late;
  EXPECT_NE(last.find("slow: 4/4"), std::string::npos) << last;
  EXPECT_NE(last.find(", took "), std::string::npos) << last;
}

// ringid `args` with its standard error on a pseudo-terminal and standard
// output to a file; what the terminal showed, the exit status and seconds.
std::string OnATerminal(const std::string& args, int* status, double* seconds) {
  const int master = posix_openpt(O_RDWR | O_NOCTTY);
  EXPECT_GE(master, 0);
  EXPECT_EQ(grantpt(master), 0);
  EXPECT_EQ(unlockpt(master), 0);
  const std::string terminal = ptsname(master);
  const std::string shell = "cd " + SourcePath("") + " && exec " + std::string(RINGID_BINARY) + " " +
                            args + " > " + Scratch("terminal_stdout.txt");
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 2, terminal.c_str(), O_RDWR, 0);
  const char* argv[] = {"/bin/sh", "-c", shell.c_str(), nullptr};
  const auto t0 = std::chrono::steady_clock::now();
  pid_t pid = -1;
  EXPECT_EQ(posix_spawn(&pid, "/bin/sh", &files, nullptr, const_cast<char**>(argv), environ), 0);
  posix_spawn_file_actions_destroy(&files);
  std::string shown;
  char buffer[4096];
  for (int raw = 0;;) {
    pollfd p{master, POLLIN, 0};
    if (::poll(&p, 1, 100) > 0) {
      const ssize_t n = ::read(master, buffer, sizeof buffer);
      if (n > 0) shown.append(buffer, n);
    }
    if (::waitpid(pid, &raw, WNOHANG) == pid) {
      *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      while (::poll(&p, 1, 100) > 0) {  // what is left
        const ssize_t n = ::read(master, buffer, sizeof buffer);
        if (n <= 0) break;
        shown.append(buffer, n);
      }
      *status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
      break;
    }
  }
  ::close(master);
  return shown;
}

// Single identifiability and diagnose runs are wired to that progress: on a
// terminal, a run that took over 2.5 s showed it, one under 1.5 s did not.
// Each command's runs go from quick to slow until one took over 2.5 s here.
TEST(CliTest, ALongSingleRunShowsProgressOnATerminal) {
  const std::string tire = " --dataset=" + SourcePath("datasets/template.json");
  const std::string rolling = " --dataset=" + SourcePath("datasets/examples/car_tire_rolling.json");
  const std::vector<std::pair<std::string, std::vector<std::string>>> commands = {
      {"identifiability",
       {"--derivatives=analytic --threads=1" + tire, "--derivatives=analytic" + rolling,
        "--threads=1" + rolling}},
      {"diagnose",
       {"--derivatives=analytic --threads=1 --starts=1" + tire, "--threads=1" + tire,
        "--threads=1" + rolling, "--threads=1 --screen=1" + rolling}}};
  for (const auto& [command, runs] : commands) {
    bool long_run = false;
    for (size_t k = 0; k < runs.size() && !long_run; ++k) {
      int status = -1;
      double seconds = 0;
      const std::string shown = OnATerminal(command + " " + runs[k], &status, &seconds);
      EXPECT_LE(status, 1) << runs[k] << ": " << shown;
      const bool drawn = shown.find(command + ": ") != std::string::npos;
      if (seconds > 2.5) {
        long_run = true;
        EXPECT_TRUE(drawn) << command << " " << runs[k] << " took " << seconds << " s";
        EXPECT_NE(shown.find(", took "), std::string::npos) << shown;
      } else if (seconds < 1.5) {
        EXPECT_FALSE(drawn) << command << " " << runs[k] << " took " << seconds << " s: " << shown;
      }
    }
    EXPECT_TRUE(long_run) << command << ": no run took 2.5 s here";
  }
}

}  // namespace
