// A test lab's UFF modes as a ringid dataset (docs/uff.md): the public
// dataset-55 files read to the values of their text under a map; a file
// written here from the model's own modes (complex, turned by arbitrary
// phases, in millimetres, shuffled) is labelled by the model as the truth;
// bad maps are refused naming the field; `ringid import` writes a dataset
// identify reads, and nothing on bad input.
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "datasets/measurement.h"
#include "datasets/synthetic.h"
#include "datasets/uff.h"
#include "datasets/uff_dataset.h"
#include "estimation/label_by_fit.h"
#include "model/rigid_ring_model.h"
#include "tests/test_support.h"

namespace ringid {
namespace {

using testing::Ringid;
using testing::RunResult;
using testing::Scratch;


using UffImportCorpusTest = testing::CorpusTest;


double ShapeOf(const MeasuredMode& m, Dof dof) {
  for (const auto& [d, v] : m.shape) {
    if (d == dof) return v;
  }
  ADD_FAILURE() << DofName(dof);
  return NAN;
}

TEST_F(UffImportCorpusTest, TheModesOfAPublicFileReadAsItsTextSaysUnderAMap) {
  UffFile file;
  LoadError e;
  ASSERT_TRUE(LoadUff(testing::UffCorpus("uff55_translation.uff"), &file, &e)) << e.OneLine();
  const UffMap map = testing::ParsedUffMap(R"({"format": "ringid-uff-map/1", "name": "t",
      "channels": [{"node": 1, "direction": 3, "dof": "z_b"},
                   {"node": 2, "direction": 1, "dof": "x_b", "sign": -1}],
      "labels": [{"mode": 1, "label": "vertical"}, {"mode": 2, "label": "longitudinal"},
                 {"mode": 3, "label": "rotation_in_phase"}]})");
  UffImport in;
  ASSERT_TRUE(UffToDataset(file, map, nullptr, &in, &e)) << e.OneLine();
  const Dataset& d = in.dataset;
  ASSERT_EQ(d.modes.size(), 3u);
  // The text: mode 1 at 1.00000e+01 Hz, node 1 -1.46518e+00, node 2
  // 1.50162e-01 (each node's three values equal); mode 2 at 12 Hz, node 1
  // 1.82904e+00, node 2 -3.98226e-02; mode 3 at 13 Hz, -6.34670e-01 and
  // -6.62803e-01. Damping 0 is no measurement.
  const double hz[] = {10, 12, 13}, z[] = {-1.46518, 1.82904, -0.634670},
               x[] = {-0.150162, 0.0398226, 0.662803};
  const ModeLabel labels[] = {ModeLabel::kVertical, ModeLabel::kLongitudinal,
                              ModeLabel::kRotationInPhase};
  for (int i = 0; i < 3; ++i) {
    const MeasuredMode& m = d.modes[i];
    EXPECT_EQ(m.label, labels[i]);
    EXPECT_EQ(m.frequency_hz, hz[i]);
    EXPECT_FALSE(m.damping_ratio);
    // Real as the contract's §2: the largest component +1, the other in ratio.
    const double largest = std::abs(z[i]) > std::abs(x[i]) ? z[i] : x[i];
    EXPECT_NEAR(ShapeOf(m, Dof::kZb), z[i] / largest, 1e-12) << i;
    EXPECT_NEAR(ShapeOf(m, Dof::kXb), x[i] / largest, 1e-12) << i;
  }
  EXPECT_NE(in.notes.front().find("no dataset 164"), std::string::npos) << in.notes.front();
}

TEST_F(UffImportCorpusTest, AComplexEigenvalueGivesTheDampedFrequencyAndItsRatio) {
  UffFile file;
  LoadError e;
  ASSERT_TRUE(LoadUff(testing::UffCorpus("uff55_sample_test_record10.uff"), &file, &e)) << e.OneLine();
  // Record 8: -1.111111E-01 4.111111E+01 (the eigenvalue); node 111111's z
  // value 7.111111E-03 + 4.111111E-03 i and y 1.111111E-01 + 9.111111E-02 i.
  const UffMap map = testing::ParsedUffMap(R"({"format": "ringid-uff-map/1", "name": "r",
      "channels": [{"node": 111111, "direction": 2, "dof": "y_b"},
                   {"node": 111111, "direction": 3, "dof": "psi_b"}],
      "labels": [{"mode": 1, "label": "lateral"}]})");
  UffImport in;
  ASSERT_TRUE(UffToDataset(file, map, nullptr, &in, &e)) << e.OneLine();
  const MeasuredMode& m = in.dataset.modes.at(0);
  const std::complex<double> lambda(-1.111111e-01, 4.111111e+01);
  EXPECT_NEAR(m.frequency_hz, 4.111111e+01 / (2 * M_PI), 1e-12);
  ASSERT_TRUE(m.damping_ratio);
  EXPECT_NEAR(*m.damping_ratio, 1.111111e-01 / std::abs(lambda), 1e-15);
  const std::complex<double> y(1.111111e-01, 9.111111e-02), psi(7.111111e-03, 4.111111e-03);
  EXPECT_NEAR(ShapeOf(m, Dof::kYb), 1, 1e-15);
  EXPECT_NEAR(ShapeOf(m, Dof::kPsiB), std::real(psi * std::conj(y)) / std::norm(y), 1e-12);
}

