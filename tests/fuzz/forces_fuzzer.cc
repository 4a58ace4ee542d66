// Arbitrary bytes -> a response dataset (contract §8) or a clean error. One
// that loads writes, reads and writes the same bytes, and its forces are
// estimated with the example car tire without a crash, whatever the status.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "datasets/response_dataset.h"
#include "datasets/synthetic.h"
#include "estimation/forces.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  ringid::ResponseDataset d, again;
  ringid::LoadError e;
  if (!ringid::ParseResponseDataset(text, "fuzz.json", &d, &e)) {
    if (e.message.empty() || e.OneLine().find('\n') != std::string::npos) std::abort();
    return 0;
  }
  const std::string written = ringid::ResponseDatasetToJson(d);
  if (!ringid::ParseResponseDataset(written, "again.json", &again, &e)) std::abort();
  if (ringid::ResponseDatasetToJson(again) != written) std::abort();
  ringid::ForceParameters p;
  p.shared = ringid::ExampleCarTire();
  ringid::ForcesResult r;
  ringid::EstimateForces(ringid::RigidRingModel(), p, d, ringid::ForcesOptions{}, &r);
  return 0;
}
