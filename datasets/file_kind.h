// What kind of input a file is: the one place that tells a directory, a .tir,
// a UFF file and each JSON file of ringid apart (their "format", an identify
// report's "report"), so that a file given where another kind belongs is
// named as what it is, with where it belongs, by every loader.
#ifndef RINGID_DATASETS_FILE_KIND_H_
#define RINGID_DATASETS_FILE_KIND_H_

#include <string>

namespace ringid {

enum class FileKind {
  kUnknown,  // none of the below (JSON of no known format, or not JSON)
  kDirectory,
  kTir,   // by its extension, case aside
  kUff,   // by its first line, "    -1" (datasets/uff.h)
  kModalDataset,
  kParameterSet,  // marked, or a "parameters" object without modes, conditions or report
  kTruth,
  kResponseDataset,
  kLugForces,
  kUffMap,
  kFrfSpec,
  kObstacleSpec,
  kLugProfile,
  kReport,  // any ringid report ("report": KIND)
};

struct SniffedFile {
  FileKind kind = FileKind::kUnknown;
  std::string detail;  // the format written, or the report's kind
  std::string field;   // the key that tells: "format", "report", "parameters"; "" by name or text
};

// By the path alone: a directory, a .tir.
SniffedFile SniffPath(const std::string& path);
// By the path, then by the text's first two lines (UFF: "-1", then a
// dataset number); JSON text is Unknown here: its kind is SniffJson's.
SniffedFile SniffFile(const std::string& path, const std::string& text);
// A parsed JSON file (nlohmann::json or ordered_json) by its "format" (a
// format of ringid; any other is Unknown), else a "report" string, else a
// bare "parameters" object.
template <class J>
SniffedFile SniffJson(const J& j);
// The kind a "format" value names; Unknown for none of ringid's.
FileKind FormatKind(const std::string& format);

// "a parameter set (ringid-parameters/1)".
std::string KindName(const SniffedFile& kind);
// "this is a parameter set (ringid-parameters/1), not a dataset; use
// --parameters": `found` named, then `expected` ("a dataset"), then where
// `found` belongs, where ringid reads it.
std::string NotTheKind(const SniffedFile& found, const std::string& expected);

template <class J>
SniffedFile SniffJson(const J& j) {
  if (!j.is_object()) return {};
  if (j.contains("format")) {
    if (!j["format"].is_string()) return {};
    const std::string format = j["format"].template get<std::string>();
    return {FormatKind(format), format, "format"};
  }
  if (j.contains("report") && j["report"].is_string()) {
    return {FileKind::kReport, j["report"].template get<std::string>(), "report"};
  }
  if (j.contains("parameters") && !j.contains("modes") && !j.contains("conditions") &&
      !j.contains("report")) {
    return {FileKind::kParameterSet, "", "parameters"};
  }
  return {};
}

}  // namespace ringid

#endif  // RINGID_DATASETS_FILE_KIND_H_