// A dataset-55 record of mode `number` with complex shape values per node.
std::string Record55(int number, std::complex<double> lambda,
                     const std::vector<std::pair<int, std::vector<std::complex<double>>>>& nodes) {
  char line[200];
  std::string out = "    -1\n    55\nringid: a model mode of the example car tire, written as a lab would\nNONE\nNONE\nNONE\nNONE\n";
  out += "         1         3         2         8         5         3\n";
  std::snprintf(line, sizeof line, "%10d%10d%10d%10d\n", 2, 6, 1, number);
  out += line;
  std::snprintf(line, sizeof line, "%13.5E%13.5E%13.5E%13.5E%13.5E%13.5E\n", lambda.real(),
                lambda.imag(), 1.0, 0.0, 0.0, 0.0);
  out += line;
  for (const auto& [label, values] : nodes) {
    std::snprintf(line, sizeof line, "%10d\n", label);
    out += line;
    for (const std::complex<double>& v : values) {
      std::snprintf(line, sizeof line, "%13.5E%13.5E", v.real(), v.imag());
      out += line;
    }
    out += "\n";
  }
  return out + "    -1\n";
}

// The import keeps the damping ratios the JSON loader takes, the open (0, 1)
// of DampingRatioProblem: a lightly damped mode of zeta = 1e-7 (from the
// eigenvalue -zeta w + i w sqrt(1 - zeta^2), 6 digits written) keeps its
// ratio, as the same ratio in a JSON dataset loads (the import had dropped
// ratios below 1e-6); an unstable eigenvalue (zeta = -0.1) is left out with a
// note, as the loader refuses its ratio.
TEST(UffImportTest, KeepsEveryDampingRatioTheJsonLoaderTakes) {
  const UffMap map = testing::ParsedUffMap(R"({"format": "ringid-uff-map/1", "name": "d",
      "channels": [{"node": 1, "direction": 3, "dof": "z_b"}],
      "labels": [{"mode": 1, "label": "vertical"}]})");
  const double w = 2 * M_PI * 50;
  for (const double zeta : {1e-7, -0.1}) {
    const std::complex<double> lambda(-zeta * w, w * std::sqrt(1 - zeta * zeta));
    UffFile file;
    LoadError e;
    ASSERT_TRUE(ParseUff(Record55(1, lambda, {{1, {0.0, 0.0, 1.0}}}), "d.uff", &file, &e))
        << e.OneLine();
    UffImport in;
    ASSERT_TRUE(UffToDataset(file, map, nullptr, &in, &e)) << e.OneLine();
    const std::optional<double> read = in.dataset.modes.at(0).damping_ratio;
    const double written = -lambda.real() / std::abs(lambda);
    char ratio[32];
    std::snprintf(ratio, sizeof ratio, "%.17g", written);
    Dataset json;
    const std::string text =
        R"({"format": "ringid-modal-dataset/1", "name": "d", "modes": [{"label": "vertical",
            "frequency_hz": 50, "damping_ratio": )" + std::string(ratio) + "}]}";
    const bool loads = ParseDataset(text, "d.json", &json, &e);
    EXPECT_EQ(read.has_value(), loads) << zeta << ": " << e.OneLine();
    if (zeta > 0) {
      ASSERT_TRUE(read) << zeta;
      EXPECT_NEAR(*read, zeta, 1e-5 * zeta);
    } else {
      EXPECT_FALSE(read);
      bool noted = false;
      for (const std::string& note : in.notes) noted |= note.find("left out") != std::string::npos;
      EXPECT_TRUE(noted);
    }
  }
}

