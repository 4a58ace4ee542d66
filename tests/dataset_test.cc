// The loader accepts the shipped datasets and refuses each kind of bad file
// with a message naming the field.
#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "datasets/dataset.h"
#include "datasets/file_kind.h"
#include "datasets/parameter_files.h"
#include "datasets/synthetic.h"
#include "model/effects.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using nlohmann::json;

json Valid() {
  return json::parse(R"({
    "format": "ringid-modal-dataset/1", "name": "t",
    "known": {"m_b": 2.37}, "initial": {"k_bx": 3e5}, "ties": {"k_bz": "k_bx"},
    "modes": [{"label": "vertical", "plane": "in_plane", "frequency_hz": 74.5,
               "frequency_sigma_hz": 0.5, "damping_ratio": 0.08,
               "damping_sigma": 0.02, "shape": {"z_b": 1.0, "x_b": 0.01},
               "shape_sigma": 0.05}]})");
}

TEST(DatasetTest, ShippedDatasetsLoad) {
  for (const char* f : {"datasets/paper/table1.json",
                        "datasets/paper/inertia_recovery.json"}) {
    Dataset d;
    LoadError e;
    EXPECT_TRUE(LoadDataset(testing::SourcePath(f), &d, &e)) << e.OneLine();
    EXPECT_EQ(d.modes.size(), 7u);
  }
}

TEST(DatasetTest, ContractExampleLoadsAndRoundTrips) {
  Dataset d, again;
  LoadError e;
  ASSERT_TRUE(ParseDataset(Valid().dump(), "x.json", &d, &e)) << e.OneLine();
  ASSERT_TRUE(ParseDataset(DatasetToJson(d), "y.json", &again, &e)) << e.OneLine();
  EXPECT_EQ(again.modes[0].shape.size(), 2u);
  EXPECT_EQ(again.ties.at(Param::k_bz), Param::k_bx);
}

TEST(DatasetTest, RefusesEveryMalformedDataset) {
  const auto cases = testing::MalformedDatasets();
  EXPECT_GE(cases.size(), 176u);  // the README quotes this count
  for (const auto& bad : cases) {
    Dataset d;
    LoadError e;
    EXPECT_FALSE(ParseDataset(bad.text, "bad.json", &d, &e)) << bad.what;
    const std::string line = e.OneLine();
    EXPECT_EQ(line.rfind("bad.json: ", 0), 0u) << bad.what << ": " << line;
    EXPECT_NE(line.find(bad.field), std::string::npos) << bad.what << ": " << line;
    EXPECT_EQ(line.find('\n'), std::string::npos) << bad.what;
    EXPECT_FALSE(e.message.empty()) << bad.what;
  }
}

// A format-2 dataset of docs/conventions.md §7 with every kind of field.
json Valid2() {
  return json::parse(R"({
    "format": "ringid-modal-dataset/2", "name": "t2", "description": "two speeds",
    "known": {"m_b": 2.37, "r_e0": 0.319}, "initial": {"K_cx": 1.0e4},
    "ties": {"k_bz": "k_bx"},
    "priors": {"K_cx": {"distribution": "lognormal", "median": 1.0e4, "factor_95": 3.0},
               "r_l0": {"distribution": "normal", "mean": 0.30, "sigma": 0.01}},
    "per_condition": ["k_cz", "F_cz0"],
    "conditions": [
      {"name": "standing", "speed_m_s": 0.0, "known": {"F_cz0": 3000},
       "initial": {"k_cz": 2.0e5},
       "modes": [{"label": "vertical", "frequency_hz": 74.5, "frequency_sigma_hz": 0.5},
                 {"label": "camber", "frequency_hz": 60.1,
                  "shape": {"gamma_b": 1.0, "y_b": -0.2}, "shape_sigma": 0.05}]},
      {"name": "drum_6.0-B", "speed_m_s": 6.0, "known": {"F_cz0": 3100},
       "modes": [{"label": "vertical", "frequency_hz": 73.9,
                  "damping_ratio": 0.07, "damping_sigma": 0.01}]}]})");
}

// The error of loading `j`, as one line ("" when it loads).

void ExpectSameModes(const std::vector<MeasuredMode>& a, const std::vector<MeasuredMode>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].label, b[i].label) << i;
    EXPECT_EQ(a[i].condition, b[i].condition) << i;
    EXPECT_EQ(a[i].frequency_hz, b[i].frequency_hz) << i;
    EXPECT_EQ(a[i].frequency_sigma_hz, b[i].frequency_sigma_hz) << i;
    EXPECT_EQ(a[i].damping_ratio, b[i].damping_ratio) << i;
    EXPECT_EQ(a[i].damping_sigma, b[i].damping_sigma) << i;
    EXPECT_EQ(a[i].shape, b[i].shape) << i;
    EXPECT_EQ(a[i].shape_sigma, b[i].shape_sigma) << i;
  }
}

