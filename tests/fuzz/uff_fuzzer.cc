// Arbitrary bytes -> a universal file or a clean error (one line of printable
// ASCII). A file that reads is consistent: every dataset listed points at a
// record of its kind, every function has its points, every node its values,
// and no value is NaN or infinite.
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "datasets/uff.h"

namespace {

void CleanError(const ringid::LoadError& e) {
  if (e.message.empty()) std::abort();
  for (const char c : e.field + e.message) {
    if (c < 32 || c > 126) std::abort();
  }
}

void Finite(double v) {
  if (!std::isfinite(v)) std::abort();
}
void Finite(std::complex<double> v) {
  Finite(v.real());
  Finite(v.imag());
}

size_t Count(const ringid::UffFile& f, int number) {
  switch (number) {
    case 15: return f.nodes.size();
    case 18: return f.coordinate_systems.size();
    case 55: return f.modal_data.size();
    case 58: return f.functions.size();
    case 82: return f.trace_lines.size();
    case 151: return f.headers.size();
    case 164: return f.units.size();
    default: return 0;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  ringid::UffFile file;
  ringid::LoadError e;
  if (!ringid::ParseUff(bytes, "fuzz.uff", &file, &e)) {
    CleanError(e);
    return 0;
  }
  if (file.datasets.empty()) std::abort();
  size_t read = 0;
  for (const ringid::UffDatasetInfo& d : file.datasets) {
    if (d.skipped != (d.index < 0)) std::abort();
    if (d.skipped) continue;
    ++read;
    if (static_cast<size_t>(d.index) >= Count(file, d.number)) std::abort();
  }
  if (read != file.nodes.size() + file.coordinate_systems.size() + file.modal_data.size() +
                  file.functions.size() + file.trace_lines.size() + file.headers.size() +
                  file.units.size()) {
    std::abort();
  }
  for (const ringid::UffFunction& f : file.functions) {
    if (f.points < 1 || f.x.size() != static_cast<size_t>(f.points) || f.y.size() != f.x.size()) {
      std::abort();
    }
    for (size_t i = 0; i < f.x.size(); ++i) {
      Finite(f.x[i]);
      Finite(f.y[i]);
      if (!f.IsComplex() && f.y[i].imag() != 0) std::abort();
    }
  }
  for (const ringid::UffModalData& m : file.modal_data) {
    for (const ringid::UffNodeValues& n : m.nodes) {
      if (n.values.size() != static_cast<size_t>(m.values_per_node)) std::abort();
      for (const std::complex<double> v : n.values) Finite(v);
    }
    if (m.FrequencyHz()) Finite(*m.FrequencyHz());
    if (m.DampingRatio()) Finite(*m.DampingRatio());
  }
  for (const ringid::UffUnits& u : file.units) {
    if (!(u.length_factor > 0 && u.force_factor > 0 && u.temperature_factor > 0)) std::abort();
  }
  for (const ringid::UffTraceLine& t : file.trace_lines) {
    if (t.nodes.empty()) std::abort();
  }
  return 0;
}
