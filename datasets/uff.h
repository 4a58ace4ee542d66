// The Universal File Format (UFF, UNV) of modal-test software, strictly: the
// datasets a modal identification reads (55 modal data, 58 and 58b functions
// at a node, 151 header, 164 units, 15 nodes, 18 coordinate systems, 82 trace
// lines); every other dataset is listed and skipped. What this reader cannot
// read is refused with one line naming the file, the dataset and the record.
//
// The syntax read (the SDRC/I-DEAS dataset definitions, as pyuff documents
// them):
//   A file is a sequence of datasets. Each opens with a line "    -1" (I6),
//   then a line with the dataset number (I6; "    58b" plus a binary header
//   for binary 58), its records, and a closing line "    -1". Blank lines may
//   separate datasets; nothing else may stand outside one.
//   Records are Fortran fixed-width fields (I10, E13.5, D25.17, 80A1, ...),
//   read by column: "1.0E+03-2.0E+00" is two E13.5 fields. A field that is
//   blank where a number must be, a field that is not a number, text beyond
//   a record's last field, a missing record and an extra line are refused
//   (one exception: 55's record 9, a node label alone on its line, may
//   overflow its I10 columns, as pyuff's sample file has it).
//   Numbers may use E or D exponents, or Fortran's "1.00000-100"; none may
//   be NaN or infinite.
//   58b: after the 11 ASCII header lines come exactly the header's byte count
//   of IEEE 754 values in the header's byte order, then "    -1" (directly,
//   or after one line ending).
#ifndef RINGID_DATASETS_UFF_H_
#define RINGID_DATASETS_UFF_H_

#include <array>
#include <complex>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "datasets/dataset.h"

namespace ringid {

// LoadUff reads files up to this size (UFF function files are large; 58b at
// 4 bytes a value, this is 64 million values). Parsing takes up to about
// eight times the file's size in memory (a 4-byte value is read as a double,
// then kept as an abscissa and a complex ordinate: six times).
inline constexpr int64_t kMaxUffFileBytes = int64_t{256} << 20;

// One dataset of the file, in file order.
struct UffDatasetInfo {
  int number = 0;        // 55, 58, 151, ... (58 for "58b")
  bool binary = false;   // "58b" (or another number followed by 'b')
  int line = 0;          // 1-based line of its opening "    -1"
  bool skipped = false;  // a number this reader does not read
  int index = -1;        // into the UffFile vector of its kind; -1 if skipped
};

// Dataset 151, header.
struct UffHeader {
  int line = 0;
  std::string model_name, description, database_program;  // records 1-3
  std::string date_created, time_created;                 // record 4
  std::optional<int> version1, version2, file_type;       // record 4, when given
  std::string date_saved, time_saved;                     // record 5
  std::string file_program;                               // record 6
  std::string date_written, time_written;                 // record 7
};

// Dataset 164, units. To convert a value from the file's units to SI, divide
// it by the factor of its dimension (164 record 2: "to convert from universal
// file units to SI divide by the appropriate factor"): a length in mm, with
// length factor 1000, is length / 1000 m.
struct UffUnits {
  int line = 0;
  int code = 0;  // 1 SI, 2 BG, 3 MG, 4 BA, 5 MM, 6 CM, 7 IN, 8 GM, 9 user, 10 MN
  std::string description;
  std::optional<int> temperature_mode;  // 1 absolute, 2 relative; often omitted
  double length_factor = 1, force_factor = 1, temperature_factor = 1;
  double temperature_offset = 0;  // as written; how it applies is not defined (see .cc)

  // `value` of dimension length^l force^f temperature^t (time is always in
  // seconds), in SI: value / (length^l force^f temperature^t). For absolute
  // temperatures the offset would apply too; this does not handle them.
  double ToSi(double value, int length_exp, int force_exp, int temperature_exp = 0) const;
  double LengthToSi(double v) const { return ToSi(v, 1, 0); }
  double ForceToSi(double v) const { return ToSi(v, 0, 1); }
};

// Dataset 18, one coordinate system (records 1-3).
struct UffCoordinateSystem {
  int label = 0;
  int type = 0;       // 0 cartesian, 1 cylindrical, 2 spherical
  int reference = 0;  // the system it is defined in
  int color = 0;
  int method = 0;  // 1: origin, point on +x, point in +xz plane
  std::string name;
  std::array<double, 3> origin{}, x_point{}, xz_point{};
};
struct UffCoordinateSystems {
  int line = 0;
  std::vector<UffCoordinateSystem> systems;
};

// Dataset 15, one node.
struct UffNode {
  int label = 0;
  int definition_system = 0, displacement_system = 0, color = 0;
  std::array<double, 3> xyz{};  // in the definition system
};
struct UffNodes {
  int line = 0;
  std::vector<UffNode> nodes;
};

// Dataset 82, a trace line.
struct UffTraceLine {
  int line = 0;
  int label = 0, color = 0;
  std::string description;
  std::vector<int> nodes;  // 0: move to the next node without drawing
};

// Dataset 55, data at nodes: one mode shape (or one response).
struct UffNodeValues {
  int label = 0;
  std::vector<std::complex<double>> values;  // values_per_node; real data: imag 0
};
struct UffModalData {
  int line = 0;
  std::array<std::string, 5> id;  // records 1-5
  // Record 6.
  int model_type = 0;     // 0 unknown, 1 structural, 2 heat transfer, 3 fluid flow
  int analysis_type = 0;  // 2 normal mode, 3 complex eigenvalue (1st order),
                          // 7 complex eigenvalue (2nd order); others kept raw
  int data_characteristic = 0;  // 1 scalar, 2 3-DOF translation, 3 6-DOF, 4-5 tensors
  int specific_data_type = 0;   // 8 displacement, 11 velocity, 12 acceleration, ...
  int data_type = 0;            // 2 real, 5 complex
  int values_per_node = 0;
  // Records 7 and 8 as written: the type-specific integers (record 7 fields
  // 3...) and reals.
  std::vector<int> integer_parameters;
  std::vector<double> real_parameters;
  int load_case = 0, mode_number = 0;  // analysis types 2, 3, 7
  // Analysis type 2, record 8.
  double frequency_hz = 0, modal_mass = 0;
  double viscous_damping_ratio = 0, hysteretic_damping_ratio = 0;
  // Analysis types 3 and 7, record 8.
  std::complex<double> eigenvalue, modal_a, modal_b;
  std::vector<UffNodeValues> nodes;  // records 9 and 10