// The car tire's modes written as a lab would: node 1 holds the belt's
// translations x, y, z (in millimetres, dataset 164), node 2 its rotations,
// node 3 the rim's;
// each mode's shape turned by a phase and scaled, the modes shuffled.
std::string LabFile(const ModalSolution& s, std::vector<ModeLabel>* order) {
  std::string text =
      "    -1\n   164\n         5mm (milli newton)           2\n"
      "  1.00000000000000000D+03  1.00000000000000000D+00  1.00000000000000000D+00\n"
      "  2.73150000000000000D+02\n    -1\n";
  std::vector<int> index(s.modes.size());
  for (size_t i = 0; i < index.size(); ++i) index[i] = static_cast<int>(i);
  std::mt19937_64 rng(55);
  std::shuffle(index.begin(), index.end(), rng);
  std::uniform_real_distribution<double> phase(-M_PI, M_PI), scale(0.5, 3);
  for (size_t k = 0; k < index.size(); ++k) {
    const Mode& m = s.modes[index[k]];
    order->push_back(m.label);
    const std::complex<double> turn = std::polar(scale(rng), phase(rng));
    const auto at = [&](Dof d) { return turn * m.shape(static_cast<int>(d)); };
    const double mm = 1000;
    text += Record55(static_cast<int>(k) + 1, m.eigenvalue,
                     {{1, {mm * at(Dof::kXb), mm * at(Dof::kYb), mm * at(Dof::kZb)}},
                      {2, {at(Dof::kGammaB), at(Dof::kThetaB), at(Dof::kPsiB)}},
                      {3, {0.0, at(Dof::kThetaA), 0.0}}});
  }
  return text;
}

constexpr const char* kLabMap = R"({"format": "ringid-uff-map/1", "name": "lab",
    "channels": [{"node": 1, "direction": 1, "dof": "x_b"}, {"node": 1, "direction": 2, "dof": "y_b"},
                 {"node": 1, "direction": 3, "dof": "z_b"}, {"node": 2, "direction": 1, "dof": "gamma_b"},
                 {"node": 2, "direction": 2, "dof": "theta_b"}, {"node": 2, "direction": 3, "dof": "psi_b"},
                 {"node": 3, "direction": 2, "dof": "theta_a"}],
    "known": ["m_b", "I_ay", "I_by", "I_bx", "I_bz", "F_cz0"]})";

// LabFile of the modes at `p`, read back; `labels` the truth's, in file order.
UffFile ReadLabFile(const Parameters& p, ModalSolution* s, std::vector<ModeLabel>* labels) {
  *s = RigidRingModel().Solve(p);
  EXPECT_TRUE(s->ok);
  UffFile file;
  LoadError e;
  EXPECT_TRUE(ParseUff(LabFile(*s, labels), "lab.uff", &file, &e)) << e.OneLine();
  return file;
}

