// The Universal File Format reader (datasets/uff.h): every file of the public
// corpus (CorpusPath("uff"), pyuff's test files; skipped where absent) reads,
// with the values the files' text holds (typed in below from the files, not from this reader);
// 58b reads in both byte orders; and malformed input is refused with one line
// naming the dataset and record.
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "datasets/uff.h"
#include "tests/test_support.h"

namespace ringid {
namespace {


using UffCorpusTest = testing::CorpusTest;

UffFile Load(const std::string& name) {
  UffFile f;
  LoadError e;
  EXPECT_TRUE(LoadUff(testing::UffCorpus(name), &f, &e)) << e.OneLine();
  return f;
}


std::vector<int> Numbers(const UffFile& f) {
  std::vector<int> out;
  for (const UffDatasetInfo& d : f.datasets) out.push_back(d.number);
  return out;
}

// `text` with its one occurrence of `from` replaced by `to`.
std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

using C = std::complex<double>;

// A dataset 55 as pyuff writes one: normal mode 1 at 10 Hz, two nodes.
const std::string kModal55 =
    "    -1\n"
    "    55\n"
    "NONE\nNONE\nNONE\nNONE\nNONE\n"
    "         1         2         2         8         2         3\n"
    "         2         4         1         1\n"
    "  1.00000e+01  0.00000e+00  0.00000e+00  0.00000e+00\n"
    "         1\n"
    " -1.46518e+00 -1.46518e+00 -1.46518e+00\n"
    "         2\n"
    "  1.50162e-01  1.50162e-01  1.50162e-01\n"
    "    -1\n";

// Dataset 58 records up to 11 (an FRF, acceleration over force).
std::string Header58(int type, long points, int spacing, double min, double inc,
                     const std::string& number_line = "    58") {
  char r7[128];
  std::snprintf(r7, sizeof r7, "%10d%10ld%10d%13.5E%13.5E%13.5E\n", type, points, spacing, min,
                inc, 0.0);
  return "    -1\n" + number_line + "\nNONE\nNONE\nNONE\nNONE\nNONE\n" +
         "    4         0    0         0 NONE               1   3 NONE               2  -3\n" + r7 +
         "        18    0    0    0 Frequency            Hz                  \n"
         "        12    0    0    0 Acceleration         m/s^2               \n"
         "        13    0    0    0 Force                N                   \n"
         "         0    0    0    0 NONE                 NONE                \n";
}

const std::string kFunction58 =
    Header58(2, 8, 1, 0, 0.01) +
    "  1.00000E+00  2.00000E+00  3.00000E+00  4.00000E+00  5.00000E+00  6.00000E+00\n"
    "  7.00000E+00  8.00000E+00\n"
    "    -1\n";

void AppendValue(std::string* out, double v, size_t size, bool big_endian) {
  uint64_t u = 0;
  if (size == 4) {
    const float f = static_cast<float>(v);
    uint32_t w;
    std::memcpy(&w, &f, 4);
    u = w;
  } else {
    std::memcpy(&u, &v, 8);
  }
  for (size_t i = 0; i < size; ++i) {
    const size_t shift = 8 * (big_endian ? size - 1 - i : i);
    out->push_back(static_cast<char>((u >> shift) & 0xFF));
  }
}

// A dataset 58b of `values` (flat, as record 12 orders them).
std::string Binary58(const std::vector<double>& values, int type, int spacing, bool big_endian,
                     long long bytes = -1, int format = 2, int order = 0) {
  const size_t size = (type == 2 || type == 5) ? 4 : 8;
  const size_t per_point = (spacing ? 0 : 1) + ((type == 5 || type == 6) ? 2 : 1);
  if (bytes < 0) bytes = static_cast<long long>(values.size() * size);
  char number[128];
  std::snprintf(number, sizeof number, "    58b%6d%6d%12d%12lld%6d%6d%12d%12d",
                order ? order : (big_endian ? 2 : 1), format, 11, bytes, 0, 0, 0, 0);
  std::string s = Header58(type, static_cast<long>(values.size() / per_point), spacing, 0, 0.5,
                           number);
  for (const double v : values) AppendValue(&s, v, size, big_endian);
  return s + "    -1\n";
}

TEST_F(UffCorpusTest, ReadsEveryFileOfTheCorpusAsTheSequenceOfItsDatasets) {
  EXPECT_EQ(Numbers(Load("uff55_translation.uff")), (std::vector<int>{55, 55, 55}));
  EXPECT_EQ(Numbers(Load("uff55_translation_rotation.uff")), (std::vector<int>{55}));
  EXPECT_EQ(Numbers(Load("uff55_sample_test_record10.uff")), (std::vector<int>{55}));
  EXPECT_EQ(Numbers(Load("Sample_UFF58_ascii.uff")), (std::vector<int>{58}));
  EXPECT_EQ(Numbers(Load("Sample_UFF58b_bin.uff")), (std::vector<int>{58}));
  EXPECT_EQ(Numbers(Load("binary8byte.uff")), (std::vector<int>{58}));
  const UffFile lab = Load("TestLab_161_164_18_15_82.uff");
  EXPECT_EQ(Numbers(lab), (std::vector<int>{151, 164, 18, 15, 82, 82, 82}));
  std::vector<int> lines;
  for (const UffDatasetInfo& d : lab.datasets) {
    EXPECT_FALSE(d.skipped);
    lines.push_back(d.line);
  }
  // grep -n '^    -1' shows every other delimiter opening a dataset.
  EXPECT_EQ(lines, (std::vector<int>{1, 11, 17, 164, 203, 210, 219}));
  EXPECT_TRUE(Load("binary8byte.uff").datasets[0].binary);
  EXPECT_FALSE(Load("Sample_UFF58_ascii.uff").datasets[0].binary);
}

TEST_F(UffCorpusTest, ReadsDataset55NormalModesAsWrittenInTheFile) {
  const UffFile f = Load("uff55_translation.uff");
  ASSERT_EQ(f.modal_data.size(), 3u);
  const double freq[] = {1.00000e+01, 1.20000e+01, 1.30000e+01};
  const double first[] = {-1.46518e+00, 1.82904e+00, -6.34670e-01};
  const double last[] = {7.24863e-01, 1.98289e+00, -7.95555e-01};
  for (int m = 0; m < 3; ++m) {
    const UffModalData& d = f.modal_data[m];
    EXPECT_EQ(d.id[0], "NONE");
    EXPECT_EQ(d.model_type, 1);
    EXPECT_EQ(d.analysis_type, 2);
    EXPECT_EQ(d.data_characteristic, 2);
    EXPECT_EQ(d.specific_data_type, 8);
    EXPECT_EQ(d.data_type, 2);
    EXPECT_EQ(d.values_per_node, 3);
    EXPECT_EQ(d.load_case, 1);
    EXPECT_EQ(d.mode_number, m + 1);
    EXPECT_EQ(d.frequency_hz, freq[m]);
    EXPECT_EQ(*d.FrequencyHz(), freq[m]);
    EXPECT_EQ(*d.DampingRatio(), 0.0);
    EXPECT_EQ(d.modal_mass, 0.0);
    ASSERT_EQ(d.nodes.size(), 4u);
    EXPECT_EQ(d.nodes[0].label, 1);
    EXPECT_EQ(d.nodes[3].label, 4);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(d.nodes[0].values[k], C(first[m], 0));
      EXPECT_EQ(d.nodes[3].values[k], C(last[m], 0));
    }
  }
}

TEST_F(UffCorpusTest, ReadsSixValuesPerNodeOfTranslationAndRotation) {
  const UffModalData d = Load("uff55_translation_rotation.uff").modal_data.at(0);
  EXPECT_EQ(d.data_characteristic, 3);
  EXPECT_EQ(d.values_per_node, 6);
  EXPECT_EQ(d.frequency_hz, 9.7013e+01);
  EXPECT_EQ(d.mode_number, 0);
  EXPECT_EQ(d.load_case, 0);
  ASSERT_EQ(d.nodes.size(), 43u);
  const double first[] = {5.3569e-02, 2.0271e-02, 4.6623e-03, 0, 0, 0};
  const double last[] = {2.7381e-03, 6.1222e-01, -8.1751e-01, 0, 0, 0};
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(d.nodes.front().values[k], C(first[k], 0));
    EXPECT_EQ(d.nodes.back().values[k], C(last[k], 0));
  }
  EXPECT_EQ(d.nodes.back().label, 43);
}

