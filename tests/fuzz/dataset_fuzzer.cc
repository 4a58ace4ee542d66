// Arbitrary bytes -> a dataset or a clean error. A dataset that loads must
// survive a round trip through DatasetToJson unchanged in meaning.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "datasets/dataset.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  ringid::Dataset d, again;
  ringid::LoadError e;
  if (!ringid::ParseDataset(text, "fuzz.json", &d, &e)) {
    if (e.message.empty() || e.OneLine().find('\n') != std::string::npos) std::abort();
    return 0;
  }
  if (!ringid::ParseDataset(ringid::DatasetToJson(d), "again.json", &again, &e)) std::abort();
  if (again.modes.size() != d.modes.size() || again.ties != d.ties ||
      again.known != d.known || again.initial != d.initial) {
    std::abort();
  }
  return 0;
}
