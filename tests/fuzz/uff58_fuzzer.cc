// Arbitrary bytes -> the UFF 58 import (datasets/uff_frf.h) under a map that
// places nodes 1-3 (the first byte picks one of three: points given, points
// from dataset 15 in a z-up frame with coherence averages, the map's units),
// or a clean error (one line of printable ASCII). What imports is a format-3
// dataset the loader reads back, and writes back to the same text.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "datasets/dataset.h"
#include "datasets/uff.h"
#include "datasets/uff_dataset.h"
#include "datasets/uff_frf.h"

namespace {

void CleanError(const ringid::LoadError& e) {
  if (e.message.empty()) std::abort();
  for (const char c : e.field + e.message) {
    if (c < 32 || c > 126) std::abort();
  }
}

const char* const kMaps[] = {
    R"({"format": "ringid-uff-map/2", "name": "fuzz", "points": [
        {"node": 1, "on": "belt", "point_m": [0, 0, -0.3]},
        {"node": 2, "on": "belt", "point_m": [0.3, 0, 0]},
        {"node": 3, "on": "rim", "point_m": [0, 0, 0.2]}]})",
    R"({"format": "ringid-uff-map/2", "name": "fuzz", "axes": ["x", "-y", "-z"], "averages": 10,
        "points": [{"node": 1, "on": "belt"}, {"node": 2, "on": "belt"}, {"node": 3, "on": "belt"}]})",
    R"({"format": "ringid-uff-map/2", "name": "fuzz", "units": {"response": "g", "reference": "N"},
        "averages": 3, "points": [{"node": 1, "on": "belt", "point_m": [0, 0, -0.3]},
        {"node": 2, "on": "rim"}, {"node": 3, "on": "belt", "point_m": [0, 0.1, 0.3]}]})"};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  ringid::UffFile file;
  ringid::LoadError e;
  if (!ringid::ParseUff(bytes, "fuzz.uff", &file, &e)) return 0;  // uff_fuzzer's part
  ringid::UffMap map;
  if (!ringid::ParseUffMap(kMaps[size ? data[0] % 3 : 0], "map.json", &map, &e)) std::abort();
  ringid::UffImport in;
  if (!ringid::AddUffFrfs(file, map, &in, &e)) {
    CleanError(e);
    return 0;
  }
  if (in.dataset.format != 3 || in.dataset.conditions.empty()) std::abort();
  const std::string text = ringid::DatasetToJson(in.dataset);
  ringid::Dataset back;
  if (!ringid::ParseDataset(text, "fuzz.json", &back, &e)) std::abort();  // the import wrote what the loader refuses
  if (ringid::DatasetToJson(back) != text) std::abort();
  return 0;
}