// Record 8 and the node values run together ("4.111111E+03-3.111111E+03"):
// the fields are read by column.
TEST_F(UffCorpusTest, ReadsComplexEigenvalueModeWithFieldsRunTogether) {
  const UffModalData d = Load("uff55_sample_test_record10.uff").modal_data.at(0);
  EXPECT_EQ(d.id[0], "TESTTEST:Cfg=0:C1:trans:111121");
  EXPECT_EQ(d.id[4], "999999         3         8        13");
  EXPECT_EQ(d.analysis_type, 3);
  EXPECT_EQ(d.data_type, 5);
  EXPECT_EQ(d.mode_number, 1);
  EXPECT_EQ(d.eigenvalue, C(-1.111111E-01, 4.111111E+01));
  EXPECT_EQ(d.modal_a, C(4.111111E+03, -3.111111E+03));
  EXPECT_EQ(d.modal_b, C(-1.111110E+05, -2.111110E+05));
  ASSERT_EQ(d.nodes.size(), 2u);
  EXPECT_EQ(d.nodes[0].label, 111111);
  EXPECT_EQ(d.nodes[0].values[1], C(1.111111E-01, 9.111111E-02));
  EXPECT_EQ(d.nodes[1].label, 60101);
  EXPECT_EQ(d.nodes[1].values[2], C(-4.111111E-02, -1.111111E-02));
  // lambda = -0.1111111 + 41.11111 i: f = 41.11111 / 2 pi, zeta = 0.1111111 / |lambda|.
  EXPECT_NEAR(*d.FrequencyHz(), 41.11111 / (2 * M_PI), 1e-12);
  EXPECT_NEAR(*d.DampingRatio(), 0.1111111 / std::hypot(0.1111111, 41.11111), 1e-12);
  EXPECT_NEAR(*d.FrequencyHz(), 6.5431, 1e-4);
}

