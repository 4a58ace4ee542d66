// Arbitrary parameter vectors (zeros, negatives, 1e+-300, NaN, Inf) and any
// set of effects -> labelled modes or a clean error. Never a non-finite
// frequency reported as a result, never a label twice or on no mode.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <set>
#include <vector>

#include "model/effects.h"
#include "model/rigid_ring_model.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace ringid;
  if (size < 1) return 0;
  std::vector<const Effect*> effects;
  const auto& all = EffectCatalogue();
  for (size_t i = 0; i < all.size(); ++i) {
    if (data[0] & (1u << i)) effects.push_back(all[i]);
  }
  ++data;
  --size;
  Parameters p;
  for (int i = 0; i < kNumParams && size >= sizeof(double); ++i) {
    double v;
    std::memcpy(&v, data, sizeof v);
    p[ParamAt(i)] = v;
    data += sizeof v;
    size -= sizeof v;
  }
  const ModalSolution s = RigidRingModel(effects).Solve(p);
  if (!s.ok) {
    if (s.error.empty() || !s.modes.empty()) std::abort();
    return 0;
  }
  std::set<ModeLabel> seen;
  for (const Mode& m : s.modes) {
    if (!std::isfinite(m.frequency_hz) || !(m.frequency_hz > 0) ||
        !std::isfinite(m.damping_ratio) || !m.shape.allFinite()) {
      std::abort();
    }
    if (!seen.insert(m.label).second) std::abort();
  }
  for (ModeLabel l : s.vanished) {
    if (!seen.insert(l).second) std::abort();
  }
  return 0;
}
