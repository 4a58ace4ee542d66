// A test lab's FRFs (UFF 58) as format-3 frf blocks (datasets/uff_frf.h,
// docs/uff.md), from files this test writes with its own 58 writer: the same
// FRFs in millimetres, in g with zero exponents and in feet per pound-force
// read to the same SI values; a z-up lab frame through the map's axes and a
// turned displacement system give the dataset of ringid's frame; a units label
// that disagrees is refused naming the record; a coherence gives contract §9's
// sigma; other lines are another condition; what the map cannot place is
// listed; `ringid import` writes a dataset the loader reads back to the byte.
#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "datasets/frf.h"
#include "datasets/tir_parameters.h"
#include "datasets/uff.h"
#include "datasets/uff_dataset.h"
#include "datasets/uff_frf.h"
#include "tests/test_support.h"
#include "tests/uff_writer.h"

namespace ringid {
namespace {

using C = std::complex<double>;
using testing::Ringid;
using testing::RunResult;
using testing::Scratch;
using Vec3 = std::array<double, 3>;

// The 58 writer (tests/uff_writer.h), and datasets 15, 18 and 164.
using testing::Axis;
using testing::Fn;
using testing::Function58;

std::string Units164(int code, const std::string& name, double length, double force) {
  char line[200];
  std::snprintf(line, sizeof line, "    -1\n   164\n%10d%-20s%10d\n%25.17E%25.17E%25.17E\n%25.17E\n    -1\n",
                code, name.c_str(), 2, length, force, 1.0, 0.0);
  return line;
}

struct Node {
  int label, definition, displacement;
  Vec3 xyz;
};
std::string Nodes15(const std::vector<Node>& nodes) {
  std::string s = "    -1\n    15\n";
  for (const Node& n : nodes) {
    char line[120];
    std::snprintf(line, sizeof line, "%10d%10d%10d%10d%13.5E%13.5E%13.5E\n", n.label, n.definition,
                  n.displacement, 8, n.xyz[0], n.xyz[1], n.xyz[2]);
    s += line;
  }
  return s + "    -1\n";
}

// Dataset 18, one cartesian system by origin, a point on +x, a point in +xz.
std::string System18(int label, const Vec3& o, const Vec3& x, const Vec3& xz) {
  char line[300];
  std::snprintf(line, sizeof line,
                "    -1\n    18\n%10d%10d%10d%10d%10d\nSYS%d\n%13.5E%13.5E%13.5E%13.5E%13.5E%13.5E\n"
                "%13.5E%13.5E%13.5E\n    -1\n",
                label, 0, 0, 8, 1, label, o[0], o[1], o[2], x[0], x[1], x[2], xz[0], xz[1], xz[2]);
  return line;
}

// The truth in SI: an accelerance per pair r, m/s² per N, at f Hz.
C Truth(double f, int r) {
  const double w = 2 * M_PI * f, m = 10, k = 4e5 * (1 + r), c = 50 + 20 * r;
  return -w * w * (1 + 0.3 * r) / C(k - m * w * w, c * w);
}
std::vector<C> TruthLines(int r, double scale, int lines = 40, double min = 2.5, double step = 2.5) {
  std::vector<C> y;
  for (int i = 0; i < lines; ++i) y.push_back(scale * Truth(min + i * step, r));
  return y;
}

bool Import(const std::string& uff, const std::string& map, UffImport* out, LoadError* e) {
  *out = UffImport{};
  return AddUffFrfs(testing::ParsedUff(uff), testing::ParsedUffMap(map), out, e);
}

constexpr const char* kPlacedMap = R"({"format": "ringid-uff-map/2", "name": "lab",
  "description": "a hammer test",
  "points": [{"node": 1, "on": "belt", "point_m": [0, 0, -0.3]},
             {"node": 2, "on": "belt", "point_m": [0.3, 0, 0]},
             {"node": 3, "on": "rim", "point_m": [0, 0.05, -0.2]}]})";