void ExpectSameDataset(const Dataset& a, const Dataset& b) {
  EXPECT_EQ(a.format, b.format);
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.known, b.known);
  EXPECT_EQ(a.initial, b.initial);
  EXPECT_EQ(a.ties, b.ties);
  EXPECT_EQ(a.per_condition, b.per_condition);
  ASSERT_EQ(a.priors.size(), b.priors.size());
  for (const auto& [p, prior] : a.priors) {
    ASSERT_TRUE(b.priors.count(p)) << ParamName(p);
    EXPECT_EQ(prior.distribution, b.priors.at(p).distribution) << ParamName(p);
    EXPECT_EQ(prior.center, b.priors.at(p).center) << ParamName(p);
    EXPECT_EQ(prior.spread, b.priors.at(p).spread) << ParamName(p);
  }
  ASSERT_EQ(a.conditions.size(), b.conditions.size());
  for (size_t i = 0; i < a.conditions.size(); ++i) {
    EXPECT_EQ(a.conditions[i].name, b.conditions[i].name);
    EXPECT_EQ(a.conditions[i].speed_m_s, b.conditions[i].speed_m_s);
    EXPECT_EQ(a.conditions[i].known, b.conditions[i].known);
    EXPECT_EQ(a.conditions[i].initial, b.conditions[i].initial);
  }
  ExpectSameModes(a.modes, b.modes);
}

// Fixing moves the initial value to known (each condition's own for a
// per-condition parameter) and drops the prior; a parameter the dataset does
// not leave free is refused by name, and nothing else changes.
TEST(DatasetTest, FixParametersHoldsTheInitialValues) {
  Dataset d;
  d.path = "d.json";
  d.conditions.resize(2);
  d.conditions[1].name = "drum_6";
  d.initial[Param::K_cx] = 6e4;
  d.initial[Param::k_bx] = 3e5;
  d.known[Param::m_b] = 7.7;
  d.ties[Param::k_bz] = Param::k_bx;
  d.priors[Param::K_cx] = {PriorDistribution::kLognormal, 6e4, 2};
  d.per_condition = {Param::F_cz0};
  d.conditions[0].initial[Param::F_cz0] = 3000;
  d.conditions[1].initial[Param::F_cz0] = 4500;
  std::string why;
  ASSERT_TRUE(FixParameters({Param::K_cx, Param::F_cz0}, &d, &why)) << why;
  EXPECT_EQ(d.known.at(Param::K_cx), 6e4);
  EXPECT_EQ(d.initial.count(Param::K_cx), 0u);
  EXPECT_EQ(d.priors.count(Param::K_cx), 0u);
  EXPECT_EQ(d.conditions[0].known.at(Param::F_cz0), 3000);
  EXPECT_EQ(d.conditions[1].known.at(Param::F_cz0), 4500);
  EXPECT_TRUE(d.conditions[1].initial.empty());
  EXPECT_EQ(d.initial.at(Param::k_bx), 3e5);
  for (Param p : {Param::m_b, Param::k_bz, Param::K_cx}) {
    Dataset copy = d;
    EXPECT_FALSE(FixParameters({p}, &copy, &why));
    EXPECT_NE(why.find(std::string(ParamName(p)) + " is not free in d.json"), std::string::npos);
  }
}

TEST(DatasetTest, FormatOneIsOneStandingCondition) {
  Dataset d;
  LoadError e;
  ASSERT_TRUE(ParseDataset(Valid().dump(), "x.json", &d, &e)) << e.OneLine();
  EXPECT_EQ(d.format, 1);
  ASSERT_EQ(d.conditions.size(), 1u);
  EXPECT_EQ(d.conditions[0].name, "standing");
  EXPECT_EQ(d.conditions[0].speed_m_s, 0.0);
  EXPECT_TRUE(d.conditions[0].known.empty());
  EXPECT_TRUE(d.priors.empty());
  EXPECT_TRUE(d.per_condition.empty());
  for (const MeasuredMode& m : d.modes) EXPECT_EQ(m.condition, 0);
  // Written back as format 1.
  EXPECT_NE(DatasetToJson(d).find("\"ringid-modal-dataset/1\""), std::string::npos);
  EXPECT_EQ(DatasetToJson(d).find("conditions"), std::string::npos);
}