TEST(UffImportTest, TheModelLabelsTheModesTheMapDoesNotAsTheTruth) {
  const Parameters p = ExampleCarTire();
  ModalSolution s;
  std::vector<ModeLabel> truth;
  const UffFile file = ReadLabFile(p, &s, &truth);
  LoadError e;
  UffImport in;
  ASSERT_TRUE(UffToDataset(file, testing::ParsedUffMap(kLabMap), &p, &in, &e)) << e.OneLine();
  const Dataset& d = in.dataset;
  ASSERT_EQ(d.modes.size(), truth.size());
  for (size_t i = 0; i < truth.size(); ++i) {
    const MeasuredMode& m = d.modes[i];
    EXPECT_EQ(m.label, truth[i]) << i;
    const Mode* model = s.Find(truth[i]);
    ASSERT_NE(model, nullptr);
    EXPECT_NEAR(m.frequency_hz, model->frequency_hz, 1e-4 * model->frequency_hz);  // 6 digits written
    EXPECT_NEAR(*m.damping_ratio, model->damping_ratio, 1e-4);
    // Millimetres back to metres: the shape is the model's, MAC 1.
    EXPECT_GT(Mac(ComparableShape(*model, ShapeConvention::kContract, m.shape), m.shape), 1 - 1e-8);
  }
  EXPECT_EQ(d.known.size(), 6u);
  EXPECT_EQ(d.known.at(Param::m_b), p[Param::m_b]);
  EXPECT_EQ(d.initial.at(Param::k_bx), p[Param::k_bx]);
  // A label the user gives is kept, and the model labels the rest around it.
  const std::string with_label = std::string(kLabMap).insert(
      std::string(kLabMap).size() - 1,
      R"(, "labels": [{"mode": 2, "label": ")" + std::string(LabelName(truth[1])) + "\"}]");
  ASSERT_TRUE(UffToDataset(file, testing::ParsedUffMap(with_label), &p, &in, &e)) << e.OneLine();
  for (size_t i = 0; i < truth.size(); ++i) EXPECT_EQ(in.dataset.modes[i].label, truth[i]);
}

// The names an import writes do not depend on the guess. Twelve guesses,
// each stiffness, damper and contact value of the truth scaled by 3^U(-1,1):
// at the guess the model names some modes differently (a camber mode
// "lateral", an in-plane rotation "longitudinal"); labelled by the fitted
// model every guess gives the truth's names.
TEST(UffImportTest, TheNamesAreTheTruthsFromScatteredGuessesOnceFitted) {
  const Parameters truth = ExampleCarTire();
  ModalSolution s;
  std::vector<ModeLabel> names;
  const UffFile file = ReadLabFile(truth, &s, &names);
  ASSERT_EQ(names.size(), 7u);
  LoadError e;
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(-1, 1);
  IdentifyOptions o;
  o.residuals.derivatives = Derivatives::kAnalytic;
  int wrong_at_guess = 0;
  for (int g = 0; g < 12; ++g) {
    Parameters guess = truth;
    for (Param q : RigidRingModel().parameters()) {
      const std::string name = ParamName(q);
      const bool scaled = name.rfind("k_", 0) == 0 || name.rfind("c_", 0) == 0 ||
                          name.rfind("K_c", 0) == 0 || name.rfind("sigma_c", 0) == 0;
      if (scaled) guess[q] = truth[q] * std::pow(3.0, u(rng));
    }
    UffImport at_guess, fitted;
    ASSERT_TRUE(UffToDataset(file, testing::ParsedUffMap(kLabMap), &guess, &at_guess, &e)) << e.OneLine();
    ASSERT_TRUE(UffToDatasetLabelledByFit(file, testing::ParsedUffMap(kLabMap), guess, o, &fitted, &e))
        << e.OneLine();
    for (size_t i = 0; i < names.size(); ++i) {
      wrong_at_guess += at_guess.dataset.modes[i].label != names[i];
      EXPECT_EQ(fitted.dataset.modes[i].label, names[i]) << "guess " << g << ", mode " << i;
    }
    // The values written are still the guess's, not the fit's.
    for (const auto& [q, value] : fitted.dataset.initial) EXPECT_EQ(value, guess[q]) << ParamName(q);
    EXPECT_EQ(fitted.dataset.known, at_guess.dataset.known);
  }
  EXPECT_GT(wrong_at_guess, 0);  // without the fit the names do depend on the guess
}

