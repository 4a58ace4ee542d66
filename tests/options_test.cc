// The options of the operations (operations/options.h): one list each, from
// which the command line's flags and the Python module's keywords are read
// (issue 34), and the flags that list adds to the command line.
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "model/campbell.h"
#include "operations/option_text.h"
#include "operations/options.h"
#include "report/report.h"
#include "test_support.h"

namespace ringid {
namespace {

using testing::ReadFile;
using testing::Ringid;
using testing::RunResult;
using testing::Scratch;
using testing::SourcePath;

std::vector<std::vector<OptionInfo>> Lists() {
  return {OptionsOf<FitSettings>(), OptionsOf<DiagnoseSettings>(),
          OptionsOf<IdentifiabilitySettings>(), OptionsOf<PredictSettings>(),
          OptionsOf<SimulateSettings>(), OptionsOf<ForcesSettings>(), OptionsOf<ExtractSettings>(),
          OptionsOf<PolesSettings>()};
}

// An option several operations take is one flag: one kind, default and
// meaning wherever it is listed, and no list names an option twice.
TEST(OptionsTest, EachOptionHasOneKindDefaultAndMeaning) {
  std::map<std::string, OptionInfo> first;
  int shared = 0;
  for (const auto& list : Lists()) {
    std::vector<std::string> names;
    for (const OptionInfo& o : list) {
      EXPECT_EQ(std::count(names.begin(), names.end(), o.name), 0) << o.name;
      names.push_back(o.name);
      EXPECT_FALSE(o.help.empty()) << o.name;
      const auto [it, inserted] = first.emplace(o.name, o);
      if (inserted) continue;
      ++shared;
      EXPECT_EQ(it->second.kind, o.kind) << o.name;
      EXPECT_EQ(it->second.default_text, o.default_text) << o.name;
      EXPECT_EQ(it->second.help, o.help) << o.name;
    }
  }
  EXPECT_GE(shared, 8);  // effects, set, speeds, fix, seed across the lists (and the fit's in diagnose)
  EXPECT_EQ(first.size(), EveryOption().size());
}

// Each default reads back from its text to itself: the flag registered with
// that text is the library's default (an empty list of loads or band
// aside, which is never read: only a flag given is).
template <class S>
void ExpectDefaultsReadBack() {
  for (const OptionInfo& o : OptionsOf<S>()) {
    S settings;
    std::string error;
    if (o.name == "loads" || o.name == "band") {
      EXPECT_FALSE(SetOption(&settings, o.name, o.default_text, &error));
      continue;
    }
    ASSERT_TRUE(SetOption(&settings, o.name, o.default_text, &error)) << o.name << ": " << error;
    OptionLister again;
    settings.Serialize(&again);
    for (const OptionInfo& a : again.options) {
      if (a.name == o.name) EXPECT_EQ(a.default_text, o.default_text) << o.name;
    }
    EXPECT_TRUE(OfKind(o.kind, o.default_text)) << o.name;
  }
}

TEST(OptionsTest, DefaultsReadBackFromTheirText) {
  ExpectDefaultsReadBack<FitSettings>();
  ExpectDefaultsReadBack<DiagnoseSettings>();
  ExpectDefaultsReadBack<IdentifiabilitySettings>();
  ExpectDefaultsReadBack<PredictSettings>();
  ExpectDefaultsReadBack<SimulateSettings>();
  ExpectDefaultsReadBack<ForcesSettings>();
  // The library's own defaults, not copies: 200 iterations, 6 starts.
  EXPECT_EQ(FitSettings().max_iterations, IdentifyOptions().max_iterations);
  EXPECT_EQ(FitSettings().starts, IdentifyOptions().starts);
  EXPECT_EQ(DiagnoseSettings().level, DiagnoseOptions().effect_significance);
}

// A bad value is the one line `ringid` printed before the lists (ringid
// d01f521, by hand from its flags), naming the option.
TEST(OptionsTest, EachBadValueIsTheOneLineNamingTheOption) {
  const std::vector<std::pair<std::pair<std::string, std::string>, std::string>> cases = {
      {{"starts", "many"}, "--starts: bad value 'many' (an integer expected)"},
      {{"starts", "99999999999"}, "--starts: bad value '99999999999' (an integer expected)"},
      {{"relative_sigma", "x"}, "--relative_sigma: bad value 'x' (a number expected)"},
      {{"shapes", "maybe"}, "--shapes: bad value 'maybe' (true or false expected)"},
      {{"method", ""}, "--method: unknown value '' (expected lm or simplex)"},
      {{"bounds", "k_bx"}, "--bounds: bad item 'k_bx' (NAME:LO:HI)"},
      {{"fix", "k_bxx"}, "--fix: unknown parameter 'k_bxx' (did you mean 'k_bx'?"},
      {{"effects", "hub"}, "--effects: unknown effect 'hub'"},
  };
  for (const auto& [option, line] : cases) {
    FitSettings s;
    std::string error;
    EXPECT_FALSE(SetOption(&s, option.first, option.second, &error)) << option.first;
    EXPECT_EQ(error.substr(0, line.size()), line) << option.first;
  }
  const std::vector<std::pair<std::pair<std::string, std::string>, std::string>> simulate = {
      {{"speeds", "1,1"}, "--speeds: '1' is listed twice"},
      {{"speeds", "-1"}, "--speeds: bad item '-1' (each must be a number >= 0 in m/s)"},
      {{"speeds", ""}, "--speeds: needs a comma-separated list, each item a number >= 0 in m/s"},
      {{"loads", "0"}, "--loads: bad item '0' (each must be a number > 0 in N)"},
      {{"set", "m_b=-1"}, "--set: m_b: bad value '-1' (a positive number)"},
      {{"set", "m_b"}, "--set: bad item 'm_b' (NAME=VALUE)"},
      {{"set", "m_b=x"}, "--set: m_b: bad value 'x' (a finite number)"},
  };
  for (const auto& [option, line] : simulate) {
    SimulateSettings s;
    std::string error;
    EXPECT_FALSE(SetOption(&s, option.first, option.second, &error)) << option.first;
    EXPECT_EQ(error, line) << option.first;
  }
  // A value of the right kind reads as gflags reads it.
  FitSettings s;
  std::string error;
  ASSERT_TRUE(SetOption(&s, "starts", "0x10", &error)) << error;
  EXPECT_EQ(s.starts, 16);
  ASSERT_TRUE(SetOption(&s, "shapes", "No", &error)) << error;
  EXPECT_FALSE(s.shapes);
  ASSERT_TRUE(SetOption(&s, "bounds", "k_bx:1e5:1e7", &error)) << error;
  EXPECT_EQ(s.bounds.at(Param::k_bx).upper, 1e7);
}

// Each command lists the options of its list with the list's defaults.
TEST(OptionsTest, EachCommandsHelpListsItsOptions) {
  const std::map<std::string, std::vector<OptionInfo>> commands = {
      {"identify", OptionsOf<FitSettings>()}, {"diagnose", OptionsOf<DiagnoseSettings>()},
      {"identifiability", OptionsOf<IdentifiabilitySettings>()},
      {"predict", OptionsOf<PredictSettings>()}, {"simulate", OptionsOf<SimulateSettings>()},
      {"forces", OptionsOf<ForcesSettings>()}};
  for (const auto& [command, options] : commands) {
    const RunResult r = Ringid(command + " --help");
    ASSERT_EQ(r.status, 0) << r.err;
    for (const OptionInfo& o : options) {
      const std::string shown = o.kind == OptionKind::kText
                                    ? (o.default_text.empty() ? "none" : "'" + o.default_text + "'")
                                    : o.default_text;
      EXPECT_NE(r.out.find("--" + o.name), std::string::npos) << command << ": " << o.name;
      EXPECT_NE(r.out.find("(default " + shown), std::string::npos) << command << ": " << o.name;
    }
  }
}

// --max_iterations stops Levenberg-Marquardt as the library's option does.
TEST(OptionsTest, MaxIterationsLimitsTheFit) {
  const std::string table1 = SourcePath("datasets/paper/table1.json");
  const std::string base = "identify --starts=1 --derivatives=analytic --dataset=" + table1;
  const auto evaluations = [&](const std::string& flags) {
    const std::string out = Scratch("max_iterations.json");
    const RunResult r = Ringid(base + flags + " --output=" + out);
    EXPECT_NE(r.status, 2) << r.err;
    IdentifyReport report;
    std::string error;
    EXPECT_TRUE(ReadReport(Json::parse(ReadFile(out)), &report, &error)) << error;
    return report.body.result.evaluations;
  };
  EXPECT_LT(evaluations(" --max_iterations=1"), evaluations(""));
  const RunResult r = Ringid(base + " --max_iterations=0");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "ringid: --max_iterations: must be at least 1\n");
}

// predict lists the critical speeds of the orders up to --max_order: the
// same as the longer list's up to that order.
TEST(OptionsTest, MaxOrderCutsTheCriticalSpeeds) {
  const std::string base = "predict --parameters=" + SourcePath("datasets/paper/parameters.json") +
                           " --speeds=0,0.5,5,10,15 --lugs_per_revolution=20";
  const auto critical = [&](const std::string& flags) {
    const std::string out = Scratch("max_order.json");
    const RunResult r = Ringid(base + flags + " --output=" + out);
    EXPECT_EQ(r.status, 0) << r.err;
    PredictReport report;
    std::string error;
    EXPECT_TRUE(ReadReport(Json::parse(ReadFile(out)), &report, &error)) << error;
    return report.body.critical_speeds.value_or(std::vector<CriticalSpeed>{});
  };
  const std::vector<CriticalSpeed> all = critical(" --max_order=" + std::to_string(kMaxOrders)), cut = critical("");
  std::vector<CriticalSpeed> expected;
  for (const CriticalSpeed& c : all) {
    if (c.order <= PredictSettings().max_order) expected.push_back(c);
  }
  ASSERT_FALSE(expected.empty());
  ASSERT_LT(expected.size(), all.size());
  ASSERT_EQ(cut.size(), expected.size());
  for (size_t i = 0; i < cut.size(); ++i) {
    EXPECT_EQ(cut[i].order, expected[i].order);
    EXPECT_EQ(cut[i].speed_m_s, expected[i].speed_m_s);
  }
  EXPECT_EQ(Ringid(base + " --max_order=0").err, "ringid: --max_order: must lie in [1, 200]\n");
}

// forces reads a .tir with --set giving what a .tir cannot hold, as it reads
// the parameter set that export makes of the same.
TEST(OptionsTest, ForcesTakesSetOverATir) {
  const std::string tir = SourcePath("datasets/examples/tno_205_60R15_belt.tir");
  const std::string data = SourcePath("datasets/examples/car_tire_lug_response.json");
  RunResult r = Ringid("forces --parameters=" + tir + " --dataset=" + data);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(tir + ": I_ay: missing"), std::string::npos) << r.err;
  // The car tire's values for what the .tir lacks.
  const std::string car = ReadFile(SourcePath("datasets/examples/car_tire.json"));
  Json values = Json::parse(car)["parameters"];
  std::string set;
  for (const char* name : {"I_ay", "F_cz0", "c_bx", "c_bz", "c_btheta", "K_cx", "sigma_cx", "r_e0",
                           "k_cz", "c_by", "c_bgamma", "c_bpsi", "K_cy", "sigma_cy", "r_l0", "t_0"}) {
    const Json& v = values[name];
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", v.is_object() ? v["value"].get<double>() : v.get<double>());
    set += std::string(set.empty() ? "" : ",") + name + "=" + text;
  }
  const std::string exported = Scratch("tir_set.json"), a = Scratch("forces_tir.json"),
                    b = Scratch("forces_exported.json");
  r = Ringid("export --format=json --parameters=" + tir + " --set=" + set + " --output=" + exported);
  ASSERT_EQ(r.status, 0) << r.err;
  r = Ringid("forces --parameters=" + tir + " --set=" + set + " --dataset=" + data + " --output=" + a);
  ASSERT_EQ(r.status, 0) << r.err;
  r = Ringid("forces --parameters=" + exported + " --dataset=" + data + " --output=" + b);
  ASSERT_EQ(r.status, 0) << r.err;
  Json from_tir = Json::parse(ReadFile(a))["conditions"], from_set = Json::parse(ReadFile(b))["conditions"];
  EXPECT_EQ(from_tir, from_set);
}

}  // namespace
}  // namespace ringid
