// Reading a JSON input file of ringid through its field list (model/archive.h):
// the text parsed strictly, a file of another kind named as what it is, then
// the typed fields; what the type cannot say is the caller's check.
// Internal to datasets/ (response_dataset.cc, frf_spec.cc).
#ifndef RINGID_DATASETS_TYPED_FILE_H_
#define RINGID_DATASETS_TYPED_FILE_H_

#include <string>

#include "datasets/dataset.h"
#include "datasets/file_kind.h"
#include "model/archive.h"

namespace ringid::internal {

// Reads `text` as the typed file Fields of `format`, then `check` says what
// the type cannot. False with `error` (file `path`, field, message).
template <class Fields, class Check>
bool ReadTyped(const std::string& text, const std::string& path, const char* format,
               LoadError* error, Check check) {
  error->file = path;
  Json j;
  if (!ParseJsonInput(text, &j, error)) return false;
  if (j.is_object() && j.contains("format") && j["format"] != format) {
    const SniffedFile found = SniffJson(j);
    error->field = "format";
    error->message = found.kind == FileKind::kUnknown
                         ? std::string("must be \"") + format + "\""
                         : NotTheKind(found, KindName({FormatKind(format), format, ""}));
    return false;
  }
  Fields fields;
  std::string why;
  if (!JsonReader::FromJson(j, "", &fields, &why)) {
    SetArchiveError(why, error);
    return false;
  }
  return check(fields);
}

}  // namespace ringid::internal

#endif  // RINGID_DATASETS_TYPED_FILE_H_