TEST(DatasetTest, FormatTwoLoadsConditionsInFileOrder) {
  Dataset d;
  LoadError e;
  ASSERT_TRUE(ParseDataset(Valid2().dump(), "x.json", &d, &e)) << e.OneLine();
  EXPECT_EQ(d.format, 2);
  ASSERT_EQ(d.conditions.size(), 2u);
  EXPECT_EQ(d.conditions[0].name, "standing");
  EXPECT_EQ(d.conditions[1].name, "drum_6.0-B");
  EXPECT_EQ(d.conditions[1].speed_m_s, 6.0);
  EXPECT_EQ(d.conditions[1].known.at(Param::F_cz0), 3100);
  EXPECT_EQ(d.conditions[0].initial.at(Param::k_cz), 2.0e5);
  // Catalogue order, not file order.
  EXPECT_EQ(d.per_condition, (std::vector<Param>{Param::F_cz0, Param::k_cz}));
  EXPECT_TRUE(d.IsPerCondition(Param::k_cz));
  EXPECT_FALSE(d.IsPerCondition(Param::k_bx));
  ASSERT_EQ(d.modes.size(), 3u);
  EXPECT_EQ(d.modes[0].condition, 0);
  EXPECT_EQ(d.modes[1].condition, 0);
  EXPECT_EQ(d.modes[2].condition, 1);
  EXPECT_EQ(d.modes[2].label, ModeLabel::kVertical);  // once per condition
  EXPECT_EQ(d.priors.at(Param::K_cx).distribution, PriorDistribution::kLognormal);
  EXPECT_EQ(d.priors.at(Param::K_cx).center, 1.0e4);
  EXPECT_EQ(d.priors.at(Param::K_cx).spread, 3.0);
  EXPECT_EQ(d.priors.at(Param::r_l0).distribution, PriorDistribution::kNormal);
  EXPECT_EQ(d.priors.at(Param::r_l0).spread, 0.01);
  EXPECT_EQ(InitialParameters(d, 1)[Param::F_cz0], 3100);
  EXPECT_EQ(InitialParameters(d, 0)[Param::F_cz0], 3000);
}

// Every dataset shipped, and the two of the contract's examples: write, read,
// write gives the same bytes, and the dataset read back is the one written.
TEST(DatasetTest, EveryShippedDatasetWritesReadsAndWritesTheSameBytes) {
  std::vector<std::pair<std::string, std::string>> texts = {{"format 1", Valid().dump()},
                                                            {"format 2", Valid2().dump()}};
  for (const char* f : {"datasets/paper/table1.json", "datasets/paper/table1_priors.json",
                        "datasets/paper/table1_r_l0_physical.json",
                        "datasets/paper/inertia_recovery.json",
                        "datasets/examples/car_tire_rolling.json", "datasets/template.json"}) {
    texts.emplace_back(f, testing::ReadFile(testing::SourcePath(f)));
  }
  for (const auto& [what, text] : texts) {
    Dataset d, again;
    LoadError e;
    ASSERT_TRUE(ParseDataset(text, what, &d, &e)) << e.OneLine();
    const std::string written = DatasetToJson(d);
    ASSERT_TRUE(ParseDataset(written, what, &again, &e)) << e.OneLine() << "\n" << written;
    ExpectSameDataset(d, again);
    EXPECT_EQ(DatasetToJson(again), written) << what;
  }
}

TEST(DatasetTest, FormatTwoRoundTrips) {
  Dataset d, again;
  LoadError e;
  ASSERT_TRUE(ParseDataset(Valid2().dump(), "x.json", &d, &e)) << e.OneLine();
  const std::string text = DatasetToJson(d);
  ASSERT_TRUE(ParseDataset(text, "y.json", &again, &e)) << e.OneLine() << "\n" << text;
  ExpectSameDataset(d, again);
  EXPECT_EQ(DatasetToJson(again), text);
}

TEST(DatasetTest, FormatTwoSpeedDefaultsToZeroAndNeedsNoExtras) {
  json j = Valid2();
  for (const char* key : {"priors", "per_condition", "known", "initial"}) j.erase(key);
  j["conditions"][0].erase("speed_m_s");
  for (json& c : j["conditions"]) c.erase("known"), c.erase("initial");
  Dataset d;
  LoadError e;
  ASSERT_TRUE(ParseDataset(j.dump(), "x.json", &d, &e)) << e.OneLine();
  EXPECT_EQ(d.conditions[0].speed_m_s, 0.0);
  EXPECT_EQ(d.format, 2);
}

TEST(DatasetTest, DatasetBuiltInCodeWithSeveralConditionsIsWrittenAsFormatTwo) {
  Dataset d;
  LoadError e;
  ASSERT_TRUE(ParseDataset(Valid().dump(), "x.json", &d, &e)) << e.OneLine();
  d.conditions.push_back({"drum", 5.0, {}, {}});
  d.modes.push_back(d.modes[0]);
  d.modes.back().condition = 1;
  Dataset again;
  ASSERT_TRUE(ParseDataset(DatasetToJson(d), "y.json", &again, &e)) << e.OneLine();
  d.format = 2;
  ExpectSameDataset(d, again);
}