// Two FRFs (2:+3 and 3:+1 per 1:+1) whose units `axis` sets, the values the
// truth times `scale` (file units per SI unit).
std::string TwoFrfs(const Axis& ordinate, const Axis& denominator, double scale) {
  std::string s;
  const int pairs[2][2] = {{2, 3}, {3, 1}};
  for (int r = 0; r < 2; ++r) {
    Fn f;
    f.response_node = pairs[r][0];
    f.response_direction = pairs[r][1];
    f.reference_node = 1;
    f.reference_direction = 1;
    f.y = TruthLines(r, scale);
    f.ordinate = ordinate;
    f.denominator = denominator;
    s += Function58(f);
  }
  return s;
}

TEST(UffFrfTest, FrfsInMillimetresInGWithZeroExponentsAndInFeetPerPoundReadToTheSameSiValues) {
  const double g = 9.80665, foot = 0.3048, pound = 4.4482216152605;  // SI, by definition
  const std::vector<std::pair<std::string, std::string>> files = {
      {"mm/s^2 per N, exponents and dataset 164 (mm, newton)",
       Units164(10, "mm (newton)", 1000, 1) +
           TwoFrfs({12, 1, 0, "mm/s^2"}, {13, 0, 1, "N"}, 1000)},
      {"g per N, zero exponents, labels",
       Units164(1, "SI", 1, 1) + TwoFrfs({12, 0, 0, "g"}, {13, 0, 0, "N"}, 1 / g)},
      {"ft/s^2 per lbf, exponents and dataset 164 (BG), no labels",
       Units164(2, "Foot (pound f)", 1 / foot, 1 / pound) +
           TwoFrfs({12, 1, 0, "NONE"}, {13, 0, 1, "NONE"}, pound / foot)}};
  for (const auto& [what, text] : files) {
    UffImport in;
    LoadError e;
    ASSERT_TRUE(Import(text, kPlacedMap, &in, &e)) << what << ": " << e.OneLine();
    ASSERT_EQ(in.dataset.conditions.size(), 1u) << what;
    const Frf& frf = *in.dataset.conditions[0].frf;
    ASSERT_EQ(frf.functions.size(), 2u) << what;
    for (int r = 0; r < 2; ++r) {
      const FrfFunction& fn = frf.functions[r];
      EXPECT_EQ(frf.outputs[fn.output].quantity, FrfQuantity::kAcceleration);
      for (size_t i = 0; i < fn.h.size(); ++i) {
        const C truth = Truth(frf.frequencies_hz[i], r);
        EXPECT_LE(std::abs(fn.h[i] - truth), 1e-9 * std::abs(truth)) << what << " line " << i;
      }
    }
  }
}

