#include "datasets/uff.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <new>
#include <string_view>

#include "datasets/uff_internal.h"

namespace ringid {
namespace {

using uff_internal::CheckRange;
using uff_internal::Fail;
using uff_internal::Failure;
using uff_internal::IsDelimiter;
using uff_internal::Line;
using uff_internal::Quoted;
using uff_internal::Reader;
using uff_internal::Trim;

constexpr size_t kWhole = std::string_view::npos;  // a text field to the end of the line
const std::vector<size_t> k6E13 = {13, 13, 13, 13, 13, 13};  // FORMAT(6E13.5)

std::string RecordName(int n) { return "record " + std::to_string(n); }

// Dataset 151, header: FORMAT(80A1) x3, (10A1,10A1,3I10), (10A1,10A1),
// (80A1), (10A1,10A1).
void ReadHeader(Reader& r, UffHeader* h) {
  h->model_name = Reader::Text(r.Record("record 1"), 0, kWhole);
  h->description = Reader::Text(r.Record("record 2"), 0, kWhole);
  h->database_program = Reader::Text(r.Record("record 3"), 0, kWhole);
  const Line l4 = r.Record("record 4");
  h->date_created = Reader::Text(l4, 0, 10);
  h->time_created = Reader::Text(l4, 10, 10);
  const auto optional_int = [&](size_t begin, const char* what) -> std::optional<int> {
    const std::optional<int64_t> v = r.OptionalInt(l4, "record 4", begin, 10, what);
    if (v) CheckRange(r, "record 4", l4, what, *v, INT32_MIN, INT32_MAX);
    return v ? std::optional<int>(static_cast<int>(*v)) : std::nullopt;
  };
  h->version1 = optional_int(20, "field 3 (version)");
  h->version2 = optional_int(30, "field 4 (version)");
  h->file_type = optional_int(40, "field 5 (file type)");
  r.NothingAfter(l4, "record 4", 50);
  const Line l5 = r.Record("record 5");
  h->date_saved = Reader::Text(l5, 0, 10);
  h->time_saved = Reader::Text(l5, 10, 10);
  r.NothingAfter(l5, "record 5", 20);
  h->file_program = Reader::Text(r.Record("record 6"), 0, kWhole);
  const Line l7 = r.Record("record 7");
  h->date_written = Reader::Text(l7, 0, 10);
  h->time_written = Reader::Text(l7, 10, 10);
  r.NothingAfter(l7, "record 7", 20);
  r.Close("record 7");
}

// Dataset 164, units: FORMAT(I10,20A1,I10), FORMAT(3D25.17) for 4 values.
void ReadUnits(Reader& r, UffUnits* u) {
  const std::string r1 = "record 1";
  const Line l1 = r.Record(r1);
  u->code = r.Int(l1, r1, 0, 10, "field 1 (units code)");
  CheckRange(r, r1, l1, "field 1 (units code)", u->code, 1, 10);
  u->description = Reader::Text(l1, 10, 20);
  const std::optional<int64_t> mode = r.OptionalInt(l1, r1, 30, 10, "field 3 (temperature mode)");
  if (mode) {
    CheckRange(r, r1, l1, "field 3 (temperature mode)", *mode, 1, 2);
    u->temperature_mode = static_cast<int>(*mode);
  }
  r.NothingAfter(l1, r1, 40);
  const int line2 = r.LineNumber();
  const std::vector<double> f = r.Reals("record 2", 4, {25, 25, 25});
  u->length_factor = f[0];
  u->force_factor = f[1];
  u->temperature_factor = f[2];
  u->temperature_offset = f[3];
  for (int i = 0; i < 3; ++i) {
    if (!(f[i] > 0)) {
      Fail(r.Field("record 2", line2), "value " + std::to_string(i + 1) +
                                           " (a unit factor) must be positive, not " +
                                           std::to_string(f[i]));
    }
  }
  r.Close("record 2");
}

// Dataset 15, nodes: FORMAT(4I10,1P3E13.5) per node.
void ReadNodes(Reader& r, UffNodes* nodes) {
  const std::string r1 = "record 1";
  while (!r.AtClose()) {
    const Line l = r.Record(r1);
    UffNode n;
    n.label = r.Int(l, r1, 0, 10, "field 1 (node label)");
    n.definition_system = r.Int(l, r1, 10, 10, "field 2 (definition coordinate system)");
    n.displacement_system = r.Int(l, r1, 20, 10, "field 3 (displacement coordinate system)");
    n.color = r.Int(l, r1, 30, 10, "field 4 (color)");
    for (int k = 0; k < 3; ++k) {
      n.xyz[k] = r.Real(l, r1, 40 + 13 * k, 13, "field " + std::to_string(5 + k) + " (coordinate)");
    }
    r.NothingAfter(l, r1, 79);
    nodes->nodes.push_back(n);
  }
  r.Close(r1);
}

// Dataset 18, coordinate systems: FORMAT(5I10), (20A2), (1P6E13.5) for 9
// values, per system.
void ReadCoordinateSystems(Reader& r, UffCoordinateSystems* out) {
  const std::string r1 = "record 1", r2 = "record 2";
  while (!r.AtClose()) {
    const Line l1 = r.Record(r1);
    UffCoordinateSystem s;
    s.label = r.Int(l1, r1, 0, 10, "field 1 (coordinate system number)");
    s.type = r.Int(l1, r1, 10, 10, "field 2 (coordinate system type)");
    s.reference = r.Int(l1, r1, 20, 10, "field 3 (reference coordinate system)");
    s.color = r.Int(l1, r1, 30, 10, "field 4 (color)");
    s.method = r.Int(l1, r1, 40, 10, "field 5 (method of definition)");
    r.NothingAfter(l1, r1, 50);
    const Line l2 = r.Record(r2);
    s.name = Reader::Text(l2, 0, 40);
    r.NothingAfter(l2, r2, 40);
    const std::vector<double> v = r.Reals("record 3", 9, k6E13);
    for (int k = 0; k < 3; ++k) {
      s.origin[k] = v[k];
      s.x_point[k] = v[3 + k];
      s.xz_point[k] = v[6 + k];
    }
    out->systems.push_back(s);
  }
  r.Close("record 3");
}

// Dataset 82, a trace line: FORMAT(3I10), (80A1), (8I10) for its nodes. The
// last line of nodes may be padded with zeros to 8 fields.
void ReadTraceLine(Reader& r, UffTraceLine* t) {
  const std::string r1 = "record 1", r3 = "record 3";
  const Line l1 = r.Record(r1);
  t->label = r.Int(l1, r1, 0, 10, "field 1 (trace line number)");
  const int n = r.Int(l1, r1, 10, 10, "field 2 (number of nodes)");
  t->color = r.Int(l1, r1, 20, 10, "field 3 (color)");
  r.NothingAfter(l1, r1, 30);
  if (n < 1) {
    Fail(r.Field(r1, l1.number),
         "field 2 (number of nodes) must be positive, not " + std::to_string(n));
  }
  if (static_cast<size_t>(n) > r.Remaining() / 10) {
    Fail(r.Field(r1, l1.number), std::to_string(n) + " nodes need at least " +
                                     std::to_string(10 * static_cast<int64_t>(n)) +
                                     " bytes; the file has " + std::to_string(r.Remaining()) +
                                     " left");
  }
  t->description = Reader::Text(r.Record("record 2"), 0, kWhole);
  t->nodes.reserve(n);
  while (static_cast<int>(t->nodes.size()) < n) {
    const Line l = r.Record(r3);
    int k = 0;
    for (; k < 8 && static_cast<int>(t->nodes.size()) < n; ++k) {
      const std::string what = "node " + std::to_string(t->nodes.size() + 1);
      const int node = r.Int(l, r3, 10 * k, 10, what);
      if (node < 0) {
        Fail(r.Field(r3, l.number), what + " must not be negative, not " + std::to_string(node));
      }
      t->nodes.push_back(node);
    }
    for (; k < 8; ++k) {  // padding after the last node
      const std::optional<int64_t> pad = r.OptionalInt(l, r3, 10 * k, 10, "padding");
      if (pad && *pad != 0) {
        Fail(r.Field(r3, l.number), "more nodes than the " + std::to_string(n) +
                                        " of record 1: " + std::to_string(*pad));
      }
    }
    r.NothingAfter(l, r3, 80);
  }
  r.Close(r3);
}

// The number of values per node a data characteristic implies (55, note 7);
// 0 for unknown.
int ValuesPerNodeOf(int data_characteristic) {
  static constexpr int kValues[] = {0, 1, 3, 6, 6, 9};
  return kValues[data_characteristic];
}
constexpr int kMaxValuesPerNode = 64;  // for characteristic 0 (unknown)

// Records 7 and 8 of dataset 55: FORMAT(8I10) for 2 + NINT integers, then
// FORMAT(6E13.5) for NRVAL reals.
void ReadModalParameters(Reader& r, UffModalData* m) {
  const std::string r7 = "record 7";
  const Line first = r.Record(r7);
  const int nint = r.Int(first, r7, 0, 10, "field 1 (number of integer values)");
  const int nreal = r.Int(first, r7, 10, 10, "field 2 (number of real values)");
  CheckRange(r, r7, first, "field 1 (number of integer values)", nint, 1, 10);
  CheckRange(r, r7, first, "field 2 (number of real values)", nreal, 1, 12);
  Line l = first;
  size_t column = 20;
  for (int k = 0; k < nint; ++k) {
    if (column == 80) {
      l = r.Record(r7);
      column = 0;
    }
    m->integer_parameters.push_back(r.Int(l, r7, column, 10, "field " + std::to_string(k + 3)));
    column += 10;
  }
  r.NothingAfter(l, r7, column);
  m->real_parameters = r.Reals("record 8", nreal, k6E13);
  if (!m->IsNormalMode() && !m->IsComplexMode()) return;  // kept as written
  const int want = m->IsNormalMode() ? 4 : 6;
  if (nint != 2 || nreal != want) {
    Fail(r.Field(r7, first.number),
         "analysis type " + std::to_string(m->analysis_type) + " has 2 integer and " +
             std::to_string(want) + " real values, not " + std::to_string(nint) + " and " +
             std::to_string(nreal));
  }
  m->load_case = m->integer_parameters[0];
  m->mode_number = m->integer_parameters[1];
  const std::vector<double>& v = m->real_parameters;
  if (m->IsNormalMode()) {
    m->frequency_hz = v[0];
    m->modal_mass = v[1];
    m->viscous_damping_ratio = v[2];
    m->hysteretic_damping_ratio = v[3];
  } else {
    m->eigenvalue = {v[0], v[1]};
    m->modal_a = {v[2], v[3]};
    m->modal_b = {v[4], v[5]};
  }
}

// Dataset 55, data at nodes: records 1-5 (80A1), 6 (6I10), 7, 8, then per
// node 9 (I10) and 10 (6E13.5 for NDV real or 2 NDV complex values).
void ReadModalData(Reader& r, UffModalData* m) {
  for (int i = 0; i < 5; ++i) m->id[i] = Reader::Text(r.Record(RecordName(i + 1)), 0, kWhole);
  const std::string r6 = "record 6";
  const Line l6 = r.Record(r6);
  m->model_type = r.Int(l6, r6, 0, 10, "field 1 (model type)");
  m->analysis_type = r.Int(l6, r6, 10, 10, "field 2 (analysis type)");
  m->data_characteristic = r.Int(l6, r6, 20, 10, "field 3 (data characteristic)");
  m->specific_data_type = r.Int(l6, r6, 30, 10, "field 4 (specific data type)");
  m->data_type = r.Int(l6, r6, 40, 10, "field 5 (data type)");
  m->values_per_node = r.Int(l6, r6, 50, 10, "field 6 (number of values per node)");
  r.NothingAfter(l6, r6, 60);
  CheckRange(r, r6, l6, "field 1 (model type)", m->model_type, 0, 3);
  CheckRange(r, r6, l6, "field 2 (analysis type)", m->analysis_type, 0, 7);
  CheckRange(r, r6, l6, "field 3 (data characteristic)", m->data_characteristic, 0, 5);
  if (m->data_type != 2 && m->data_type != 5) {
    Fail(r.Field(r6, l6.number), "field 5 (data type) must be 2 (real) or 5 (complex), not " +
                                     std::to_string(m->data_type));
  }
  const int implied = ValuesPerNodeOf(m->data_characteristic);
  if (implied != 0 && m->values_per_node != implied) {
    Fail(r.Field(r6, l6.number),
         "field 6 (number of values per node) is " + std::to_string(m->values_per_node) +
             ", but data characteristic " + std::to_string(m->data_characteristic) + " has " +
             std::to_string(implied));
  }
  CheckRange(r, r6, l6, "field 6 (number of values per node)", m->values_per_node, 1,
             kMaxValuesPerNode);
  ReadModalParameters(r, m);
  const bool complex = m->data_type == 5;
  const size_t count = static_cast<size_t>(m->values_per_node) * (complex ? 2 : 1);
  while (!r.AtClose()) {
    // Record 9 holds one I10 field. A label overflowing its columns (pyuff's
    // sample writes "      60101", 11 columns) is still the line's one
    // integer, and read as such.
    const Line l9 = r.Record("record 9");
    UffNodeValues node;
    node.label = r.Int(l9, "record 9", 0, std::max<size_t>(10, l9.text.size()),
                       "field 1 (node label)");
    const std::vector<double> v = r.Reals("record 10", count, k6E13);
    for (int k = 0; k < m->values_per_node; ++k) {
      node.values.emplace_back(complex ? v[2 * k] : v[k], complex ? v[2 * k + 1] : 0.0);
    }
    m->nodes.push_back(std::move(node));
  }
  r.Close("record 10");
}

bool Known(int number) {
  switch (number) {
    case 15: case 18: case 55: case 58: case 82: case 151: case 164: return true;
    default: return false;
  }
}

class FileParser {
 public:
  FileParser(const std::string& bytes, UffFile* file) : r_(bytes), file_(file) {}

