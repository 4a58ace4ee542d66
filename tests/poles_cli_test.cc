// `ringid poles` end to end: the example hammer file's poles equal its closed
// form (the belt's three uncoupled coordinates, scripts/make_hammer_example.py),
// a report the page draws, and files that are not FRFs refused in one line
// with exit status 2 and nothing written: time records (the corpus's dataset
// 58 files, and one written here), a single line, lines that do not increase.
#include <cmath>
#include <complex>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "datasets/synthetic.h"
#include "model/rigid_ring_model.h"
#include "tests/test_support.h"
#include "tests/uff_writer.h"

namespace ringid {
namespace {

using testing::Ringid;
using testing::RunResult;
using testing::Scratch;
using PolesCorpusTest = testing::CorpusTest;

bool Exists(const std::string& path) { return std::ifstream(path).good(); }

// The damped frequencies (Hz) and damping ratios of m s² + c s + k.
std::pair<double, double> Pole(double m, double k, double c) {
  const double wn = std::sqrt(k / m), zeta = c / (2 * std::sqrt(k * m));
  return {wn * std::sqrt(1 - zeta * zeta) / (2 * M_PI), zeta};
}

TEST(PolesCliTest, TheExampleHammerFileGivesTheBeltsThreeCoordinatesPoles) {
  const Parameters p = ExampleCarTire();
  std::vector<std::pair<double, double>> truth = {
      Pole(p[Param::m_b], p[Param::k_bx], p[Param::c_bx]),
      Pole(p[Param::m_b], p[Param::k_bz], p[Param::c_bz]),
      Pole(p[Param::I_by], p[Param::k_btheta], p[Param::c_btheta])};
  const std::string out = Scratch("poles.json"), report = Scratch("poles_report.json");
  const RunResult r = Ringid("poles --uff=" + testing::SourcePath("datasets/examples/car_tire_hammer.uff") + " --output=" + out +
                             " --report=" + report);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json poles = nlohmann::json::parse(testing::ReadFile(out));
  EXPECT_EQ(poles["format"], "ringid-poles/1");
  EXPECT_EQ(poles["conditions"][0]["noise"], "from the residuals");
  // Two coordinates with the same pole are one pole of the file.
  size_t distinct = 0;
  for (size_t q = 0; q < truth.size(); ++q) {
    bool seen = false;
    for (size_t e = 0; e < q; ++e) seen |= std::abs(truth[e].first - truth[q].first) < 1e-9 * truth[q].first;
    if (seen) continue;
    ++distinct;
    bool found = false;
    for (const auto& pole : poles["poles"]) {
      const double hz = pole["frequency_hz"], zeta = pole["damping_ratio"];
      if (std::abs(hz - truth[q].first) > 1e-5 * truth[q].first) continue;
      found = true;
      EXPECT_NEAR(zeta, truth[q].second, 1e-5 * truth[q].second);
      EXPECT_EQ(pole["residues"].size(), 6u);  // 3 responses x 2 references
      EXPECT_EQ(pole["shape_over"], "responses");
    }
    EXPECT_TRUE(found) << truth[q].first << " Hz";
  }
  EXPECT_EQ(poles["poles"].size(), distinct);
  const RunResult page = Ringid("report --input=" + report + " --output=" + Scratch("poles.html"));
  EXPECT_EQ(page.status, 0) << page.err;
}

// --dataset: the example hammer test's 28 FRFs (2 % noise, sigma given) give
// the car tire's seven modes, each within 4 of its standard errors of the
// model's at the parameters they were simulated from.
TEST(PolesCliTest, ADatasetsFrfsGiveTheModelsModesWithinTheirErrors) {
  const std::string out = Scratch("dataset_poles.json");
  const RunResult r = Ringid("poles --dataset=" +
                             testing::SourcePath("datasets/examples/car_tire_hammer_frf.json") +
                             " --output=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json poles = nlohmann::json::parse(testing::ReadFile(out));
  EXPECT_EQ(poles["conditions"][0]["noise"], "given");
  const ModalSolution truth = RigidRingModel().Solve(ExampleCarTire());
  ASSERT_TRUE(truth.ok) << truth.error;
  ASSERT_EQ(poles["poles"].size(), truth.modes.size());
  for (const Mode& m : truth.modes) {
    const nlohmann::json* nearest = nullptr;
    for (const auto& p : poles["poles"]) {
      if (!nearest || std::abs(p["frequency_hz"].get<double>() - m.frequency_hz) <
                          std::abs((*nearest)["frequency_hz"].get<double>() - m.frequency_hz)) {
        nearest = &p;
      }
    }
    const nlohmann::json& p = *nearest;
    EXPECT_LT(std::abs(p["frequency_hz"].get<double>() - m.frequency_hz),
              4 * p["frequency_sigma_hz"].get<double>()) << LabelName(m.label);
    EXPECT_LT(std::abs(p["damping_ratio"].get<double>() - m.damping_ratio),
              4 * p["damping_sigma"].get<double>()) << LabelName(m.label);
  }
}

// A refused file: exit 2, one line on stderr holding `says`, no output.
void ExpectRefused(const std::string& uff, const std::string& says) {
  const std::string out = Scratch("refused_poles.json");
  std::remove(out.c_str());
  const RunResult r = Ringid("poles --uff=" + uff + " --output=" + out);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(uff), std::string::npos) << r.err;
  EXPECT_FALSE(Exists(out));
}

std::string Written(const std::string& name, const testing::Fn& f) {
  const std::string path = Scratch(name);
  std::ofstream(path) << testing::Function58(f);
  return path;
}

TEST(PolesCliTest, FilesWithoutFrfsOrLinesAreRefusedInOneLine) {
  testing::Fn f;
  f.response_node = 1, f.response_direction = 3, f.reference_node = 1, f.reference_direction = 3;
  for (int i = 0; i < 40; ++i) f.y.emplace_back(1.0 / (1 + i), 0.1);
  testing::Fn time = f;
  time.type = 1;
  ExpectRefused(Written("time.uff", time), "function type 1 (time response)");
  testing::Fn single = f;
  single.y.resize(1);
  ExpectRefused(Written("single.uff", single), "1 line(s) above 0 Hz: poles need at least 7");
  testing::Fn decreasing = f;
  decreasing.min_hz = 200;
  decreasing.step_hz = -2.5;
  ExpectRefused(Written("decreasing.uff", decreasing), "abscissa increment) must be positive");
}

// A file without units: poles in the file's units, and --units=g,N gives the
// same poles with residues g = 9.80665 m/s² times larger, in SI.
TEST(PolesCliTest, AFileWithoutUnitsGivesPolesAndUnitsGiveItsResiduesInSi) {
  testing::Fn f;
  f.response_node = 1, f.response_direction = 3, f.reference_node = 1, f.reference_direction = 3;
  f.min_hz = 1;
  f.step_hz = 1;
  for (int i = 0; i < 200; ++i) {  // an accelerance of 1 kg on 4e5 N/m, 20 N s/m
    const double w = 2 * M_PI * (1 + i);
    f.y.push_back(-w * w / std::complex<double>(4e5 - w * w, 20 * w));
  }
  const std::string uff = Written("unitless.uff", f), a = Scratch("file_units.json"),
                    b = Scratch("si_units.json");
  const RunResult plain = Ringid("poles --uff=" + uff + " --output=" + a);
  ASSERT_EQ(plain.status, 0) << plain.err;
  const RunResult si = Ringid("poles --uff=" + uff + " --units=g,N --output=" + b);
  ASSERT_EQ(si.status, 0) << si.err;
  const nlohmann::json x = nlohmann::json::parse(testing::ReadFile(a)),
                       y = nlohmann::json::parse(testing::ReadFile(b));
  EXPECT_EQ(x["conditions"][0]["units"], "the file's units");
  ASSERT_EQ(x["poles"].size(), 1u);
  ASSERT_EQ(y["poles"].size(), 1u);
  const auto [hz, zeta] = Pole(1, 4e5, 20);
  EXPECT_NEAR(x["poles"][0]["frequency_hz"].get<double>(), hz, 1e-6 * hz);
  EXPECT_NEAR(x["poles"][0]["damping_ratio"].get<double>(), zeta, 1e-6 * zeta);
  EXPECT_NEAR(y["poles"][0]["frequency_hz"].get<double>(), hz, 1e-6 * hz);
  const double re = x["poles"][0]["residues"][0]["re"], im = x["poles"][0]["residues"][0]["im"];
  EXPECT_NEAR(y["poles"][0]["residues"][0]["re"].get<double>(), 9.80665 * re, 1e-6 * std::hypot(re, im));
  EXPECT_NEAR(y["poles"][0]["residues"][0]["im"].get<double>(), 9.80665 * im, 1e-6 * std::hypot(re, im));
  const RunResult bad = Ringid("poles --uff=" + uff + " --units=furlong,N --output=" + Scratch("bad_units.json"));
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--units"), std::string::npos) << bad.err;
}

// A coherence gives sigma to its pair's FRF on its own lines only: two sets
// of 100 lines, the coherence on the second's, the first's noise from the
// residuals; an FRF that is zero everywhere left out with a note.
TEST(PolesCliTest, ACoherenceGivesSigmaOnlyOnItsOwnLines) {
  testing::Fn a;
  a.response_node = 1, a.response_direction = 3, a.reference_node = 1, a.reference_direction = 3;
  a.min_hz = 2.5, a.step_hz = 2.5;
  testing::Fn b = a, coherence = a, zero = a;
  b.min_hz = 1.25, b.step_hz = 1.25;
  coherence.type = 6;
  coherence.min_hz = 1.25, coherence.step_hz = 1.25;
  zero.response_node = 2;
  for (int i = 0; i < 100; ++i) {
    for (testing::Fn* f : {&a, &b}) {
      const double w = 2 * M_PI * (f->min_hz + i * f->step_hz);
      f->y.push_back(-w * w / std::complex<double>(4e5 - w * w, 20 * w));
    }
    coherence.y.emplace_back(0.9, 0);
    zero.y.emplace_back(0, 0);
  }
  const std::string uff = Scratch("two_lines.uff"), map = Scratch("averages_map.json"),
                    out = Scratch("two_lines_poles.json");
  std::ofstream(uff) << testing::Function58(a) + testing::Function58(zero) + testing::Function58(b) +
                            testing::Function58(coherence);
  std::ofstream(map) << R"({"format": "ringid-uff-map/2", "name": "averages",
                            "points": [{"node": 1, "on": "belt"}], "averages": 10})";
  const RunResult r = Ringid("poles --uff=" + uff + " --map=" + map + " --output=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json poles = nlohmann::json::parse(testing::ReadFile(out));
  ASSERT_EQ(poles["conditions"].size(), 2u);
  EXPECT_EQ(poles["conditions"][0]["noise"], "from the residuals");
  EXPECT_EQ(poles["conditions"][1]["noise"], "given");
  EXPECT_EQ(poles["conditions"][0]["functions"], 1);
  EXPECT_NE(r.out.find("2:+3 / 1:+3: zero at every line above 0 Hz; left out"), std::string::npos) << r.out;
}

TEST_F(PolesCorpusTest, TheCorpusDataset58FilesHoldTimeRecordsAndAreRefused) {
  for (const char* name : {"Sample_UFF58_ascii.uff", "Sample_UFF58b_bin.uff"}) {
    ExpectRefused(testing::UffCorpus(name), "function type 1 (time response)");
  }
}

}  // namespace
}  // namespace ringid