// Each refused format-2 input: the change to Valid2(), the field the error
// names and a fragment of its message.
struct Refused {
  const char* what;
  std::function<void(json&)> change;
  const char* field;
  const char* message;
};

TEST(DatasetTest, FormatTwoRefusesEachKindOfBadInputNamingTheField) {
  const Refused cases[] = {
      {"top-level modes", [](json& j) { j["modes"] = j["conditions"][0]["modes"]; },
       "modes", "not used in format 2"},
      {"conditions missing", [](json& j) { j.erase("conditions"); }, "conditions", "missing"},
      {"conditions empty", [](json& j) { j["conditions"] = json::array(); },
       "conditions", "non-empty array"},
      {"condition not an object", [](json& j) { j["conditions"][1] = 3; },
       "conditions[1]", "must be an object"},
      {"unknown key in a condition", [](json& j) { j["conditions"][1]["speeed_m_s"] = 1; },
       "conditions[1].speeed_m_s", "unknown key"},
      {"unknown top-level key", [](json& j) { j["prior"] = json::object(); }, "prior",
       "unknown key"},
      {"condition name missing", [](json& j) { j["conditions"][1].erase("name"); },
       "conditions[1].name", "missing"},
      {"condition name empty", [](json& j) { j["conditions"][1]["name"] = ""; },
       "conditions[1].name", "must not be empty"},
      {"condition name with a space", [](json& j) { j["conditions"][1]["name"] = "drum 6"; },
       "conditions[1].name", "letters, digits"},
      {"condition name with @", [](json& j) { j["conditions"][1]["name"] = "a@b"; },
       "conditions[1].name", "letters, digits"},
      {"duplicate condition names",
       [](json& j) { j["conditions"][1]["name"] = "standing"; }, "conditions[1].name",
       "appears twice"},
      {"negative speed", [](json& j) { j["conditions"][1]["speed_m_s"] = -1.0; },
       "conditions[1].speed_m_s", "must not be negative"},
      {"speed not a number", [](json& j) { j["conditions"][1]["speed_m_s"] = "6"; },
       "conditions[1].speed_m_s", "must be a number"},
      {"condition modes missing", [](json& j) { j["conditions"][1].erase("modes"); },
       "conditions[1].modes", "missing"},
      {"condition modes empty", [](json& j) { j["conditions"][1]["modes"] = json::array(); },
       "conditions[1].modes", "non-empty array"},
      {"bad mode in a condition",
       [](json& j) { j["conditions"][1]["modes"][0]["frequency_hz"] = -3.0; },
       "conditions[1].modes[0].frequency_hz", "must be positive"},
      {"label twice within a condition",
       [](json& j) { j["conditions"][0]["modes"].push_back(j["conditions"][0]["modes"][0]); },
       "conditions[0].modes[2].label", "appears twice"},
      {"condition known for a shared parameter",
       [](json& j) { j["conditions"][1]["known"]["k_bx"] = 3e5; },
       "conditions[1].known.k_bx", "is shared: give it at top level, or list it in per_condition"},
      {"condition initial for a shared parameter",
       [](json& j) { j["conditions"][0]["initial"]["K_cx"] = 1e4; },
       "conditions[0].initial.K_cx", "is shared"},
      {"condition known and initial",
       [](json& j) { j["conditions"][0]["initial"]["F_cz0"] = 3000; },
       "conditions[0].initial.F_cz0", "also given in known"},
      {"condition value of the wrong sign",
       [](json& j) { j["conditions"][0]["known"]["F_cz0"] = -1; },
       "conditions[0].known.F_cz0", "must be positive"},
      {"per_condition not an array", [](json& j) { j["per_condition"] = "k_cz"; },
       "per_condition", "must be an array"},
      {"per_condition unknown parameter",
       [](json& j) { j["per_condition"][0] = "k_qq"; }, "per_condition[0]",
       "unknown parameter 'k_qq'"},
      {"per_condition repeated", [](json& j) { j["per_condition"].push_back("k_cz"); },
       "per_condition[2]", "listed twice"},
      {"per_condition also known at top level", [](json& j) { j["known"]["k_cz"] = 2e5; },
       "per_condition[0]", "also given in top-level known"},
      {"per_condition also initial at top level",
       [](json& j) { j["initial"]["F_cz0"] = 3000; }, "per_condition[1]",
       "also given in top-level initial"},
      {"per_condition tied (source)", [](json& j) { j["per_condition"].push_back("k_bz"); },
       "per_condition[2]", "is tied"},
      {"per_condition tied (target)", [](json& j) { j["per_condition"].push_back("k_bx"); },
       "per_condition[2]", "is tied"},
      {"prior on an unknown parameter",
       [](json& j) { j["priors"]["k_qq"] = j["priors"]["r_l0"]; }, "priors.k_qq",
       "unknown parameter"},
      {"priors not an object", [](json& j) { j["priors"] = json::array(); }, "priors",
       "must be an object"},
      {"prior not an object", [](json& j) { j["priors"]["r_l0"] = 0.3; }, "priors.r_l0",
       "must be an object"},
      {"unknown key in a prior", [](json& j) { j["priors"]["r_l0"]["std"] = 0.1; },
       "priors.r_l0.std", "unknown key"},
      {"prior distribution missing", [](json& j) { j["priors"]["r_l0"].erase("distribution"); },
       "priors.r_l0.distribution", "missing"},
      {"prior distribution unknown",
       [](json& j) { j["priors"]["r_l0"]["distribution"] = "uniform"; },
       "priors.r_l0.distribution", "must be normal or lognormal"},
      {"normal prior without mean", [](json& j) { j["priors"]["r_l0"].erase("mean"); },
       "priors.r_l0.mean", "missing"},
      {"normal prior mean not a number", [](json& j) { j["priors"]["r_l0"]["mean"] = "0.3"; },
       "priors.r_l0.mean", "must be a number"},
      {"normal prior without sigma", [](json& j) { j["priors"]["r_l0"].erase("sigma"); },
       "priors.r_l0.sigma", "missing"},
      {"normal prior sigma zero", [](json& j) { j["priors"]["r_l0"]["sigma"] = 0.0; },
       "priors.r_l0.sigma", "must be positive"},
      {"normal prior with a lognormal key",
       [](json& j) { j["priors"]["r_l0"]["factor_95"] = 2.0; }, "priors.r_l0.factor_95",
       "not a key of a normal prior"},
      {"lognormal prior without median", [](json& j) { j["priors"]["K_cx"].erase("median"); },
       "priors.K_cx.median", "missing"},
      {"lognormal prior median not positive",
       [](json& j) { j["priors"]["K_cx"]["median"] = -1.0; }, "priors.K_cx.median",
       "must be positive"},
      {"lognormal prior without factor",
       [](json& j) { j["priors"]["K_cx"].erase("factor_95"); }, "priors.K_cx.factor_95",
       "missing"},
      {"lognormal prior factor 1", [](json& j) { j["priors"]["K_cx"]["factor_95"] = 1.0; },
       "priors.K_cx.factor_95", "must be greater than 1"},
      {"lognormal prior factor below 1",
       [](json& j) { j["priors"]["K_cx"]["factor_95"] = 0.5; }, "priors.K_cx.factor_95",
       "must be greater than 1"},
      {"lognormal prior with a normal key", [](json& j) { j["priors"]["K_cx"]["sigma"] = 2.0; },
       "priors.K_cx.sigma", "not a key of a lognormal prior"},
      {"lognormal prior on a real parameter",
       [](json& j) { j["priors"]["dk_bz"] = j["priors"]["K_cx"]; }, "priors.dk_bz.distribution",
       "positive parameter"},
      {"lognormal prior on a non-negative parameter",
       [](json& j) { j["priors"]["s_h"] = j["priors"]["K_cx"]; }, "priors.s_h.distribution",
       "positive parameter"},
      {"prior on a known parameter",
       [](json& j) { j["priors"]["m_b"] = {{"distribution", "normal"}, {"mean", 2.4},
                                           {"sigma", 0.1}}; },
       "priors.m_b", "a known value needs no prior"},
      {"prior on a tied parameter", [](json& j) { j["priors"]["k_bz"] = j["priors"]["K_cx"]; },
       "priors.k_bz", "is tied"},
      {"prior on a per-condition parameter",
       [](json& j) { j["priors"]["k_cz"] = j["priors"]["K_cx"]; }, "priors.k_cz",
       "priors on per-condition parameters are not supported"},
  };
  ASSERT_EQ(testing::DatasetErrorOf(Valid2()), "");
  for (const Refused& c : cases) {
    json j = Valid2();
    c.change(j);
    const std::string line = testing::DatasetErrorOf(j);
    EXPECT_NE(line.find(std::string("bad.json: ") + c.field + ": "), std::string::npos)
        << c.what << ": " << line;
    EXPECT_NE(line.find(c.message), std::string::npos) << c.what << ": " << line;
  }
}

