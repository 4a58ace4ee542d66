// Dataset 58 (function at nodal DOF) and its binary form 58b (UC-SDRL,
// adopted by SDRC): records 1-11 are ASCII in both; record 12, the data, is
// ASCII in 58 and IEEE 754 values in the header's byte order in 58b.
#include <cmath>
#include <cstring>

#include "datasets/uff_internal.h"

namespace ringid::uff_internal {
namespace {

// Record 6: FORMAT(2(I5,I10),2(1X,10A1,I10,I4)).
void ReadDof(Reader& r, UffFunction* f) {
  const std::string rec = "record 6";
  const Line l = r.Record(rec);
  f->function_type = r.Int(l, rec, 0, 5, "field 1 (function type)");
  f->function_id = r.Int(l, rec, 5, 10, "field 2 (function identification number)");
  f->version = r.Int(l, rec, 15, 5, "field 3 (version number)");
  f->load_case = r.Int(l, rec, 20, 10, "field 4 (load case)");
  f->response_entity = Reader::Text(l, 31, 10);
  f->response_node = r.Int(l, rec, 41, 10, "field 6 (response node)");
  f->response_direction = r.Int(l, rec, 51, 4, "field 7 (response direction)");
  f->reference_entity = Reader::Text(l, 56, 10);
  f->reference_node = r.Int(l, rec, 66, 10, "field 9 (reference node)");
  f->reference_direction = r.Int(l, rec, 76, 4, "field 10 (reference direction)");
  r.NothingAfter(l, rec, 80);
  CheckRange(r, rec, l, "field 1 (function type)", f->function_type, 0, 27);
  CheckRange(r, rec, l, "field 7 (response direction)", f->response_direction, -6, 6);
  CheckRange(r, rec, l, "field 10 (reference direction)", f->reference_direction, -6, 6);
}

// Record 7: FORMAT(3I10,3E13.5). Returns its line.
int ReadDataForm(Reader& r, UffFunction* f) {
  const std::string rec = "record 7";
  const Line l = r.Record(rec);
  f->ordinate_type = r.Int(l, rec, 0, 10, "field 1 (ordinate data type)");
  f->points = r.Int64(l, rec, 10, 10, "field 2 (number of points)");
  const int spacing = r.Int(l, rec, 20, 10, "field 3 (abscissa spacing)");
  f->abscissa_min = r.Real(l, rec, 30, 13, "field 4 (abscissa minimum)");
  f->abscissa_increment = r.Real(l, rec, 43, 13, "field 5 (abscissa increment)");
  f->z_axis_value = r.Real(l, rec, 56, 13, "field 6 (z-axis value)");
  r.NothingAfter(l, rec, 69);
  const int t = f->ordinate_type;
  if (t != 2 && t != 4 && t != 5 && t != 6) {
    Fail(r.Field(rec, l.number), "field 1 (ordinate data type) must be 2, 4, 5 or 6, not " +
                                     std::to_string(t));
  }
  CheckRange(r, rec, l, "field 2 (number of points)", f->points, 1, 9999999999);
  CheckRange(r, rec, l, "field 3 (abscissa spacing)", spacing, 0, 1);
  f->even = spacing == 1;
  if (f->even && !(f->abscissa_increment > 0)) {
    Fail(r.Field(rec, l.number), "field 5 (abscissa increment) must be positive for even spacing");
  }
  const double last = f->abscissa_min + static_cast<double>(f->points - 1) * f->abscissa_increment;
  if (f->even && !std::isfinite(last)) {
    Fail(r.Field(rec, l.number), "the abscissa overflows: minimum + (points - 1) * increment");
  }
  return l.number;
}

// Records 8-11: FORMAT(I10,3I5,2(1X,20A1)).
void ReadAxis(Reader& r, const std::string& rec, UffAxis* a) {
  const Line l = r.Record(rec);
  a->specific_data_type = r.Int(l, rec, 0, 10, "field 1 (specific data type)");
  a->length_exponent = r.Int(l, rec, 10, 5, "field 2 (length units exponent)");
  a->force_exponent = r.Int(l, rec, 15, 5, "field 3 (force units exponent)");
  a->temperature_exponent = r.Int(l, rec, 20, 5, "field 4 (temperature units exponent)");
  a->label = Reader::Text(l, 26, 20);
  a->units_label = Reader::Text(l, 47, 20);
  r.NothingAfter(l, rec, 67);
}

// Values a point takes in record 12: abscissa (uneven only), then the real
// part and, complex, the imaginary part.
int ValuesPerPoint(const UffFunction& f) { return (f.even ? 0 : 1) + (f.IsComplex() ? 2 : 1); }

// The ASCII layout of record 12 (58, Addendum B): the fields of one line.
std::vector<size_t> AsciiWidths(const UffFunction& f) {
  if (!f.IsDouble()) return {13, 13, 13, 13, 13, 13};  // 6E13.5
  if (f.even) return {20, 20, 20, 20};                  // 4E20.12
  if (!f.IsComplex()) return {13, 20, 13, 20};          // 2(E13.5,E20.12)
  return {13, 20, 20};                                  // E13.5,2E20.12
}

std::string Kind(const UffFunction& f) {
  return std::string(f.IsComplex() ? "complex" : "real") + (f.IsDouble() ? " double" : " single") +
         (f.even ? "" : " uneven");
}

// One IEEE 754 value of `size` bytes at `p`, in the byte order given.
double Decode(const unsigned char* p, size_t size, bool big_endian) {
  uint64_t u = 0;
  for (size_t i = 0; i < size; ++i) u = (u << 8) | p[big_endian ? i : size - 1 - i];
  if (size == 4) {
    const uint32_t w = static_cast<uint32_t>(u);
    float v;
    std::memcpy(&v, &w, 4);
    return v;
  }
  double v;
  std::memcpy(&v, &u, 8);
  return v;
}

// Record 12 of 58b: exactly the header's byte count, every value of the
// ordinate's precision (the abscissa of uneven spacing too, as pyuff writes
// and reads it).
std::vector<double> ReadBinaryValues(Reader& r, const Line& number_line, const UffFunction& f) {
  const size_t size = f.IsDouble() ? 8 : 4;
  const int64_t count = f.points * ValuesPerPoint(f);
  const int64_t need = count * static_cast<int64_t>(size);
  if (f.data_bytes != need) {
    Fail(r.Field("number line", number_line.number),
         "field 6 (number of bytes) is " + std::to_string(f.data_bytes) + ", but " +
             std::to_string(f.points) + " points of " + Kind(f) + " data take " +
             std::to_string(need) + " bytes");
  }
  const std::string rec = "record 12";
  if (static_cast<uint64_t>(need) > r.Remaining()) {
    Fail(r.Field(rec, r.LineNumber()), "truncated: " + std::to_string(need) +
                                           " bytes of binary data announced, the file has " +
                                           std::to_string(r.Remaining()) + " left");
  }
  const int line = r.LineNumber();
  const auto* p = reinterpret_cast<const unsigned char*>(r.Bytes().data() + r.Offset());
  std::vector<double> v(static_cast<size_t>(count));
  for (size_t i = 0; i < v.size(); ++i) {
    v[i] = Decode(p + i * size, size, f.byte_order == 2);
    if (!std::isfinite(v[i])) {
      Fail(r.Field(rec, line), "value " + std::to_string(i + 1) + " (byte " +
                                   std::to_string(i * size) + " of the data) is not finite");
    }
  }
  r.SkipBytes(static_cast<size_t>(need));
  return v;
}

// Record 12 of 58.
std::vector<double> ReadAsciiValues(Reader& r, const UffFunction& f, int record7_line) {
  const std::vector<size_t> widths = AsciiWidths(f);
  const uint64_t count = static_cast<uint64_t>(f.points) * ValuesPerPoint(f);
  const uint64_t need = count * 13;  // the narrowest field
  if (need > r.Remaining()) {
    Fail(r.Field("record 7", record7_line),
         std::to_string(f.points) + " points of " + Kind(f) + " data need at least " +
             std::to_string(need) + " bytes; the file has " + std::to_string(r.Remaining()) +
             " left");
  }
  return r.Reals("record 12", static_cast<size_t>(count), widths);
}

// The flat values of record 12 as abscissa and ordinate.
void Assemble(const std::vector<double>& v, UffFunction* f) {
  const size_t n = static_cast<size_t>(f->points);
  const size_t per_point = static_cast<size_t>(ValuesPerPoint(*f));
  f->x.resize(n);
  f->y.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const double* p = &v[i * per_point];
    f->x[i] = f->even ? f->abscissa_min + static_cast<double>(i) * f->abscissa_increment : *p++;
    f->y[i] = {p[0], f->IsComplex() ? p[1] : 0.0};
  }
}

}  // namespace