TEST_F(UffCorpusTest, ReadsDataset58AsciiFunctionAsWrittenInTheFile) {
  const UffFunction f = Load("Sample_UFF58_ascii.uff").functions.at(0);
  EXPECT_FALSE(f.binary);
  EXPECT_EQ(f.id[0], "Mic 01.0Scalar");
  EXPECT_EQ(f.id[2], "18-Apr-16 13:49:58");
  EXPECT_EQ(f.function_type, 1);
  EXPECT_EQ(f.response_entity, "Mic 01");
  EXPECT_EQ(f.response_node, 0);
  EXPECT_EQ(f.response_direction, 1);
  EXPECT_EQ(f.reference_entity, "NONE");
  EXPECT_EQ(f.ordinate_type, 2);
  EXPECT_EQ(f.points, 79292);
  EXPECT_TRUE(f.even);
  EXPECT_EQ(f.abscissa_min, 0.0);
  EXPECT_EQ(f.abscissa_increment, 1.52588E-05);
  EXPECT_EQ(f.abscissa.specific_data_type, 17);
  EXPECT_EQ(f.abscissa.label, "time");
  EXPECT_EQ(f.abscissa.units_label, "s");
  EXPECT_EQ(f.ordinate.specific_data_type, 21);
  EXPECT_EQ(f.ordinate.label, "Pressure");
  EXPECT_EQ(f.ordinate.units_label, "Pa");
  EXPECT_EQ(f.denominator.label, "NONE");
  ASSERT_EQ(f.y.size(), 79292u);
  ASSERT_EQ(f.x.size(), 79292u);
  EXPECT_EQ(f.y[0], C(-1.47553E-02, 0));
  EXPECT_EQ(f.y[1], C(-1.72957E-02, 0));
  EXPECT_EQ(f.y[79290], C(4.43632E-04, 0));
  EXPECT_EQ(f.y[79291], C(-4.31469E-03, 0));
  EXPECT_DOUBLE_EQ(f.x[79291], 79291 * 1.52588E-05);
}

// The two samples hold the same microphone signal: the binary file as
// floats, the ASCII file as the same values to 6 significant digits.
TEST_F(UffCorpusTest, Reads58bSingleValuesThatAgreeWithTheAsciiSample) {
  const UffFunction b = Load("Sample_UFF58b_bin.uff").functions.at(0);
  const UffFunction a = Load("Sample_UFF58_ascii.uff").functions.at(0);
  EXPECT_TRUE(b.binary);
  EXPECT_EQ(b.byte_order, 1);
  EXPECT_EQ(b.float_format, 2);
  EXPECT_EQ(b.ascii_lines, 11);
  EXPECT_EQ(b.data_bytes, 317168);
  EXPECT_EQ(b.id, a.id);
  EXPECT_EQ(b.points, a.points);
  EXPECT_EQ(b.abscissa_increment, a.abscissa_increment);
  EXPECT_EQ(b.ordinate.units_label, "Pa");
  // Bytes 0c c0 71 bc and 3c 62 8d bb (xxd): the first and last floats.
  EXPECT_EQ(b.y.front().real(), static_cast<double>(-0.014755260199308395f));
  EXPECT_EQ(b.y.back().real(), static_cast<double>(-0.004314688965678215f));
  ASSERT_EQ(b.y.size(), a.y.size());
  for (size_t i = 0; i < a.y.size(); ++i) {
    const double ascii = a.y[i].real(), binary = b.y[i].real();
    const double unit = std::pow(10.0, std::floor(std::log10(std::abs(ascii))) - 5);
    ASSERT_LE(std::abs(ascii - binary), unit) << "point " << i;
    ASSERT_EQ(b.y[i].imag(), 0.0);
    ASSERT_EQ(b.x[i], a.x[i]);
  }
}

