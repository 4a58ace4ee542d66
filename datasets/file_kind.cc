#include "datasets/file_kind.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>

#include "datasets/dataset.h"
#include "datasets/frf_spec.h"
#include "datasets/obstacle.h"
#include "datasets/parameter_files.h"
#include "datasets/response_dataset.h"
#include "datasets/uff_dataset.h"

namespace ringid {

SniffedFile SniffPath(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return {FileKind::kDirectory, "", ""};
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".tir") return {FileKind::kTir, "", ""};
  return {};
}

SniffedFile SniffFile(const std::string& path, const std::string& text) {
  const SniffedFile by_path = SniffPath(path);
  if (by_path.kind != FileKind::kUnknown) return by_path;
  // A UFF file opens with a line "    -1" (I6), after blank lines at most, and
  // a dataset number on the next ("    55", "    58b"; datasets/uff.h).
  std::istringstream lines(text.substr(0, 4096));  // the opening is enough
  std::string line, number;
  while (std::getline(lines, line) && line.find_first_not_of(" \t\r") == std::string::npos) {}
  std::istringstream opening(line);
  std::string minus_one, rest;
  if (!(opening >> minus_one) || minus_one != "-1" || (opening >> rest)) return {};
  if (!std::getline(lines, line)) return {};
  std::istringstream second(line);
  if (!(second >> number)) return {};  // 58b: its binary header follows on the line
  if (number.back() == 'b') number.pop_back();
  if (number.empty() || number.find_first_not_of("0123456789") != std::string::npos) return {};
  return {FileKind::kUff, "", ""};
}

FileKind FormatKind(const std::string& format) {
  static const std::pair<const char*, FileKind> kFormats[] = {
      {kDatasetFormat1, FileKind::kModalDataset},    {kDatasetFormat2, FileKind::kModalDataset},
      {kDatasetFormat3, FileKind::kModalDataset},
      {kParameterSetFormat, FileKind::kParameterSet}, {kTruthFormat, FileKind::kTruth},
      {kResponseFormat, FileKind::kResponseDataset},  {kLugForcesFormat, FileKind::kLugForces},
      {kUffMapFormat, FileKind::kUffMap},           {kUffMapFormat2, FileKind::kUffMap},
      {kFrfSpecFormat, FileKind::kFrfSpec},         {kObstacleSpecFormat, FileKind::kObstacleSpec},
      {kLugProfileFormat, FileKind::kLugProfile},
  };
  for (const auto& [name, kind] : kFormats) {
    if (format == name) return kind;
  }
  return FileKind::kUnknown;
}

namespace {

// What `found` is, in words, and where ringid reads it ("" where nowhere).
void Words(const SniffedFile& found, std::string* what_out, std::string* belongs_out) {
  const std::string format = found.detail.empty() ? "" : " (" + found.detail + ")";
  std::string& what = *what_out;
  std::string& belongs = *belongs_out;
  switch (found.kind) {
    case FileKind::kUnknown: what = "a file of no kind ringid reads"; break;
    case FileKind::kDirectory: what = "a directory"; break;
    case FileKind::kTir:
      what = "an MF-Swift tire property file (.tir)";
      belongs = "use --parameters (docs/tir.md)";
      break;
    case FileKind::kUff:
      what = "a UFF file";
      belongs = "import its modes or FRFs: ringid import --uff=FILE (docs/uff.md)";
      break;
    case FileKind::kModalDataset: what = "a modal dataset" + format; belongs = "use --dataset"; break;
    case FileKind::kParameterSet:  // a set may leave its format out
      what = std::string("a parameter set (") +
             (found.detail.empty() ? kParameterSetFormat : found.detail.c_str()) + ")";
      belongs = "use --parameters";
      break;
    case FileKind::kTruth: what = "a truth file" + format + " of simulate"; break;
    case FileKind::kResponseDataset:
      what = "a response dataset" + format;
      belongs = "ringid forces reads it";
      break;
    case FileKind::kLugForces:
      what = "a lug-force file" + format;
      belongs = "use simulate --lug_forces";
      break;
    case FileKind::kUffMap: what = "a UFF map" + format; belongs = "use import --map"; break;
    case FileKind::kFrfSpec:
      what = "an FRF test's layout" + format;
      belongs = "use simulate --frf";
      break;
    case FileKind::kObstacleSpec:
      what = "an obstacle test's layout" + format;
      belongs = "use simulate --obstacle";
      break;
    case FileKind::kLugProfile:
      what = "a lugged tread's profile" + format;
      belongs = "use predict --lug_profile";
      break;
    case FileKind::kReport: what = "a ringid " + found.detail + " report"; break;
  }
}

}  // namespace

std::string KindName(const SniffedFile& kind) {
  std::string what, belongs;
  Words(kind, &what, &belongs);
  return what;
}

std::string NotTheKind(const SniffedFile& found, const std::string& expected) {
  std::string what, belongs;
  Words(found, &what, &belongs);
  return "this is " + what + ", not " + expected + (belongs.empty() ? "" : "; " + belongs);
}

}  // namespace ringid