  void Run() {
    int ordinal = 0;
    while (!r_.AtEnd()) {
      const Line l = r_.NextLine();
      const std::string where = "line " + std::to_string(l.number);
      Reader::CheckText(l, where);
      if (Trim(l.text).empty()) continue;
      if (!IsDelimiter(l.text)) {
        Fail(where, std::string("expected '    -1' opening ") + (ordinal ? "the next" : "a") +
                        " dataset, found " + Quoted(l.text));
      }
      if (r_.AtEnd()) Fail(where, "the file ends after '    -1': no dataset number follows");
      Dataset(l, ++ordinal);
    }
    if (ordinal == 0) Fail("", "no dataset (a universal file is datasets between '    -1' lines)");
  }

 private:
  void Dataset(const Line& open, int ordinal) {
    const Line n = r_.NextLine();
    const std::string where = "line " + std::to_string(n.number);
    Reader::CheckText(n, where);
    const std::string_view field = Trim(n.text.substr(0, 6));
    if (field.empty() || field.size() > 6 ||
        field.find_first_not_of("0123456789") != std::string_view::npos) {
      Fail(where, "expected a dataset number (I6) after '    -1', found " + Quoted(n.text));
    }
    UffDatasetInfo info;
    info.number = std::stoi(std::string(field));
    info.binary = n.text.size() > 6 && n.text[6] == 'b';
    info.line = open.number;
    r_.BeginDataset(std::to_string(info.number) + (info.binary ? "b" : ""), ordinal, open.number);
    if (!info.binary) r_.NothingAfter(n, "number line", 6);
    if (info.binary && info.number != 58) {
      if (Known(info.number)) {
        Fail(r_.Field("number line", n.number),
             "dataset " + std::to_string(info.number) + " has no binary form (only 58 has: 58b)");
      }
      SkipBinary(n);
      info.skipped = true;
    } else {
      info.skipped = !Read(info.number, n, info.binary, open.number, &info.index);
    }
    file_->datasets.push_back(info);
  }