TEST_F(UffCorpusTest, Reads58bEightByteValues) {
  const UffFunction f = Load("binary8byte.uff").functions.at(0);
  EXPECT_EQ(f.ordinate_type, 4);
  EXPECT_EQ(f.data_bytes, 2000);
  EXPECT_EQ(f.points, 250);
  EXPECT_EQ(f.response_entity, "sine 5 Hz");
  EXPECT_EQ(f.response_node, 1);
  EXPECT_EQ(f.response_direction, 0);
  EXPECT_EQ(f.abscissa_increment, 1.00000e-02);
  EXPECT_EQ(f.ordinate.specific_data_type, 12);
  EXPECT_EQ(f.ordinate.label, "acc (g)");
  EXPECT_EQ(f.ordinate.units_label, "g");
  ASSERT_EQ(f.y.size(), 250u);
  // xxd: 00000000 00000000, 00000020 efc6d33f, ..., 00000020 f9c6d33f.
  EXPECT_EQ(f.y[0], C(0, 0));
  EXPECT_EQ(f.y[1], C(0.30901697278022766, 0));
  EXPECT_EQ(f.y[5], C(1.0, 0));
  EXPECT_EQ(f.y[249], C(0.3090193569660187, 0));
  EXPECT_DOUBLE_EQ(f.x[249], 2.49);
}

// The corpus file with the header's byte order set to 2 and every value's
// bytes reversed.
std::string BigEndianCopy(const std::string& bytes, size_t value_size) {
  std::string big = bytes;
  const size_t line2 = big.find('\n') + 1;
  big.replace(line2 + 7, 6, "     2");
  size_t start = 0;
  for (int i = 0; i < 13; ++i) start = big.find('\n', start) + 1;
  const size_t end = big.rfind("    -1");
  EXPECT_EQ((end - start) % value_size, 0u);
  for (size_t p = start; p + value_size <= end; p += value_size) {
    std::reverse(big.begin() + p, big.begin() + p + value_size);
  }
  return big;
}

TEST_F(UffCorpusTest, BigEndianCopiesOfThe58bFilesReadTheSameValues) {
  for (const auto& [name, size] : {std::pair<std::string, size_t>{"Sample_UFF58b_bin.uff", 4},
                                   {"binary8byte.uff", 8}}) {
    const UffFunction little = Load(name).functions.at(0);
    const UffFunction big =
        testing::ParsedUff(BigEndianCopy(testing::ReadFile(testing::UffCorpus(name)), size)).functions.at(0);
    EXPECT_EQ(little.byte_order, 1);
    EXPECT_EQ(big.byte_order, 2);
    ASSERT_EQ(big.y.size(), little.y.size());
    EXPECT_EQ(big.y, little.y) << name;
    EXPECT_EQ(big.x, little.x) << name;
  }
}