TEST(DatasetTest, FormatOneRefusesFormatTwoKeysAndUnknownFormats) {
  json j = Valid();
  j["priors"] = json::object();
  EXPECT_NE(testing::DatasetErrorOf(j).find("bad.json: priors: unknown key"), std::string::npos) << testing::DatasetErrorOf(j);
  j = Valid();
  j["format"] = "ringid-modal-dataset/3";
  EXPECT_NE(testing::DatasetErrorOf(j).find("format: must be \"ringid-modal-dataset/1\", "
                            "\"ringid-modal-dataset/2\" or \"ringid-dataset/3\""),
            std::string::npos)
      << testing::DatasetErrorOf(j);
}

// A typo in a label, a parameter or a degree of freedom is answered with the
// nearest valid name and the valid ones; a hub label is not one a dataset may
// name, so it is neither suggested nor listed.
TEST(DatasetTest, AMisspelledNameSuggestsTheNearestValidOne) {
  json j = Valid();
  j["modes"][0]["label"] = "rotation_inphase";
  EXPECT_EQ(testing::DatasetErrorOf(j), "bad.json: modes[0].label: unknown label 'rotation_inphase' (did you "
                        "mean 'rotation_in_phase'? expected rotation_in_phase, "
                        "rotation_anti_phase, vertical, longitudinal, camber, yaw or lateral)");
  j = Valid();
  j["modes"][0]["label"] = "hub_vertical";
  EXPECT_EQ(testing::DatasetErrorOf(j), "bad.json: modes[0].label: 'hub_vertical' is a mode of the hub, which a "
                        "dataset does not list (expected rotation_in_phase, rotation_anti_phase, "
                        "vertical, longitudinal, camber, yaw or lateral)");
  j = Valid();
  j["known"] = {{"m_bb", 2.37}};
  EXPECT_NE(testing::DatasetErrorOf(j).find("known.m_bb: unknown parameter 'm_bb' (did you mean 'm_b'? "
                            "expected m_b, I_ay,"),
            std::string::npos)
      << testing::DatasetErrorOf(j);
  j = Valid();
  j["modes"][0]["shape"] = {{"zb", 1.0}};
  EXPECT_NE(testing::DatasetErrorOf(j).find("modes[0].shape.zb: unknown degree of freedom 'zb' (did you mean "
                            "'z_b'?"),
            std::string::npos)
      << testing::DatasetErrorOf(j);
}