// datasets/examples/car_tire_lab.uff is LabFile of the example car tire, and
// car_tire_lab_map.json its map (the README's example); RINGID_REGENERATE=1
// writes the file again.
TEST(UffImportTest, TheShippedLabExampleIsTheCarTiresModesUnderItsMap) {
  std::vector<ModeLabel> truth;
  const std::string text = LabFile(RigidRingModel().Solve(ExampleCarTire()), &truth);
  const std::string path = testing::SourcePath("datasets/examples/car_tire_lab.uff");
  if (std::getenv("RINGID_REGENERATE")) std::ofstream(path) << text;
  EXPECT_EQ(testing::ReadFile(path), text)
      << "RINGID_REGENERATE=1 build/tests/data_tests --gtest_filter=*ShippedLab*";
  UffMap shipped, here = testing::ParsedUffMap(kLabMap);
  LoadError e;
  ASSERT_TRUE(LoadUffMap(testing::SourcePath("datasets/examples/car_tire_lab_map.json"), &shipped, &e))
      << e.OneLine();
  ASSERT_EQ(shipped.channels.size(), here.channels.size());
  for (size_t i = 0; i < here.channels.size(); ++i) {
    EXPECT_EQ(shipped.channels[i].node, here.channels[i].node);
    EXPECT_EQ(shipped.channels[i].direction, here.channels[i].direction);
    EXPECT_EQ(shipped.channels[i].dof, here.channels[i].dof);
    EXPECT_EQ(shipped.channels[i].sign, here.channels[i].sign);
  }
  EXPECT_EQ(shipped.known, here.known);
}

TEST(UffImportTest, BadMapsAndUnlabelledModesAreRefusedNamingTheField) {
  const std::string head = R"({"format": "ringid-uff-map/1", "name": "m", )";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"format": "ringid-uff-map/3", "name": "m", "channels": []})", "format"},
      {head + R"("channels": []})", "channels"},
      {head + R"("channels": [{"node": 1, "direction": 3, "dof": "z_bb"}]})", "channels[0].dof"},
      {head + R"("channels": [{"node": 1, "direction": 7, "dof": "z_b"}]})", "channels[0].direction"},
      {head + R"("channels": [{"node": 0, "direction": 3, "dof": "z_b"}]})", "channels[0].node"},
      {head + R"("channels": [{"node": 1, "direction": 3, "dof": "z_b", "sign": 2}]})", "channels[0].sign"},
      {head + R"("channels": [{"node": 1, "direction": 3, "dof": "z_b"}, {"node": 1, "direction": -3, "dof": "x_b"}]})", "channels[1]"},
      {head + R"("channels": [{"node": 1, "direction": 3, "dof": "z_b"}], "labels": [{"mode": 1, "label": "vertikal"}]})", "labels[0].label"},
      {head + R"("channels": [{"node": 1, "direction": 3, "dof": "z_b"}], "labels": [{"mode": 1, "label": "vertical"}, {"mode": 2, "label": "vertical"}]})", "labels[1].label"},
      {head + R"("channels": [{"node": 1, "direction": 3, "dof": "z_b"}], "known": ["m_bb"]})", "known"},
      {head + R"("channels": [{"node": 1, "direction": 3, "dof": "z_b"}], "extra": 1})", "extra"},
      {head + R"("channels": [{"node": "one", "direction": 3, "dof": "z_b"}]})", "channels[0].node"},
  };
  for (const auto& [json, field] : cases) {
    UffMap map;
    LoadError e;
    EXPECT_FALSE(ParseUffMap(json, "map.json", &map, &e)) << json;
    EXPECT_EQ(e.field, field) << json << ": " << e.OneLine();
    EXPECT_EQ(e.OneLine().find('\n'), std::string::npos);
  }
}