TEST_F(UffCorpusTest, ReadsTestLabHeaderUnitsCoordinateSystemsNodesAndTraceLines) {
  const UffFile f = Load("TestLab_161_164_18_15_82.uff");
  const UffHeader& h = f.headers.at(0);
  EXPECT_EQ(h.model_name, "AME_Test");
  EXPECT_EQ(h.description, "NONE");
  EXPECT_EQ(h.database_program, "LMS Test.Lab Rev project-15A");
  EXPECT_EQ(h.date_created, "11-Oct-17");
  EXPECT_EQ(h.time_created, "09:34:21");
  EXPECT_FALSE(h.version1.has_value());
  EXPECT_EQ(h.date_written, "17-Oct-17");
  EXPECT_EQ(h.time_written, "13:50:13");
  const UffUnits& u = f.units.at(0);
  EXPECT_EQ(u.code, 9);
  EXPECT_EQ(u.description, "USER_DEFINED");
  EXPECT_FALSE(u.temperature_mode.has_value());  // the line ends after the description
  EXPECT_EQ(u.length_factor, 1.0);
  EXPECT_EQ(u.force_factor, 1.0);
  EXPECT_EQ(u.temperature_factor, 1.0);
  EXPECT_EQ(u.temperature_offset, -2.73149999999999960e+02);
  EXPECT_EQ(u.LengthToSi(2.35), 2.35);
  const std::vector<UffCoordinateSystem>& cs = f.coordinate_systems.at(0).systems;
  ASSERT_EQ(cs.size(), 36u);
  EXPECT_EQ(cs[0].label, 1);
  EXPECT_EQ(cs[0].name, "SYS1");
  EXPECT_EQ(cs[0].color, 8);
  EXPECT_EQ(cs[0].method, 1);
  EXPECT_EQ(cs[0].origin, (std::array<double, 3>{-2.4, -0.95, 0}));
  EXPECT_EQ(cs[0].x_point, (std::array<double, 3>{-3.4, -0.95, -8.74228e-08}));
  EXPECT_EQ(cs[0].xz_point, (std::array<double, 3>{-3.4, -0.95, -1}));
  EXPECT_EQ(cs[35].name, "SYS36");
  EXPECT_EQ(cs[35].xz_point, (std::array<double, 3>{2.2, 8.4, 1}));
  const std::vector<UffNode>& n = f.nodes.at(0).nodes;
  ASSERT_EQ(n.size(), 36u);
  EXPECT_EQ(n[0].label, 1);
  EXPECT_EQ(n[0].displacement_system, 1);
  EXPECT_EQ(n[0].color, 8);
  EXPECT_EQ(n[0].xyz, (std::array<double, 3>{-2.4, -0.95, 0}));
  EXPECT_EQ(n[35].label, 36);
  EXPECT_EQ(n[35].displacement_system, 36);
  EXPECT_EQ(n[35].xyz, (std::array<double, 3>{1.2, 8.4, 0}));
  ASSERT_EQ(f.trace_lines.size(), 3u);
  EXPECT_EQ(f.trace_lines[0].description, "Massif");
  EXPECT_EQ(f.trace_lines[0].nodes, (std::vector<int>{2, 5, 6, 3, 4, 1, 2, 3, 0}));
  EXPECT_EQ(f.trace_lines[1].description, "Stator");
  EXPECT_EQ(f.trace_lines[1].nodes.size(), 32u);
  EXPECT_EQ(f.trace_lines[1].nodes.back(), 0);
  EXPECT_EQ(f.trace_lines[2].label, 3);
  EXPECT_EQ(f.trace_lines[2].nodes, (std::vector<int>{34, 33, 36, 35, 32, 31, 34, 0, 33, 32, 0}));
}

const std::string kUnits164 =
    "    -1\n   164\n"
    "         5MM (milli newton)            2\n"
    "  1.00000000000000000D+03  1.00000000000000000D+03  1.00000000000000000D+00\n"
    "  2.73150000000000000D+02\n"
    "    -1\n";

// 164 record 2: "To convert from universal file units to SI divide by the
// appropriate factor". In mm and mN: 1500 mm = 1.5 m, 2500 mN = 2.5 N,
// 1 mN/mm = 1 N/m, 1 mN/mm^2 = 1000 Pa.
TEST(UffReaderTest, UnitsConvertToSiByDividingByTheirFactors) {
  const UffUnits u = testing::ParsedUff(kUnits164).units.at(0);
  EXPECT_EQ(u.code, 5);
  EXPECT_EQ(u.description, "MM (milli newton)");
  EXPECT_EQ(u.temperature_mode, 2);
  EXPECT_EQ(u.length_factor, 1000.0);
  EXPECT_EQ(u.temperature_offset, 273.15);
  EXPECT_DOUBLE_EQ(u.LengthToSi(1500), 1.5);
  EXPECT_DOUBLE_EQ(u.ForceToSi(2500), 2.5);
  EXPECT_DOUBLE_EQ(u.ToSi(1, -1, 1), 1.0);
  EXPECT_DOUBLE_EQ(u.ToSi(1, -2, 1), 1000.0);
}

TEST(UffReaderTest, ListsAndSkipsDatasetsItDoesNotRead) {
  const std::string text =
      kUnits164 +
      "    -1\n  2411\n         1         1         1        11\n   0.0   0.0   0.0\n    -1\n"
      "    -1\n  2414b     1     2           1           5     0     0           0           0\n"
      "header\nA\nB\x01\x02    -1\n" +
      kModal55;
  const UffFile f = testing::ParsedUff(text);
  ASSERT_EQ(Numbers(f), (std::vector<int>{164, 2411, 2414, 55}));
  const bool skipped[] = {false, true, true, false}, binary[] = {false, false, true, false};
  const int lines[] = {1, 7, 12, 17}, index[] = {0, -1, -1, 0};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(f.datasets[i].skipped, skipped[i]) << i;
    EXPECT_EQ(f.datasets[i].binary, binary[i]) << i;
    EXPECT_EQ(f.datasets[i].line, lines[i]) << i;
    EXPECT_EQ(f.datasets[i].index, index[i]) << i;
  }
  EXPECT_EQ(f.modal_data.at(0).nodes.size(), 2u);
}