  // Reads a known dataset into its vector; false for a number this reader skips.
  bool Read(int number, const Line& n, bool binary, int line, int* index) {
    const auto add = [&](auto& v) -> auto& {
      *index = static_cast<int>(v.size());
      v.emplace_back();
      v.back().line = line;
      return v.back();
    };
    switch (number) {
      case 15: ReadNodes(r_, &add(file_->nodes)); return true;
      case 18: ReadCoordinateSystems(r_, &add(file_->coordinate_systems)); return true;
      case 55: ReadModalData(r_, &add(file_->modal_data)); return true;
      case 58: uff_internal::ReadFunction(r_, n, binary, &add(file_->functions)); return true;
      case 82: ReadTraceLine(r_, &add(file_->trace_lines)); return true;
      case 151: ReadHeader(r_, &add(file_->headers)); return true;
      case 164: ReadUnits(r_, &add(file_->units)); return true;
      default: break;
    }
    while (!r_.AtClose()) {
      const Line l = r_.NextLine();
      Reader::CheckText(l, r_.DatasetField() + " (skipped) line " + std::to_string(l.number));
    }
    r_.NextLine();
    return false;
  }

  // A binary dataset other than 58b: its header lines and bytes, unread.
  void SkipBinary(const Line& n) {
    const uff_internal::BinaryHeader h = uff_internal::ReadBinaryHeader(r_, n);
    for (int i = 0; i < h.ascii_lines; ++i) r_.Record("header line " + std::to_string(i + 1));
    if (static_cast<uint64_t>(h.bytes) > r_.Remaining()) {
      Fail(r_.Field("binary data", r_.LineNumber()),
           "truncated: the header gives " + std::to_string(h.bytes) + " bytes, the file has " +
               std::to_string(r_.Remaining()) + " left");
    }
    r_.SkipBytes(static_cast<size_t>(h.bytes));
    r_.CloseAfterBinary("binary data");
  }