TEST_F(UffImportCorpusTest, UnlabelledAndMissingModesOfAPublicFileAreRefusedNamingTheField) {
  const std::string head = R"({"format": "ringid-uff-map/1", "name": "m", )";
  UffFile file;
  LoadError e;
  ASSERT_TRUE(LoadUff(testing::UffCorpus("uff55_translation.uff"), &file, &e)) << e.OneLine();
  UffImport in;
  const UffMap map = testing::ParsedUffMap(head + R"("channels": [{"node": 1, "direction": 3, "dof": "z_b"}]})");
  EXPECT_FALSE(UffToDataset(file, map, nullptr, &in, &e));
  EXPECT_EQ(e.field, "labels");
  EXPECT_NE(e.message.find("3 modes have no label"), std::string::npos) << e.OneLine();
  const UffMap missing = testing::ParsedUffMap(head + R"("channels": [{"node": 1, "direction": 3, "dof": "z_b"}],
      "labels": [{"mode": 9, "label": "vertical"}]})");
  EXPECT_FALSE(UffToDataset(file, missing, nullptr, &in, &e));
  EXPECT_NE(e.message.find("mode 9 is not in the file"), std::string::npos) << e.OneLine();
}

TEST(UffImportTest, TheCommandWritesADatasetIdentifyReadsAndNothingOnBadInput) {
  const Parameters p = ExampleCarTire();
  std::vector<ModeLabel> truth;
  const std::string uff = Scratch("lab.uff"), map = Scratch("lab_map.json");
  std::ofstream(uff) << LabFile(RigidRingModel().Solve(p), &truth);
  std::ofstream(map) << kLabMap;
  const std::string out = Scratch("lab_dataset.json");
  std::remove(out.c_str());
  const std::string car = testing::SourcePath("datasets/examples/car_tire.json");
  RunResult r = Ringid("import --uff=" + uff + " --map=" + map + " --parameters=" + car +
                       " --output=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("labelled"), std::string::npos) << r.out;
  r = Ringid("identify --starts=1 --dataset=" + out);
  EXPECT_EQ(r.status, 0) << r.err;
  r = Ringid("import --uff=" + uff);  // lists what the file holds
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("modes (55)"), std::string::npos) << r.out;
  const std::string bad = Scratch("bad_map.json");
  std::ofstream(bad) << R"({"format": "ringid-uff-map/1", "name": "m", "channels": [{"node": 1, "direction": 3, "dof": "zb"}]})";
  for (const std::string& args :
       {"import --uff=" + uff + " --map=" + bad + " --output=" + out,
        "import --uff=" + map + " --map=" + map + " --output=" + out,
        "import --uff=" + uff + " --map=" + map + " --output=" + out}) {  // no labels, no parameters
    std::remove(out.c_str());
    r = Ringid(args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.out;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(testing::Exists(out)) << args;
  }
}


// A map channel on a node the file's modes do not hold would drop that degree
// of freedom from every shape: it is refused, naming the node, its direction
// and the file, exit 2, nothing written.
TEST(UffImportTest, AMappedNodeTheFileDoesNotHoldIsRefusedNamingIt) {
  const Parameters p = ExampleCarTire();
  ModalSolution s;
  std::vector<ModeLabel> truth;
  const UffFile file = ReadLabFile(p, &s, &truth);  // nodes 1, 2 and 3 (LabFile)
  std::string json = kLabMap;
  const std::string extra = R"({"node": 9, "direction": 2, "dof": "y_a"}, )";
  json.insert(json.find("{\"node\": 1"), extra);
  const UffMap map = testing::ParsedUffMap(json);
  UffImport in;
  LoadError e;
  EXPECT_FALSE(UffToDataset(file, map, &p, &in, &e));
  EXPECT_EQ(e.file, "lab.uff");
  EXPECT_NE(e.message.find("node 9 direction 2"), std::string::npos) << e.OneLine();
  EXPECT_NE(e.message.find("channels[0]"), std::string::npos) << e.OneLine();
  EXPECT_NE(e.message.find("its nodes: 1, 2, 3"), std::string::npos) << e.OneLine();
  // A direction the node does not hold (LabFile writes three values a node).
  std::string beyond = kLabMap;
  beyond.replace(beyond.find(R"("direction": 2, "dof": "theta_a")"), 14, R"("direction": 5)");
  EXPECT_FALSE(UffToDataset(file, testing::ParsedUffMap(beyond), &p, &in, &e));
  EXPECT_NE(e.message.find("node 3 direction 5"), std::string::npos) << e.OneLine();
  // The command: exit 2, one line naming the node and the file, no dataset.
  const std::string uff = Scratch("lab_node.uff"), map_path = Scratch("lab_node_map.json");
  const std::string out = Scratch("lab_node_dataset.json");
  std::ofstream(uff) << LabFile(s, &truth);
  std::ofstream(map_path) << json;
  std::remove(out.c_str());
  const RunResult r = Ringid("import --uff=" + uff + " --map=" + map_path + " --parameters=" +
                             testing::SourcePath("datasets/examples/car_tire.json") +
                             " --output=" + out);
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(uff), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("node 9 direction 2"), std::string::npos) << r.err;
  EXPECT_FALSE(testing::Exists(out));
}