TEST(UffReaderTest, ReadsEachAsciiLayoutOfRecord12) {
  // Complex double, even: 4E20.12.
  UffFunction f = testing::ParsedUff(Header58(6, 3, 1, 5, 0.5) +
                        "  1.000000000000E+00  2.000000000000E+00  3.000000000000E+00  4.000000000000E+00\n"
                        "  5.000000000000E+00 -6.000000000000E+00\n    -1\n")
                      .functions.at(0);
  EXPECT_EQ(f.y, (std::vector<C>{{1, 2}, {3, 4}, {5, -6}}));
  EXPECT_EQ(f.x, (std::vector<double>{5, 5.5, 6}));
  // Complex double, uneven: E13.5,2E20.12.
  f = testing::ParsedUff(Header58(6, 2, 0, 0, 0) +
            "  1.00000E+01  1.000000000000E+00 -2.000000000000E+00\n"
            "  2.50000E+01  3.000000000000E+00  4.000000000000E+00\n    -1\n")
          .functions.at(0);
  EXPECT_EQ(f.x, (std::vector<double>{10, 25}));
  EXPECT_EQ(f.y, (std::vector<C>{{1, -2}, {3, 4}}));
  // Real double, uneven: 2(E13.5,E20.12).
  f = testing::ParsedUff(Header58(4, 3, 0, 0, 0) +
            "  1.00000E+01  1.000000000000E+00  2.00000E+01  2.000000000000E+00\n"
            "  4.00000E+01 -3.000000000000E+00\n    -1\n")
          .functions.at(0);
  EXPECT_EQ(f.x, (std::vector<double>{10, 20, 40}));
  EXPECT_EQ(f.y, (std::vector<C>{{1, 0}, {2, 0}, {-3, 0}}));
  // Complex single, uneven: 6E13.5.
  f = testing::ParsedUff(Header58(5, 2, 0, 0, 0) +
            "  1.00000E+00  2.00000E+00  3.00000E+00  2.00000E+00  4.00000E+00  5.00000E+00\n"
            "    -1\n")
          .functions.at(0);
  EXPECT_EQ(f.x, (std::vector<double>{1, 2}));
  EXPECT_EQ(f.y, (std::vector<C>{{2, 3}, {4, 5}}));
  EXPECT_EQ(f.response_node, 1);
  EXPECT_EQ(f.response_direction, 3);
  EXPECT_EQ(f.reference_node, 2);
  EXPECT_EQ(f.reference_direction, -3);
  EXPECT_EQ(f.function_type, 4);
  EXPECT_EQ(f.denominator.units_label, "N");
}

// Fortran writes E, or D for double precision, and drops the letter of a
// three-digit exponent.
TEST(UffReaderTest, ReadsTheFortranFormsOfAnExponent) {
  const UffFunction f = testing::ParsedUff(Header58(2, 6, 1, 0, 0.01) +
                              "  1.00000E+00  2.00000e-01  3.00000D+02  4.00000d-03  5.00000-100 -6.00000+101\n"
                              "    -1\n")
                            .functions.at(0);
  EXPECT_EQ(f.y, (std::vector<C>{{1, 0}, {0.2, 0}, {300, 0}, {0.004, 0}, {5e-100, 0}, {-6e101, 0}}));
}

TEST(UffReaderTest, Reads58bInBothByteOrdersAndAfterALineEnding) {
  for (const bool big : {false, true}) {
    const UffFunction d =
        testing::ParsedUff(Binary58({1.5, -2.25, 1e-300, 3e300, 0.125, -7}, 6, 1, big)).functions.at(0);
    EXPECT_EQ(d.y, (std::vector<C>{{1.5, -2.25}, {1e-300, 3e300}, {0.125, -7}}));
    EXPECT_EQ(d.x, (std::vector<double>{0, 0.5, 1}));
    const UffFunction s = testing::ParsedUff(Binary58({1.5, -2.25, 0.125, -7}, 5, 1, big)).functions.at(0);
    EXPECT_EQ(s.y, (std::vector<C>{{1.5, -2.25}, {0.125, -7}}));
  }
  const UffFunction uneven = testing::ParsedUff(Binary58({1, 2, 3, 4, 5, 6}, 6, 0, true)).functions.at(0);
  EXPECT_EQ(uneven.x, (std::vector<double>{1, 4}));
  EXPECT_EQ(uneven.y, (std::vector<C>{{2, 3}, {5, 6}}));
  std::string crlf = Binary58({1, 2}, 4, 1, false);
  crlf.replace(crlf.size() - 7, 7, "\r\n    -1\r\n");
  EXPECT_EQ(testing::ParsedUff(crlf).functions.at(0).y, (std::vector<C>{{1, 0}, {2, 0}}));
}

