// Arbitrary bytes -> a .tir or a clean error (one line), read strictly and
// leniently; the contact values of a lenient read are positive finite numbers
// or a clean error, and every note is one line. A rigid-ring block
// that reads must write back, and the file written must read again with the
// same values for every key the reader uses (to rounding, where every value
// lies well inside double range).
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "datasets/tir.h"
#include "datasets/tir_contact.h"
#include "datasets/tir_parameters.h"

namespace {

void CleanError(const ringid::LoadError& e) {
  if (e.message.empty() || e.OneLine().find('\n') != std::string::npos) std::abort();
}

void OneLineEach(const std::vector<std::string>& notes) {
  for (const std::string& n : notes) {
    if (n.empty() || n.find('\n') != std::string::npos) std::abort();
  }
}

// Read as predict reads: leniently outside the sections used, with the
// contact values derived.
void Lenient(const std::string& text) {
  ringid::TirFile file;
  ringid::LoadError e;
  ringid::Parameters p;
  if (!ringid::ParseTir(text, "fuzz.tir", &file, &e, &ringid::TirSectionsRead()) ||
      !ringid::TirToParameters(file, &p, &e)) {
    CleanError(e);
    return;
  }
  OneLineEach(file.notes);
  ringid::TirContact c;
  if (!ringid::DeriveTirContact(file, p, {}, &c, &e)) {
    CleanError(e);
    return;
  }
  OneLineEach(c.notes);
  for (const ringid::TirDerived& d : c.derived) {
    if (!(d.value > 0) || !std::isfinite(d.value)) std::abort();
  }
}

bool Moderate(double v) { return std::abs(v) >= 1e-150 && std::abs(v) <= 1e150; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  Lenient(text);
  ringid::TirFile file;
  ringid::LoadError e;
  if (!ringid::ParseTir(text, "fuzz.tir", &file, &e)) {
    CleanError(e);
    return 0;
  }
  ringid::Parameters p;
  if (!ringid::TirToParameters(file, &p, &e)) {
    CleanError(e);
    return 0;
  }
  std::string written;
  if (!ringid::ParametersToTir(p, "fuzz", "fuzz.tir", &written, &e)) std::abort();
  ringid::TirFile again;
  ringid::Parameters q;
  if (!ringid::ParseTir(written, "again.tir", &again, &e) ||
      !ringid::TirToParameters(again, &q, &e)) {
    std::abort();
  }
  bool moderate = true;
  for (int i = 0; i < ringid::kNumParams; ++i) {
    if (p.IsSet(ringid::ParamAt(i)) && p[ringid::ParamAt(i)] != 0) {
      moderate &= Moderate(p[ringid::ParamAt(i)]);
    }
  }
  for (const ringid::TirField& f : ringid::TirFields()) {
    if (!f.read_into) continue;
    const ringid::TirEntry* before = file.Find(f.section, f.key);
    const ringid::TirEntry* after = again.Find(f.section, f.key);
    if (!before != !after) std::abort();  // a key read is written, and only those
    if (!before) continue;
    moderate &= Moderate(*before->number);
    if (moderate && std::abs(*after->number / *before->number - 1) > 1e-9) std::abort();
  }
  return 0;
}