// Ringid's frame (x forward, y right, z down) and a z-up lab frame (x
// forward, y left): the same nodes, in millimetres, and the same FRFs give
// the same points and directions, with axes ["x", "-y", "-z"]; node 1's
// displacement system in the lab file is turned half a turn about y, so its
// direction +x is the system's -x.
TEST(UffFrfTest, AZUpLabFrameThroughAxesGivesTheDatasetOfRingidsFrame) {
  const std::string units = Units164(10, "mm (newton)", 1000, 1);
  const Axis acc{12, 1, 0, "mm/s^2"}, force{13, 0, 1, "N"};
  // response node, direction in ringid's frame and in the lab's; reference 1:+1 (lab system: -1)
  const int pairs[3][3] = {{2, 3, -3}, {2, 1, 1}, {3, 2, -2}};
  std::string ringid = units + Nodes15({{1, 0, 0, {0, 0, -300}}, {2, 0, 0, {300, 0, 0}},
                                        {3, 0, 0, {0, 50, -200}}});
  std::string lab = units + System18(1, {0, 0, 0}, {-1, 0, 0}, {-1, 0, -1}) +
                    Nodes15({{1, 0, 1, {0, 0, 300}}, {2, 0, 0, {300, 0, 0}},
                             {3, 0, 0, {0, -50, 200}}});
  for (int r = 0; r < 3; ++r) {
    Fn f;
    f.response_node = pairs[r][0];
    f.reference_node = 1;
    f.y = TruthLines(r, 1000);
    f.ordinate = acc;
    f.denominator = force;
    f.response_direction = pairs[r][1];
    f.reference_direction = 1;
    ringid += Function58(f);
    f.response_direction = pairs[r][2];
    f.reference_direction = -1;
    lab += Function58(f);
  }
  const std::string points = R"("points": [{"node": 1, "on": "belt"}, {"node": 2, "on": "belt"},
                                           {"node": 3, "on": "rim"}]})";
  UffImport a, b;
  LoadError e;
  ASSERT_TRUE(Import(ringid, R"({"format": "ringid-uff-map/2", "name": "t", )" + points, &a, &e))
      << e.OneLine();
  ASSERT_TRUE(Import(lab, R"({"format": "ringid-uff-map/2", "name": "t", "axes": ["x", "-y", "-z"], )" +
                              points, &b, &e))
      << e.OneLine();
  const Frf &fa = *a.dataset.conditions.at(0).frf, &fb = *b.dataset.conditions.at(0).frf;
  ASSERT_EQ(fa.functions.size(), 3u);
  ASSERT_EQ(fb.functions.size(), 3u);
  // By hand: the points in metres from the nodes, the directions of the pairs.
  const Vec3 where[4] = {{}, {0, 0, -0.3}, {0.3, 0, 0}, {0, 0.05, -0.2}};
  const Vec3 along[4] = {{}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int r = 0; r < 3; ++r) {
    for (const Frf* frf : {&fa, &fb}) {
      const FrfFunction& fn = frf->functions[r];
      const FrfPoint &out = *frf->outputs[fn.output].point, &in = *frf->inputs[fn.input].point;
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(out.point_m[k], where[pairs[r][0]][k], 1e-12) << r;
        EXPECT_NEAR(out.direction[k], along[pairs[r][1]][k], 1e-12) << r;
        EXPECT_NEAR(in.point_m[k], where[1][k], 1e-12) << r;
        EXPECT_NEAR(in.direction[k], along[1][k], 1e-12) << r;
      }
      EXPECT_EQ(frf->outputs[fn.output].coordinates, fa.outputs[fa.functions[r].output].coordinates);
      EXPECT_EQ(fn.h, fa.functions[r].h);
      EXPECT_EQ(fn.sigma, fa.functions[r].sigma);
    }
  }
  EXPECT_EQ(fb.outputs[fb.functions[2].output].point->on, FrfBody::kRim);
}

