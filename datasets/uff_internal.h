// Internal to the UFF reader (datasets/uff.cc, datasets/uff_function.cc): a
// cursor over the file's bytes that reads lines, fixed-width Fortran fields
// and binary blocks, and names the dataset and record of every failure.
#ifndef RINGID_DATASETS_UFF_INTERNAL_H_
#define RINGID_DATASETS_UFF_INTERNAL_H_

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "datasets/load_failure.h"
#include "datasets/uff.h"

namespace ringid::uff_internal {

// Thrown inside the reader only, caught in ParseUff.
using internal::Fail;
using internal::Failure;

using internal::Quoted;
std::string_view Trim(std::string_view s);
// An I6 field "-1" in columns 1-6 and nothing else: a dataset's delimiter.
bool IsDelimiter(std::string_view line);

struct Line {
  std::string_view text;  // without its line ending
  int number = 0;         // 1-based
};

class Reader {
 public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}

  bool AtEnd() const { return pos_ >= bytes_.size(); }
  size_t Remaining() const { return bytes_.size() - pos_; }
  size_t Offset() const { return pos_; }
  int LineNumber() const { return line_; }
  const std::string& Bytes() const { return bytes_; }
  Line NextLine();  // AtEnd() must be false
  Line PeekLine() const;
  // Steps over `n` bytes of binary data (n <= Remaining()), counting the line
  // feeds among them so that later line numbers stay those of an editor.
  void SkipBytes(size_t n);
  // Refuses a control character in `line` (other than a tab).
  static void CheckText(const Line& line, const std::string& field);

  // The dataset being read, for messages: "dataset 58b #2 (line 14)".
  void BeginDataset(const std::string& number, int ordinal, int line);
  const std::string& DatasetField() const { return dataset_; }
  // "dataset 58b #2 (line 14) record 7 (line 22)".
  std::string Field(const std::string& record, int line) const;

  // The next line, as `record` of the dataset: refused at the end of the file
  // or at the dataset's closing line.
  Line Record(const std::string& record);
  // Whether the next line closes the dataset (refused at the end of the file).
  bool AtClose() const;
  // Consumes the closing line, refusing anything else after `last_record`.
  void Close(const std::string& last_record);
  // The same right after a binary block: "    -1" directly or after one line
  // ending.
  void CloseAfterBinary(const std::string& last_record);

  // Fixed-width fields: columns [begin, begin + width) of the line (a short
  // line is padded with blanks, as Fortran reads it). `what` names the field
  // in messages: "field 2 (number of points)".
  static std::string Text(const Line& l, size_t begin, size_t width);
  std::optional<int64_t> OptionalInt(const Line& l, const std::string& record, size_t begin,
                                     size_t width, const std::string& what) const;
  int64_t Int64(const Line& l, const std::string& record, size_t begin, size_t width,
                const std::string& what) const;
  int Int(const Line& l, const std::string& record, size_t begin, size_t width,
          const std::string& what) const;
  double Real(const Line& l, const std::string& record, size_t begin, size_t width,
              const std::string& what) const;
  // Refuses anything but blanks from column `end` on.
  void NothingAfter(const Line& l, const std::string& record, size_t end) const;
  // `count` numbers written as a Fortran format repeats: each line holds the
  // fields of `widths` in turn, the last line as many as remain.
  std::vector<double> Reals(const std::string& record, size_t count,
                            const std::vector<size_t>& widths);

 private:
  const std::string& bytes_;
  size_t pos_ = 0;
  int line_ = 1;
  std::string dataset_;
};

// Refuses `value` of `what` outside [lo, hi].
void CheckRange(const Reader& r, const std::string& record, const Line& l,
                const std::string& what, int64_t value, int64_t lo, int64_t hi);

// Dataset 58 or 58b; `number_line` is the line holding "    58" or "    58b...".
void ReadFunction(Reader& r, const Line& number_line, bool binary, UffFunction* f);

// The binary header of a "NNNNNNb" number line (58b's, and by its definition
// any later binary dataset's): Format (I6,1A1,I6,I6,I12,I12,I6,I6,I12,I12).
struct BinaryHeader {
  int byte_order = 0, float_format = 0, ascii_lines = 0;
  int64_t bytes = 0;
};
BinaryHeader ReadBinaryHeader(const Reader& r, const Line& number_line);

}  // namespace ringid::uff_internal

#endif  // RINGID_DATASETS_UFF_INTERNAL_H_