// A parameter set or a report given where a dataset belongs is named as what
// it is, not by the first key a dataset lacks ("parameters: unknown key").
TEST(DatasetTest, AParameterSetOrAReportIsNamedAsWhatItIs) {
  Dataset d;
  LoadError e;
  const std::string set = testing::SourcePath("datasets/paper/parameters.json");
  EXPECT_FALSE(LoadDataset(set, &d, &e));
  EXPECT_EQ(e.OneLine(), set + ": format: this is a parameter set (ringid-parameters/1), not a "
                               "dataset; use --parameters");
  EXPECT_FALSE(ParseDataset(R"({"parameters": {"m_b": 2}})", "x.json", &d, &e));
  EXPECT_EQ(e.OneLine(), "x.json: parameters: this is a parameter set (ringid-parameters/1), "
                         "not a dataset; use --parameters");
  EXPECT_FALSE(ParseDataset(R"({"report": "identify", "schema_version": 2})", "r.json", &d, &e));
  EXPECT_EQ(e.OneLine(), "r.json: report: this is a ringid identify report, not a dataset");
  // And the other way round.
  Parameters p;
  EXPECT_FALSE(LoadParameterSet(testing::SourcePath("datasets/paper/table1.json"), &p, &e));
  EXPECT_NE(e.OneLine().find("format: this is a modal dataset (ringid-modal-dataset/1), not a "
                             "parameter set"),
            std::string::npos)
      << e.OneLine();
}

TEST(DatasetTest, MissingFileIsAnError) {
  Dataset d;
  LoadError e;
  EXPECT_FALSE(LoadDataset("/nonexistent/x.json", &d, &e));
  EXPECT_NE(e.OneLine().find("/nonexistent/x.json"), std::string::npos);
}

}  // namespace
}  // namespace ringid