// A units label that disagrees with the exponents (or with the specific data
// type), or that names no unit ringid knows, is refused naming the record
// and the map's units that would settle it; the map's units do.
TEST(UffFrfTest, AUnitsLabelThatDisagreesIsRefusedNamingTheRecordUnlessTheMapSaysTheUnit) {
  const std::string mm = Units164(10, "mm (newton)", 1000, 1);
  const struct {
    std::string what, text, field, says;
  } cases[] = {
      {"g with length exponent 1 in mm", mm + TwoFrfs({12, 1, 0, "g"}, {13, 0, 1, "N"}, 1000),
       "record 9", "'g' disagrees with the exponents"},
      {"lbf with force exponent 1 in newton", mm + TwoFrfs({12, 1, 0, "NONE"}, {13, 0, 1, "lbf"}, 1),
       "record 10", "'lbf' disagrees with the exponents"},
      {"an unknown label", mm + TwoFrfs({12, 0, 0, "furlong/s^2"}, {13, 0, 0, "N"}, 1), "record 9",
       "names no unit ringid knows"},
      {"no exponents, no labels", mm + TwoFrfs({12, 0, 0, "NONE"}, {13, 0, 0, "NONE"}, 1),
       "record 9", "not a motion per force"},
      {"velocity data type, a label in g", mm + TwoFrfs({11, 0, 0, "g"}, {13, 0, 0, "N"}, 1),
       "record 9", "says velocity"},
  };
  for (const auto& c : cases) {
    UffImport in;
    LoadError e;
    EXPECT_FALSE(Import(c.text, kPlacedMap, &in, &e)) << c.what;
    EXPECT_EQ(e.file, "test.uff") << c.what;
    EXPECT_NE(e.field.find("dataset 58 #1 (line "), std::string::npos) << c.what << ": " << e.OneLine();
    EXPECT_NE(e.field.find(c.field), std::string::npos) << c.what << ": " << e.OneLine();
    EXPECT_NE(e.message.find(c.says), std::string::npos) << c.what << ": " << e.OneLine();
    EXPECT_NE(e.message.find("units."), std::string::npos) << c.what << ": " << e.OneLine();
  }
  // The map's units settle the first: the values are g per N, whatever the exponents say.
  std::string map = kPlacedMap;
  map.insert(map.rfind('}'), R"(, "units": {"response": "g", "reference": "N"})");
  UffImport in;
  LoadError e;
  ASSERT_TRUE(Import(mm + TwoFrfs({12, 1, 0, "g"}, {13, 0, 1, "N"}, 1 / 9.80665), map, &in, &e))
      << e.OneLine();
  const FrfFunction& fn = in.dataset.conditions[0].frf->functions[1];
  EXPECT_LE(std::abs(fn.h[7] - Truth(in.dataset.conditions[0].frf->frequencies_hz[7], 1)),
            1e-9 * std::abs(fn.h[7]));
}

// A coherence function (type 6) of the pair gives sigma = |H| sqrt((1 -
// gamma2) / (2 n gamma2)) with the map's n (contract §9), computed here; a
// function without one gets the stated default, 2 % of |H| but at least 2 %
// of 1 % of its largest |H|; a coherence of exactly 1 is taken inside (0, 1).
TEST(UffFrfTest, ACoherenceGivesContractSection9sSigmaAndNoCoherenceTheStatedDefault) {
  std::string text = Units164(1, "SI", 1, 1) + TwoFrfs({12, 1, 0, "m/s^2"}, {13, 0, 1, "N"}, 1);
  Fn coherence;
  coherence.type = 6;
  coherence.response_node = 2;
  coherence.response_direction = 3;
  coherence.reference_node = 1;
  coherence.reference_direction = 1;
  coherence.ordinate = coherence.denominator = {0, 0, 0, "NONE"};
  std::vector<double> gamma2;
  for (int i = 0; i < 40; ++i) {
    gamma2.push_back(0.9 + 0.09 * std::cos(0.3 * i));
    coherence.y.push_back(gamma2.back());
  }
  std::string map = kPlacedMap;
  map.insert(map.rfind('}'), R"(, "averages": 20)");
  UffImport in;
  LoadError e;
  EXPECT_FALSE(Import(text + Function58(coherence), kPlacedMap, &in, &e));
  EXPECT_EQ(e.field, "averages") << e.OneLine();
  ASSERT_TRUE(Import(text + Function58(coherence), map, &in, &e)) << e.OneLine();
  const Frf& frf = *in.dataset.conditions[0].frf;
  const FrfFunction &with = frf.functions[0], &without = frf.functions[1];
  ASSERT_TRUE(with.coherence);
  EXPECT_EQ(with.coherence->averages, 20);
  double peak = 0;
  for (const C& h : without.h) peak = std::max(peak, std::abs(h));
  for (size_t i = 0; i < 40; ++i) {
    const double expected = std::abs(with.h[i]) * std::sqrt((1 - gamma2[i]) / (2 * 20 * gamma2[i]));
    EXPECT_NEAR(with.sigma[i], expected, 1e-9 * expected) << i;
    EXPECT_DOUBLE_EQ(without.sigma[i], 0.02 * std::max(std::abs(without.h[i]), 0.01 * peak)) << i;
  }
  coherence.y[5] = 1;  // to the file's precision
  ASSERT_TRUE(Import(text + Function58(coherence), map, &in, &e)) << e.OneLine();
  const FrfFunction& clamped = in.dataset.conditions[0].frf->functions[0];
  EXPECT_FALSE(clamped.coherence);  // written as sigma: the loader takes coherence in (0, 1) only
  EXPECT_GT(clamped.sigma[5], 0);
  EXPECT_NEAR(clamped.sigma[6], std::abs(clamped.h[6]) * std::sqrt((1 - gamma2[6]) / (40 * gamma2[6])),
              1e-9 * clamped.sigma[6]);
}

