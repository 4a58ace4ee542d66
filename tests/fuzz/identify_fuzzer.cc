// A valid dataset with extreme values and degenerate setups (everything tied
// or known, nothing free, one mode, everything free, any method) -> an
// identification result that says what went wrong, never an abort.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "estimation/identify.h"

namespace {

struct Reader {
  const uint8_t* data;
  size_t size;
  uint8_t Byte() {
    if (size == 0) return 0;
    --size;
    return *data++;
  }
  double Double() {
    double v = 0;
    if (size >= sizeof v) {
      std::memcpy(&v, data, sizeof v);
      data += sizeof v;
      size -= sizeof v;
    }
    return v;
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace ringid;
  Reader in{data, size};
  Dataset d;
  d.name = "fuzz";
  // The paper's identified set as the starting values.
  const double base[] = {2.3724, 0.0199, 0.024194, 0.0069935, 0.015091, 106680,
                         1380, 1380, 18.5, 384000, 384000, 7670, 10300, 0.0673,
                         0.319, 304000, 1210, 6.06, 6.06, 281000, 1410, 1410,
                         637, 0.00117, 0.00258, 0.00135};
  for (int i = 0; i < 26; ++i) {
    const Param p = ParamAt(i);
    const uint8_t how = in.Byte();
    // Extreme but loader-valid values: positive and finite.
    double v = base[i];
    if (how & 0x10) v *= std::pow(10.0, static_cast<int8_t>(in.Byte()) % 300);
    if (!(v > 0) || !std::isfinite(v)) v = base[i];
    if ((how & 3) == 0) d.known[p] = v;
    else if ((how & 3) == 1) d.initial[p] = v;
    else if ((how & 3) == 2 && i > 0) {
      const Param to = ParamAt(in.Byte() % 26);
      if (to != p && !d.ties.count(to) && !d.known.count(p) && !d.initial.count(p)) {
        bool target_of_other = false;
        for (const auto& [a, b] : d.ties) target_of_other |= (b == p);
        if (!target_of_other) d.ties[p] = to;
        else d.initial[p] = v;
      } else {
        d.initial[p] = v;
      }
    } else {
      d.initial[p] = v;
    }
  }
  const int modes = 1 + in.Byte() % 7;
  for (int k = 0; k < modes; ++k) {
    MeasuredMode m;
    m.label = static_cast<ModeLabel>(k);
    const double f = std::abs(in.Double());
    m.frequency_hz = (f > 0 && std::isfinite(f)) ? f : 50.0;
    if (in.Byte() & 1) m.frequency_sigma_hz = 0.1;
    if (in.Byte() & 1) {
      m.damping_ratio = 0.01 + (in.Byte() % 98) / 100.0;
      m.damping_sigma = 0.02;
    }
    if (in.Byte() & 1) {
      m.shape.emplace_back(Dof::kXb, in.Byte() / 255.0 + 1e-3);
      m.shape.emplace_back(Dof::kYb, (in.Byte() - 128) / 128.0);
      m.shape_sigma = 0.05;
    }
    d.modes.push_back(m);
  }
  IdentifyOptions o;
  // Few iterations: the fuzzer is after the paths, not the optimum.
  o.starts = 1 + in.Byte() % 2;
  o.max_iterations = 2;
  o.simplex.max_evaluations = 30;
  o.method = (in.Byte() & 1) ? Method::kSimplex : Method::kLevenbergMarquardt;
  IdentifyResult s;
  Identify(RigidRingModel(), d, o, &s);
  if (!s.status.ok() && s.status.message.empty()) std::abort();
  if (s.status.ok() && !std::isfinite(s.cost)) std::abort();
  if (s.uncertainty.covariance_ok && !s.uncertainty.covariance.allFinite()) std::abort();
  return 0;
}