  bool IsNormalMode() const { return analysis_type == 2; }
  bool IsComplexMode() const { return analysis_type == 3 || analysis_type == 7; }
  // Type 2: the frequency written. Types 3, 7: the damped natural frequency
  // |Im lambda| / (2 pi). Empty for other analysis types.
  std::optional<double> FrequencyHz() const;
  // Type 2: the viscous damping ratio written. Types 3, 7:
  // -Re lambda / |lambda| (empty when lambda = 0). Empty otherwise.
  std::optional<double> DampingRatio() const;
};

// Records 8-11 of dataset 58: the data characteristics of one axis.
struct UffAxis {
  int specific_data_type = 0;  // 17 time, 18 frequency, 12 acceleration, 13 force, ...
  int length_exponent = 0, force_exponent = 0, temperature_exponent = 0;
  std::string label, units_label;  // "NONE" when unused
};

// Dataset 58 (ASCII) or 58b (binary): a function at a node, e.g. an FRF.
struct UffFunction {
  int line = 0;
  bool binary = false;
  // 58b header (number line); zero for ASCII.
  int byte_order = 0;    // 1 little endian, 2 big endian
  int float_format = 0;  // 2 IEEE 754 (the only one read)
  int ascii_lines = 0;   // 11
  int64_t data_bytes = 0;
  std::array<std::string, 5> id;  // records 1-5
  // Record 6.
  int function_type = 0;  // 1 time response, 2 auto spectrum, 4 FRF, 6 coherence, ...
  int function_id = 0, version = 0, load_case = 0;
  std::string response_entity;
  int response_node = 0, response_direction = 0;  // direction: +-1..3 translation, +-4..6 rotation
  std::string reference_entity;
  int reference_node = 0, reference_direction = 0;
  // Record 7.
  int ordinate_type = 0;  // 2 real single, 4 real double, 5 complex single, 6 complex double
  int64_t points = 0;
  bool even = false;  // even abscissa spacing (no abscissa values stored)
  double abscissa_min = 0, abscissa_increment = 0, z_axis_value = 0;
  UffAxis abscissa, ordinate, denominator, z_axis;  // records 8-11
  // Record 12: `points` values each; real data: imag 0. Even spacing:
  // x[i] = abscissa_min + i * abscissa_increment.
  std::vector<double> x;
  std::vector<std::complex<double>> y;

  bool IsComplex() const { return ordinate_type == 5 || ordinate_type == 6; }
  bool IsDouble() const { return ordinate_type == 4 || ordinate_type == 6; }
};

struct UffFile {
  std::string path;
  std::vector<UffDatasetInfo> datasets;  // every dataset, read or skipped, in order
  std::vector<UffHeader> headers;                         // 151
  std::vector<UffUnits> units;                            // 164
  std::vector<UffCoordinateSystems> coordinate_systems;   // 18
  std::vector<UffNodes> nodes;                            // 15
  std::vector<UffTraceLine> trace_lines;                  // 82
  std::vector<UffModalData> modal_data;                   // 55
  std::vector<UffFunction> functions;                     // 58, 58b
};

// Parses UFF bytes; `path` only names them in messages. On failure returns
// false with `error` set (field: "dataset 55 #3 (line 30) record 8 (line 42)",
// or "line N" outside a dataset) and `file` unspecified.
bool ParseUff(const std::string& bytes, const std::string& path, UffFile* file,
              LoadError* error);
// Reads (at most kMaxUffFileBytes) and parses a UFF file.
bool LoadUff(const std::string& path, UffFile* file, LoadError* error);

}  // namespace ringid

#endif  // RINGID_DATASETS_UFF_H_