namespace ringid {
namespace {

bool LoadText(const std::string& text, Parameters* p, LoadError* e) {
  const std::string path = ::testing::TempDir() + "parameter_set_" +
                           std::to_string(::getpid()) + ".json";
  std::ofstream(path) << text;
  return LoadParameterSet(path, p, e);
}

TEST(ParameterSetTest, ReadsTheShippedSetAndRefusesBadOnes) {
  Parameters p;
  LoadError e;
  ASSERT_TRUE(LoadParameterSet(testing::SourcePath("datasets/paper/parameters.json"), &p, &e))
      << e.OneLine();
  EXPECT_NEAR(p[Param::k_bx], 3.84e5, 1);
  const std::pair<std::string, std::string> bad[] = {
      {R"({"parameters": {"k_qq": 1}})", "parameters.k_qq"},
      {R"({"parameters": {"m_b": {"value": "2"}}})", "parameters.m_b.value"},
      {R"({"parameters": {"m_b": 1, "m_b": 2}})", "parameters.m_b: duplicate key"},
      {R"({"format": "x", "parameters": {}})", "format"},
      {R"({"parameters": [1]})", "parameters"},
      {"{\"parameters\":" + std::string(30, '[') + std::string(30, ']') + "}", "nested"},
  };
  for (const auto& [text, field] : bad) {
    EXPECT_FALSE(LoadText(text, &p, &e)) << text;
    EXPECT_NE(e.OneLine().find(field), std::string::npos) << e.OneLine();
  }
}

// A value's fields are ParameterValue's, read by its field list as the
// writer writes them: a std that is no number is refused naming it, and an
// object without a value says the value is missing (the hand reader took the
// first for a set without a std, and the second for a bad number). The other
// fields of an identify report's value and its nulls (not available: as if
// absent), and a bare number, still read.
TEST(ParameterSetTest, AValuesFieldsAreReadByItsFieldList) {
  Parameters p;
  LoadError e;
  const std::pair<std::string, std::string> bad[] = {
      {R"({"parameters": {"m_b": {"value": 2, "std": "big"}}})",
       "parameters.m_b.std: must be a number"},
      {R"({"parameters": {"m_b": {"std": 0.1}}})", "parameters.m_b.value: missing"},
      {R"({"parameters": {"m_b": {"value": 2, "condition": 3}}})",
       "parameters.m_b.condition: must be a string"},
  };
  for (const auto& [text, says] : bad) {
    EXPECT_FALSE(LoadText(text, &p, &e)) << text;
    EXPECT_NE(e.OneLine().find(says), std::string::npos) << e.OneLine();
  }
  ASSERT_TRUE(LoadText(R"({"report": "identify", "parameters": {"m_b": {"value": 2, "unit": "kg",
      "free": true, "std": null, "identifiable": "no", "reason": "r", "condition": null},
      "k_bx": 3e5}})", &p, &e))
      << e.OneLine();
  EXPECT_EQ(p[Param::m_b], 2);
  EXPECT_EQ(p[Param::k_bx], 3e5);
}

// A value written to 17 significant digits reads back as the same double, so
// write, read and write again give the same bytes.
// The shipped sets, read and written, write the same bytes when read again.
TEST(ParameterSetTest, EveryShippedSetWrittenReadsBackToTheSameBytes) {
  for (const char* f : {"datasets/paper/parameters.json", "datasets/examples/car_tire.json"}) {
    Parameters p, again;
    LoadError e;
    ASSERT_TRUE(LoadParameterSet(testing::SourcePath(f), &p, &e)) << e.OneLine();
    const std::string written = ParameterSetToJson(p, "set", f);
    ASSERT_TRUE(LoadText(written, &again, &e)) << e.OneLine();
    EXPECT_EQ(ParameterSetToJson(again, "set", f), written) << f;
  }
}

TEST(ParameterSetTest, WriteReadWriteGivesTheSameBytes) {
  const Parameters truth = ExampleCarTire();
  const std::string first = ParameterSetToJson(truth, "car", "the example car tire");
  const std::string path = testing::Scratch("set.json");
  std::ofstream(path) << first;
  Parameters p;
  LoadError e;
  ASSERT_TRUE(LoadParameterSet(path, &p, &e)) << e.OneLine();
  for (Param q : RigidRingModel().parameters()) EXPECT_EQ(p[q], truth[q]) << ParamName(q);
  EXPECT_EQ(ParameterSetToJson(p, "car", "the example car tire"), first);
}

// The truth of a simulation at two loads and a speed: every value simulated,
// a per-condition one under NAME@CONDITION, reads back.
TEST(TruthFileTest, ReadsBackEveryValueSimulatedAndWritesTheSameBytes) {
  const RigidRingModel model({FindEffect("sensor_mass")});
  Parameters truth = ExampleCarTire();
  truth[Param::dm] = 0.3;
  std::mt19937_64 rng(3);
  const Dataset d = PlanSimulation(truth, 1.5, {0, 10}, {3000, 4500}, &rng);
  ASSERT_EQ(d.conditions.size(), 4u);
  const std::string text = TruthText(MakeTruth(model, truth, d, "data.json"));
  const std::string path = testing::Scratch("truth.json");
  std::ofstream(path) << text;
  Truth t;
  LoadError e;
  ASSERT_TRUE(LoadTruth(path, &t, &e)) << e.OneLine();
  EXPECT_EQ(t.dataset, "data.json");
  EXPECT_EQ(t.effect, "sensor_mass");
  for (Param q : model.parameters()) {
    if (q == Param::F_cz0) continue;  // per condition
    ASSERT_TRUE(t.parameters.count(ParamName(q))) << ParamName(q);
    EXPECT_EQ(t.parameters.at(ParamName(q)).value, truth[q]) << ParamName(q);
  }
  EXPECT_FALSE(t.parameters.count("F_cz0"));
  for (const Condition& c : d.conditions) {
    EXPECT_EQ(t.parameters.at("F_cz0@" + c.name).value, c.known.at(Param::F_cz0)) << c.name;
  }
  EXPECT_EQ(TruthText(t), text);
}