// Without --map the command lists the nodes of the modes and the directions
// each holds, what a map's channels name: LabFile writes nodes 1, 2 and 3,
// three values each, in all seven modes.
TEST(UffImportTest, TheListingGivesTheNodesAndDirectionsAMapNames) {
  std::vector<ModeLabel> truth;
  const std::string uff = Scratch("lab_list.uff");
  std::ofstream(uff) << LabFile(RigidRingModel().Solve(ExampleCarTire()), &truth);
  const RunResult r = Ringid("import --uff=" + uff);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("nodes 1-3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("directions 1-3, in every mode"), std::string::npos) << r.out;
}

// A map that swaps the belt's x and z channels: the shapes match no model
// mode well, and the labels that rest on them are said to (exit 0, with a
// warning); the right map of the same file says nothing of the kind.
TEST(UffImportTest, LabelsThatRestOnAPoorMatchAreAWarning) {
  const Parameters p = ExampleCarTire();
  ModalSolution s;
  std::vector<ModeLabel> truth;
  const UffFile file = ReadLabFile(p, &s, &truth);
  std::string swapped = kLabMap;
  swapped.replace(swapped.find(R"("direction": 1, "dof": "x_b")"), 28, R"("direction": 1, "dof": "z_b")");
  swapped.replace(swapped.find(R"("direction": 3, "dof": "z_b")"), 28, R"("direction": 3, "dof": "x_b")");
  IdentifyOptions o;
  o.residuals.derivatives = Derivatives::kAnalytic;
  UffImport good, poor;
  LoadError e;
  ASSERT_TRUE(UffToDatasetLabelledByFit(file, testing::ParsedUffMap(kLabMap), p, o, &good, &e)) << e.OneLine();
  EXPECT_TRUE(good.warnings.empty()) << good.warnings.front();
  ASSERT_TRUE(UffToDatasetLabelledByFit(file, testing::ParsedUffMap(swapped), p, o, &poor, &e)) << e.OneLine();
  ASSERT_EQ(poor.warnings.size(), 1u);
  EXPECT_NE(poor.warnings[0].find("poor match"), std::string::npos) << poor.warnings[0];
  // The thresholds: a MAC under 0.8 named with its mode, or p under 1e-3.
  bool low_mac = false;
  for (const UffModelLabel& l : poor.by_model) low_mac |= l.mac && *l.mac < 0.8;
  EXPECT_EQ(low_mac, poor.warnings[0].find("MAC") != std::string::npos) << poor.warnings[0];
  for (const UffModelLabel& l : good.by_model) EXPECT_GT(*l.mac, 1 - 1e-6);
  // The command prints it and still writes the dataset.
  const std::string uff = Scratch("lab_poor.uff"), map = Scratch("lab_poor_map.json");
  const std::string out = Scratch("lab_poor_dataset.json");
  std::ofstream(uff) << LabFile(s, &truth);
  std::ofstream(map) << swapped;
  std::remove(out.c_str());
  const RunResult r = Ringid("import --uff=" + uff + " --map=" + map + " --parameters=" +
                             testing::SourcePath("datasets/examples/car_tire.json") +
                             " --output=" + out);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("warning: the labels rest on a poor match"), std::string::npos) << r.out;
  EXPECT_TRUE(testing::Exists(out));
}

}  // namespace
}  // namespace ringid