void ReadFunction(Reader& r, const Line& number_line, bool binary, UffFunction* f) {
  f->binary = binary;
  if (binary) {
    const std::string rec = "number line";
    const BinaryHeader h = ReadBinaryHeader(r, number_line);
    CheckRange(r, rec, number_line, "field 3 (byte ordering)", h.byte_order, 1, 2);
    if (h.float_format != 2) {
      Fail(r.Field(rec, number_line.number),
           "field 4 (floating-point format) is " + std::to_string(h.float_format) +
               "; only 2 (IEEE 754) is read, not 1 (DEC VMS) or 3 (IBM 370)");
    }
    CheckRange(r, rec, number_line, "field 5 (number of ASCII lines)", h.ascii_lines, 11, 11);
    f->byte_order = h.byte_order;
    f->float_format = h.float_format;
    f->ascii_lines = h.ascii_lines;
    f->data_bytes = h.bytes;
  }
  for (int i = 0; i < 5; ++i) {
    f->id[i] = Reader::Text(r.Record("record " + std::to_string(i + 1)), 0, std::string::npos);
  }
  ReadDof(r, f);
  const int record7_line = ReadDataForm(r, f);
  ReadAxis(r, "record 8", &f->abscissa);
  ReadAxis(r, "record 9", &f->ordinate);
  ReadAxis(r, "record 10", &f->denominator);
  ReadAxis(r, "record 11", &f->z_axis);
  const std::vector<double> v =
      binary ? ReadBinaryValues(r, number_line, *f) : ReadAsciiValues(r, *f, record7_line);
  Assemble(v, f);
  if (binary) {
    r.CloseAfterBinary("record 12");
  } else {
    r.Close("record 12");
  }
}

}  // namespace ringid::uff_internal