const std::string kHeader151 =
    "    -1\n   151\nmodel\nNONE\nwriter\n"
    "01-Jan-20 10:00:00           1         2         0\n"
    "01-Jan-20 10:00:00\nwriter\n02-Jan-20 11:00:00\n    -1\n";
const std::string kTrace82 =
    "    -1\n    82\n         7         9         8\nFrame\n"
    "         1         2         3         4         5         6         7         8\n"
    "         1         0         0         0         0         0         0         0\n"
    "    -1\n";

struct Malformed {
  std::string what, text, field, message;
};

std::vector<Malformed> MalformedInputs() {
  const std::string d55 = "dataset 55 #1 (line 1) ", d58 = "dataset 58 #1 (line 1) ",
                    d58b = "dataset 58b #1 (line 1) ";
  const std::string b4 = Binary58({1, 2, 3, 4}, 4, 1, false);
  const std::string b4_data_end = b4.substr(0, b4.size() - 7);  // without "    -1\n"
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return {
      {"not a number", Replace(kModal55, "  1.00000e+01", "  1.0000xe+01"),
       d55 + "record 8 (line 10)", "value 1: not a number: '1.0000xe+01'"},
      {"NaN", Replace(kModal55, "  1.00000e+01", "          nan"), d55 + "record 8 (line 10)",
       "value 1: not a number: 'nan'"},
      {"overflow", Replace(kModal55, "  1.00000e+01", "  1.0000e+999"), d55 + "record 8 (line 10)",
       "value 1: out of range"},
      {"short record", Replace(kModal55, "         2         3\n", "         2\n"),
       d55 + "record 6 (line 8)", "field 6 (number of values per node): missing (blank)"},
      {"short node values", Replace(kModal55, " -1.46518e+00 -1.46518e+00 -1.46518e+00", " -1.46518e+00 -1.46518e+00"),
       d55 + "record 10 (line 12)", "value 3: missing (blank)"},
      {"not closed", kModal55.substr(0, kModal55.size() - 7), "dataset 55 #1 (line 1)",
       "not closed by '    -1': the file ends at line 15"},
      {"data type", Replace(kModal55, "8         2         3", "8         3         3"),
       d55 + "record 6 (line 8)", "field 5 (data type) must be 2 (real) or 5 (complex), not 3"},
      {"values per node", Replace(kModal55, "8         2         3", "8         2         6"),
       d55 + "record 6 (line 8)", "field 6 (number of values per node) is 6, but data characteristic 2 has 3"},
      {"text after the record", Replace(kModal55, "         1         1\n", "         1         1         9\n"),
       d55 + "record 7 (line 9)", "unexpected text after column 40: '9'"},
      {"extra line", Replace(kModal55, "  1.50162e-01\n", "  1.50162e-01\ngarbage\n"),
       d55 + "record 9 (line 15)", "field 1 (node label): not an integer: 'garbage'"},
      {"control character", Replace(kModal55, "    55\nNONE", "    55\nNO\x01" "E"),
       d55 + "record 1 (line 3)", "a control character (byte 0x01)"},
      {"count above the data", Replace(kFunction58, "         8         1", "         9         1"),
       d58 + "record 7 (line 9)", "9 points of real single data need at least 117 bytes; the file has 113 left"},
      {"count above the data, more bytes follow",
       Replace(kFunction58, "         8         1", "         9         1") + kUnits164,
       d58 + "record 12 (line 15)", "value 9: missing (blank)"},
      {"count below the data", Replace(kFunction58, "         8         1", "         7         1"),
       d58 + "record 12 (line 15)", "unexpected text after column 13: '8.00000E+00'"},
      {"absurd count", Replace(kFunction58, "         8         1", " 999999999         1"),
       d58 + "record 7 (line 9)", "999999999 points of real single data need at least 12999999987 bytes"},
      {"ordinate type", Replace(kFunction58, "         2         8", "         3         8"),
       d58 + "record 7 (line 9)", "field 1 (ordinate data type) must be 2, 4, 5 or 6, not 3"},
      {"truncated binary", b4_data_end.substr(0, b4_data_end.size() - 10), d58b + "record 12 (line 14)",
       "truncated: 32 bytes of binary data announced, the file has 22 left"},
      {"byte count", Binary58({1, 2, 3, 4}, 4, 1, false, 24), d58b + "number line (line 2)",
       "field 6 (number of bytes) is 24, but 4 points of real double data take 32 bytes"},
      {"binary NaN", Binary58({1, nan, 3, 4}, 4, 1, false), d58b + "record 12 (line 14)",
       "value 2 (byte 8 of the data) is not finite"},
      {"float format", Binary58({1, 2}, 4, 1, false, -1, 1), d58b + "number line (line 2)",
       "field 4 (floating-point format) is 1; only 2 (IEEE 754) is read"},
      {"byte order", Binary58({1, 2}, 4, 1, false, -1, 2, 3), d58b + "number line (line 2)",
       "field 3 (byte ordering) must be 1 to 2, not 3"},
      {"binary not closed", b4_data_end + "xx    -1\n", d58b + "after record 12 (line 14)",
       "expected '    -1' right after the binary data, found 'xx    -1'"},
      {"text outside", "hello\n" + kModal55, "line 1", "expected '    -1' opening a dataset, found 'hello'"},
      {"dataset number", Replace(kModal55, "    55\n", "    5x\n"), "line 2",
       "expected a dataset number (I6) after '    -1', found '    5x'"},
      {"empty", "", "", "no dataset"},
      {"unit factor", Replace(kUnits164, "2\n  1.0", "2\n  0.0"),
       "dataset 164 #1 (line 1) record 2 (line 4)", "value 1 (a unit factor) must be positive"},
      {"trace line count", Replace(kTrace82, "         1         0         0", "         1         7         0"),
       "dataset 82 #1 (line 1) record 3 (line 6)", "more nodes than the 9 of record 1: 7"},
      {"extra record", Replace(kHeader151, "11:00:00\n", "11:00:00\nextra\n"),
       "dataset 151 #1 (line 1) after record 7 (line 10)", "expected '    -1' closing the dataset, found 'extra'"},
      {"skipped not closed", "    -1\n  2411\n  1 2 3\n", "dataset 2411 #1 (line 1)",
       "not closed by '    -1': the file ends at line 4"},
      {"binary 55", Replace(kModal55, "    55\n", "    55b     1     2          11           0     0     0           0           0\n"),
       "dataset 55b #1 (line 1) number line (line 2)", "dataset 55 has no binary form"},
  };
}