  Reader r_;
  UffFile* file_;
};

}  // namespace

double UffUnits::ToSi(double value, int length_exp, int force_exp, int temperature_exp) const {
  return value / (std::pow(length_factor, length_exp) * std::pow(force_factor, force_exp) *
                  std::pow(temperature_factor, temperature_exp));
}
// The temperature offset: the definition gives no formula. Its example (BG,
// factor 1.8, offset +459.67) reads as K = (F + offset) / factor, while
// Simcenter Testlab writes factor 1, offset -273.15 for degrees C, which that
// formula turns into C - 273.15. Absolute temperatures are therefore left to
// the caller.

std::optional<double> UffModalData::FrequencyHz() const {
  if (IsNormalMode()) return frequency_hz;
  if (IsComplexMode()) return std::abs(eigenvalue.imag()) / (2 * M_PI);
  return std::nullopt;
}

std::optional<double> UffModalData::DampingRatio() const {
  if (IsNormalMode()) return viscous_damping_ratio;
  if (!IsComplexMode() || std::abs(eigenvalue) == 0) return std::nullopt;
  return -eigenvalue.real() / std::abs(eigenvalue);
}

bool ParseUff(const std::string& bytes, const std::string& path, UffFile* file,
              LoadError* error) {
  *file = UffFile{};
  file->path = path;
  error->file = path;
  error->field.clear();
  error->message.clear();
  try {
    FileParser(bytes, file).Run();
    return true;
  } catch (const Failure& f) {
    error->field = f.field;
    error->message = f.message;
  } catch (const std::bad_alloc&) {
    error->message = "out of memory";
  }
  return false;
}

bool LoadUff(const std::string& path, UffFile* file, LoadError* error) {
  error->file = path;
  error->field.clear();
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error->message = "cannot open file";
    return false;
  }
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) {
    error->message = "cannot read file";
    return false;
  }
  if (size > kMaxUffFileBytes) {
    error->message = "the file is " + std::to_string(size) + " bytes, more than the " +
                     std::to_string(kMaxUffFileBytes) + " (256 MiB) this reader reads";
    return false;
  }
  std::string bytes(static_cast<size_t>(size), '\0');
  in.seekg(0);
  in.read(bytes.data(), size);
  if (in.gcount() != size) {
    error->message = "cannot read file";
    return false;
  }
  return ParseUff(bytes, path, file, error);
}

}  // namespace ringid
