// A UFF dataset-58 writer for tests (uff_frf_test, poles_cli_test): one axis
// of records 8-11 and one function, as the SDRC definitions lay them out.
#ifndef RINGID_TESTS_UFF_WRITER_H_
#define RINGID_TESTS_UFF_WRITER_H_

#include <complex>
#include <cstdio>
#include <string>
#include <vector>

namespace ringid::testing {

struct Axis {
  int type = 0;
  int length = 0, force = 0;
  std::string units = "NONE";
};
struct Fn {
  int type = 4;  // 4 FRF, 6 coherence
  int response_node = 0, response_direction = 0, reference_node = 0, reference_direction = 0;
  double min_hz = 2.5, step_hz = 2.5;
  std::vector<std::complex<double>> y;  // complex double; a coherence: the real parts, real double
  Axis ordinate{12, 0, 0, "NONE"}, denominator{13, 0, 0, "NONE"};
};

inline std::string AxisRecord(const Axis& a, const std::string& label) {
  char line[100];
  std::snprintf(line, sizeof line, "%10d%5d%5d%5d %-20s %-20s\n", a.type, a.length, a.force, 0,
                label.c_str(), a.units.c_str());
  return line;
}

inline std::string Function58(const Fn& f) {
  char line[200];
  std::string s = "    -1\n    58\nringid test\nNONE\nNONE\nNONE\nNONE\n";
  std::snprintf(line, sizeof line, "%5d%10d%5d%10d %-10s%10d%4d %-10s%10d%4d\n", f.type, 1, 0, 0,
                "NONE", f.response_node, f.response_direction, "NONE", f.reference_node,
                f.reference_direction);
  s += line;
  const bool complex = f.type != 6;
  std::snprintf(line, sizeof line, "%10d%10zu%10d%13.5E%13.5E%13.5E\n", complex ? 6 : 4, f.y.size(),
                1, f.min_hz, f.step_hz, 0.0);
  s += line;
  s += AxisRecord({18, 0, 0, "Hz"}, "Frequency");
  s += AxisRecord(f.ordinate, "Response");
  s += AxisRecord(f.denominator, "Reference");
  s += AxisRecord({0, 0, 0, "NONE"}, "NONE");
  std::vector<double> v;
  for (const std::complex<double>& y : f.y) {
    v.push_back(y.real());
    if (complex) v.push_back(y.imag());
  }
  for (size_t i = 0; i < v.size(); ++i) {
    std::snprintf(line, sizeof line, "%20.12E", v[i]);
    s += line;
    if (i % 4 == 3 || i + 1 == v.size()) s += "\n";
  }
  return s + "    -1\n";
}

}  // namespace ringid::testing

#endif  // RINGID_TESTS_UFF_WRITER_H_