TEST(TruthFileTest, RefusesEachKindOfBadFileNamingTheField) {
  const std::string good =
      R"({"format": "ringid-truth/1", "dataset": "d.json", "effect": "none", )"
      R"("parameters": {"m_b": {"value": 7.7}, "F_cz0@standing": {"value": 4000}}})";
  const std::string path = testing::Scratch("bad_truth.json");
  Truth t;
  LoadError e;
  std::ofstream(path) << good;
  ASSERT_TRUE(LoadTruth(path, &t, &e)) << e.OneLine();
  const std::pair<std::string, std::string> bad[] = {
      {R"({"format": "ringid-truth/2", "dataset": "d", "effect": "none", "parameters": {}})", "format"},
      {R"({"format": "ringid-truth/1", "effect": "none", "parameters": {}})", "dataset"},
      {R"({"format": "ringid-truth/1", "dataset": "d", "effect": "wobble", "parameters": {}})", "effect"},
      {R"({"format": "ringid-truth/1", "dataset": "d", "effect": "none", "parameters": {}, "x": 1})", "x"},
      {R"({"format": "ringid-truth/1", "dataset": "d", "effect": "none", "parameters": {"k_qq": {"value": 1}}})", "parameters.k_qq"},
      {R"({"format": "ringid-truth/1", "dataset": "d", "effect": "none", "parameters": {"m_b": {"value": -1}}})", "parameters.m_b.value"},
      {R"({"format": "ringid-truth/1", "dataset": "d", "effect": "none", "parameters": {"m_b": {"value": "1"}}})", "parameters.m_b.value"},
      {R"({"format": "ringid-truth/1", "dataset": "d", "effect": "none", "parameters": {"m_b": 1, "m_b": 2}})", "parameters.m_b"},
  };
  for (const auto& [text, field] : bad) {
    std::ofstream(path) << text;
    EXPECT_FALSE(LoadTruth(path, &t, &e)) << text;
    EXPECT_EQ(e.file, path);
    EXPECT_EQ(e.field, field) << text << " -> " << e.OneLine();
    EXPECT_FALSE(e.message.empty());
  }
}


// What kind a file is (datasets/file_kind.h), from the formats of docs/inputs.md
// and the UFF syntax of datasets/uff.h.
TEST(FileKindTest, EachKindIsToldByItsFormatItsNameOrItsOpening) {
  const std::pair<const char*, FileKind> formats[] = {
      {"ringid-modal-dataset/1", FileKind::kModalDataset},
      {"ringid-modal-dataset/2", FileKind::kModalDataset},
      {"ringid-parameters/1", FileKind::kParameterSet},
      {"ringid-truth/1", FileKind::kTruth},
      {"ringid-lug-response/1", FileKind::kResponseDataset},
      {"ringid-lug-forces/1", FileKind::kLugForces},
      {"ringid-uff-map/1", FileKind::kUffMap},
      {"ringid-uff-map/2", FileKind::kUffMap},
      {"ringid-frf-spec/1", FileKind::kFrfSpec},
      {"ringid-modal-dataset/9", FileKind::kUnknown}};
  for (const auto& [format, kind] : formats) {
    EXPECT_EQ(SniffJson(json{{"format", format}}).kind, kind) << format;
  }
  EXPECT_EQ(SniffJson(json{{"report", "identify"}}).kind, FileKind::kReport);
  EXPECT_EQ(SniffJson(json{{"parameters", json::object()}}).kind, FileKind::kParameterSet);
  EXPECT_EQ(SniffJson(json{{"parameters", json::object()}, {"modes", json::array()}}).kind,
            FileKind::kUnknown);
  EXPECT_EQ(SniffPath("tire.TIR").kind, FileKind::kTir);
  EXPECT_EQ(SniffPath(testing::SourcePath("datasets")).kind, FileKind::kDirectory);
  EXPECT_EQ(SniffFile("x", "\n    -1\n    55\n").kind, FileKind::kUff);
  EXPECT_EQ(SniffFile("x", "    -1\n    58b     1     2\n").kind, FileKind::kUff);
  EXPECT_EQ(SniffFile("x", "    -1\n    fifty-five\n").kind, FileKind::kUnknown);
  EXPECT_EQ(SniffFile("x", "-1\n").kind, FileKind::kUnknown);  // JSON's -1, not a UFF file
  EXPECT_EQ(SniffFile("x", "{\"format\": \"ringid-parameters/1\"}").kind, FileKind::kUnknown);
}

}  // namespace
}  // namespace ringid