// FRFs on other lines are a condition of their own; a line at 0 Hz is left
// out (contract §9: lines > 0); a node the map does not place, a rotation
// and a function that is not an FRF are listed and left out.
TEST(UffFrfTest, OtherLinesAreAnotherConditionAndWhatTheMapCannotPlaceIsListed) {
  std::string text = Units164(1, "SI", 1, 1);
  const Axis acc{12, 1, 0, "m/s^2"}, force{13, 0, 1, "N"};
  const std::tuple<int, int, int, double, double> fns[] = {
      {4, 2, 3, 0, 2.5}, {4, 3, 1, 0, 2.5}, {4, 2, 1, 1, 1},  // lines 0, 2.5, ... and 1, 2, ...
      {4, 9, 3, 0, 2.5}, {4, 2, 5, 0, 2.5}, {1, 2, 3, 0, 2.5}};
  for (const auto& [type, node, direction, min, step] : fns) {
    Fn f;
    f.type = type;
    f.response_node = node;
    f.response_direction = direction;
    f.reference_node = 1;
    f.reference_direction = 1;
    f.min_hz = min;
    f.step_hz = step;
    f.y = TruthLines(0, 1, 40, min, step);
    f.ordinate = acc;
    f.denominator = force;
    text += Function58(f);
  }
  UffImport in;
  LoadError e;
  ASSERT_TRUE(Import(text, kPlacedMap, &in, &e)) << e.OneLine();
  const auto& conditions = in.dataset.conditions;
  ASSERT_EQ(conditions.size(), 2u);
  EXPECT_EQ(conditions[0].name, "standing");
  EXPECT_EQ(conditions[1].name, "standing_2");
  EXPECT_EQ(conditions[0].frf->functions.size(), 2u);
  EXPECT_EQ(conditions[1].frf->functions.size(), 1u);
  EXPECT_EQ(conditions[0].frf->frequencies_hz.size(), 39u);
  EXPECT_EQ(conditions[0].frf->frequencies_hz.front(), 2.5);
  EXPECT_EQ(conditions[1].frf->frequencies_hz.front(), 1);
  std::string notes;
  for (const std::string& n : in.notes) notes += n + "\n";
  EXPECT_NE(notes.find("dataset 58 #4 (line "), std::string::npos) << notes;
  EXPECT_NE(notes.find("9:+3 / 1:+1: node 9 is not in the map's points; left out"), std::string::npos) << notes;
  EXPECT_NE(notes.find("2:+5 / 1:+1: direction 2:+5 is not a translation (1, 2, 3); left out"),
            std::string::npos) << notes;
  EXPECT_NE(notes.find("function type 1 is not an FRF (4); left out"), std::string::npos) << notes;
  EXPECT_NE(notes.find("lines at or below 0 Hz left out of 2 FRFs"), std::string::npos) << notes;
}