TEST(UffReaderTest, RefusesMalformedInputNamingTheDatasetAndRecordInOneLine) {
  for (const Malformed& m : MalformedInputs()) {
    UffFile f;
    LoadError e;
    ASSERT_FALSE(ParseUff(m.text, "bad.uff", &f, &e)) << m.what;
    EXPECT_EQ(e.file, "bad.uff") << m.what;
    EXPECT_EQ(e.field, m.field) << m.what << ": " << e.OneLine();
    EXPECT_NE(e.message.find(m.message), std::string::npos) << m.what << ": " << e.OneLine();
    for (const char c : e.field + e.message) {
      EXPECT_TRUE(c >= 32 && c < 127) << m.what << ": " << e.OneLine();
    }
  }
  EXPECT_GE(MalformedInputs().size(), 15u);
}

TEST(UffReaderTest, TheValidInputsTheMalformedOnesComeFromRead) {
  for (const std::string& text : {kModal55, kFunction58, kUnits164, kHeader151, kTrace82,
                                  Binary58({1, 2, 3, 4}, 4, 1, false)}) {
    EXPECT_EQ(testing::ParsedUff(text).datasets.size(), 1u);
  }
  EXPECT_EQ(testing::ParsedUff(kTrace82).trace_lines.at(0).nodes, (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 1}));
  const UffHeader h = testing::ParsedUff(kHeader151).headers.at(0);
  EXPECT_EQ(h.version2, 2);
  EXPECT_EQ(h.file_type, 0);
}

TEST(UffReaderTest, LoadRefusesAFileLargerThanItsCapNamingTheSize) {
  const std::string path = testing::Scratch("huge.uff");
  { std::ofstream(path) << "    -1\n"; }
  std::filesystem::resize_file(path, kMaxUffFileBytes + 1);  // sparse: no disk used
  UffFile f;
  LoadError e;
  EXPECT_FALSE(LoadUff(path, &f, &e));
  EXPECT_NE(e.message.find("268435457 bytes, more than the 268435456"), std::string::npos)
      << e.OneLine();
  std::filesystem::remove(path);
  EXPECT_FALSE(LoadUff(testing::Scratch("no-such.uff"), &f, &e));
  EXPECT_EQ(e.message, "cannot open file");
}

}  // namespace
}  // namespace ringid
