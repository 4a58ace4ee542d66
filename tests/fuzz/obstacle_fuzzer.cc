// Arbitrary bytes -> an obstacle spec (ringid-obstacle-spec/1) or a lug
// profile (ringid-lug-profile/1), by the format the bytes give, or a clean
// one-line error. A spec that loads is simulated on the example car tire
// (where its runs are short: the fuzzer's time is for the reader), failing
// cleanly or giving finite channels with positive sigma; a lug profile gives
// its excitation at 10 m/s, or fails cleanly.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>

#include "datasets/obstacle.h"
#include "datasets/synthetic.h"
#include "model/lug_excitation.h"

namespace {

void CleanError(const ringid::LoadError& e) {
  if (e.message.empty() || e.OneLine().find('\n') != std::string::npos) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace ringid;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const RigidRingModel model;
  const Parameters car = ExampleCarTire();
  LoadError e;
  if (text.find(kLugProfileFormat) != std::string::npos) {
    ObstacleProfile lugs;
    if (!ParseLugProfile(text, "fuzz.json", &lugs, &e)) return CleanError(e), 0;
    if (lugs.pitch_m < 1e-3 || lugs.pitch_m > 10) return 0;  // a long series, not a reader's case
    LugExcitation x;
    std::string why;
    if (!LugExcitationOf(model, car, lugs, 10, 5, &x, &why)) {
      if (why.empty()) std::abort();
      return 0;
    }
    for (const LugOrderExcitation& k : x.orders) {
      for (const auto& f : k.force) {
        if (!std::isfinite(std::abs(f))) std::abort();
      }
    }
    return 0;
  }
  ObstacleSpec spec;
  if (!ParseObstacleSpec(text, "fuzz.json", &spec, &e)) return CleanError(e), 0;
  double travel = 0;
  for (double v : spec.speeds_m_s) travel += v * spec.samples / spec.sample_rate_hz;
  if (travel > 20 || spec.samples * spec.speeds_m_s.size() > 20000) return 0;
  std::mt19937_64 rng(1);
  std::vector<Condition> conditions;
  std::vector<std::string> warnings;
  if (!SimulateObstacles(model, car, spec, {}, &rng, &conditions, &warnings, &e)) {
    return CleanError(e), 0;
  }
  for (const Condition& c : conditions) {
    for (const ObstacleChannel& ch : c.obstacle->channels) {
      for (size_t k = 0; k < ch.values.size(); ++k) {
        if (!std::isfinite(ch.values[k]) || !(ch.sigma[k] > 0)) std::abort();
      }
    }
  }
  return 0;
}