TEST(UffFrfTest, BadFormat2MapsAreRefusedNamingTheField) {
  const std::string head = R"({"format": "ringid-uff-map/2", "name": "m", )";
  const std::string point = R"("points": [{"node": 1, "on": "belt"}])";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {head + R"("axes": ["x", "x", "z"], )" + point + "}", "axes[1]"},
      {head + R"("axes": ["x", "y", "-z"], )" + point + "}", "axes"},
      {head + R"("axes": ["x", "y"], )" + point + "}", "axes"},
      {head + R"("axes": ["x", "up", "z"], )" + point + "}", "axes[1]"},
      {head + R"("units": {"response": "furlong"}, )" + point + "}", "units.response"},
      {head + R"("units": {"reference": "g"}, )" + point + "}", "units.reference"},
      {head + R"("units": {"response": "N"}, )" + point + "}", "units.response"},
      {head + R"("points": [{"node": 1, "on": "belt"}, {"node": 1, "on": "rim"}]})", "points[1].node"},
      {head + R"("points": [{"node": 1, "on": "tread"}]})", "points[0].on"},
      {head + R"("points": [{"node": 1, "on": "belt", "point_m": [0, 1]}]})", "points[0].point_m"},
      {head + R"("points": [{"node": 0, "on": "belt"}]})", "points[0].node"},
      {head + R"("points": [{"node": 1, "on": "belt", "place": 1}]})", "points[0].place"},
      {head + R"("averages": 0, )" + point + "}", "averages"},
      {head + R"("description": "nothing placed"})", "points"},
      {R"({"format": "ringid-uff-map/1", "name": "m", "channels": [{"node": 1, "direction": 3,
           "dof": "z_b"}], )" + point + "}", "points"},  // format 1 reads as before
  };
  for (const auto& [json, field] : cases) {
    UffMap map;
    LoadError e;
    EXPECT_FALSE(ParseUffMap(json, "map.json", &map, &e)) << json;
    EXPECT_EQ(e.file, "map.json");
    EXPECT_EQ(e.field, field) << json << ": " << e.OneLine();
  }
}

// A placed node that the file's dataset 15 does not hold needs its point_m.
TEST(UffFrfTest, ANodeWithoutCoordinatesOrPointIsRefusedNamingThePoint) {
  UffImport in;
  LoadError e;
  EXPECT_FALSE(Import(Units164(1, "SI", 1, 1) + TwoFrfs({12, 1, 0, "NONE"}, {13, 0, 1, "NONE"}, 1),
                      R"({"format": "ringid-uff-map/2", "name": "m", "points": [
                          {"node": 1, "on": "belt"}, {"node": 2, "on": "belt", "point_m": [0, 0, 0.3]},
                          {"node": 3, "on": "belt", "point_m": [0, 0, 0.3]}]})",
                      &in, &e));
  EXPECT_EQ(e.field, "points[0].point_m") << e.OneLine();
}

// The command writes a format-3 dataset the loader reads back to the same
// bytes; a refused label is exit 2, one line, nothing written.
TEST(UffFrfTest, TheCommandWritesAFormat3DatasetTheLoaderReadsBackAndNothingOnBadInput) {
  const std::string uff = Scratch("frf.uff"), map = Scratch("frf_map.json");
  const std::string out = Scratch("frf_dataset.json");
  std::ofstream(map) << kPlacedMap;
  std::ofstream(uff) << Units164(10, "mm (newton)", 1000, 1) +
                            TwoFrfs({12, 1, 0, "mm/s^2"}, {13, 0, 1, "N"}, 1000);
  std::remove(out.c_str());
  RunResult r = Ringid("import --uff=" + uff + " --map=" + map + " --output=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("wrote " + out + " (2 FRFs in 1 condition from "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sigma: 2 FRFs without coherence: 2 % of |H|"), std::string::npos) << r.out;
  Dataset d;
  LoadError e;
  ASSERT_TRUE(LoadDataset(out, &d, &e)) << e.OneLine();
  EXPECT_EQ(d.format, 3);
  ASSERT_TRUE(d.conditions.at(0).frf);
  EXPECT_EQ(DatasetToJson(d), testing::ReadFile(out));
  EXPECT_LE(std::abs(d.conditions[0].frf->functions[0].h[3] - Truth(10, 0)), 1e-9 * std::abs(Truth(10, 0)));
  r = Ringid("import --uff=" + uff);
  EXPECT_NE(r.out.find("functions (58): a ringid-uff-map/2's points import the FRFs"), std::string::npos)
      << r.out;
  std::ofstream(uff) << Units164(10, "mm (newton)", 1000, 1) +
                            TwoFrfs({12, 1, 0, "g"}, {13, 0, 1, "N"}, 1000);
  std::remove(out.c_str());
  r = Ringid("import --uff=" + uff + " --map=" + map + " --output=" + out);
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(uff), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("record 9"), std::string::npos) << r.err;
  EXPECT_FALSE(testing::Exists(out));
}


// datasets/examples/car_tire_hammer.uff (scripts/make_hammer_example.py) is
// the closed form its script describes, computed again here: the belt of
// car_tire.json hanging free with the rim held, x_b, z_b and theta_b three
// damped single-degree-of-freedom systems, each point's coefficients those
// of contract §9; the nodes in a z-up lab frame in millimetres.
TEST(UffFrfTest, TheShippedHammerExampleIsTheClosedFormItsScriptDescribes) {
  Parameters p;
  LoadError e;
  ASSERT_TRUE(LoadParameters(testing::SourcePath("datasets/examples/car_tire.json"), {}, &p, &e))
      << e.OneLine();
  UffFile file;
  UffMap map;
  ASSERT_TRUE(LoadUff(testing::SourcePath("datasets/examples/car_tire_hammer.uff"), &file, &e))
      << e.OneLine();
  ASSERT_TRUE(LoadUffMap(testing::SourcePath("datasets/examples/car_tire_hammer_map.json"), &map, &e))
      << e.OneLine();
  UffImport in;
  ASSERT_TRUE(AddUffFrfs(file, map, &in, &e)) << e.OneLine();
  ASSERT_EQ(in.dataset.conditions.size(), 1u);
  const Frf& frf = *in.dataset.conditions[0].frf;
  ASSERT_EQ(frf.functions.size(), 6u);
  ASSERT_EQ(frf.frequencies_hz.size(), 100u);
  const double r = p[Param::r_e0];
  const auto coefficients = [](const FrfPoint& q) {  // x_b, z_b, theta_b
    return std::array<double, 3>{q.direction[0], q.direction[2],
                                 q.direction[2] * q.point_m[0] - q.direction[0] * q.point_m[2]};
  };
  const double m[3] = {p[Param::m_b], p[Param::m_b], p[Param::I_by]};
  const double k[3] = {p[Param::k_bx], p[Param::k_bz], p[Param::k_btheta]};
  const double c[3] = {p[Param::c_bx], p[Param::c_bz], p[Param::c_btheta]};
  for (const FrfFunction& fn : frf.functions) {
    const FrfPoint &out = *frf.outputs[fn.output].point, &input = *frf.inputs[fn.input].point;
    EXPECT_NEAR(std::abs(out.point_m[0]) + std::abs(out.point_m[2]), r, 1e-12);  // on the tread
    const auto a = coefficients(out), b = coefficients(input);
    for (size_t i = 0; i < fn.h.size(); ++i) {
      const double w = 2 * M_PI * frf.frequencies_hz[i];
      C h = 0;
      for (int q = 0; q < 3; ++q) h += -w * w * a[q] * b[q] / C(k[q] - w * w * m[q], w * c[q]);
      EXPECT_LE(std::abs(fn.h[i] - h), 1e-9 * std::abs(h)) << frf.outputs[fn.output].name << " / "
                                                           << frf.inputs[fn.input].name << " line " << i;
    }
  }
  // The tangential blow at the top drives x_b and theta_b with lever r (§9's example).
  const FrfInput& top = frf.inputs[0];
  EXPECT_EQ(top.coordinates.at(Dof::kXb), 1);
  EXPECT_NEAR(top.coordinates.at(Dof::kThetaB), r, 1e-12);
}

}  // namespace
}  // namespace ringid
