// Arbitrary bytes -> a format-3 dataset (contract §10: modes, frf, static and
// obstacle per condition) or a clean one-line error. One that loads writes back to
// bytes that read back and write again the same, and its residuals at the
// start evaluate or fail cleanly (the static solve included).
#include <cstdint>
#include <cstdlib>
#include <string>

#include "datasets/dataset.h"
#include "estimation/problem.h"
#include "model/rigid_ring_model.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace ringid;
  const std::string text(reinterpret_cast<const char*>(data), size);
  Dataset d, again;
  LoadError e;
  if (!ParseDataset(text, "fuzz.json", &d, &e)) {
    if (e.message.empty() || e.OneLine().find('\n') != std::string::npos) std::abort();
    return 0;
  }
  const std::string once = DatasetToJson(d);
  if (!ParseDataset(once, "again.json", &again, &e)) std::abort();
  if (DatasetToJson(again) != once || again.statics.size() != d.statics.size() ||
      again.modes.size() != d.modes.size() || again.conditions.size() != d.conditions.size()) {
    std::abort();
  }
  for (size_t c = 0; c < d.conditions.size(); ++c) {
    if (again.conditions[c].frf.has_value() != d.conditions[c].frf.has_value()) std::abort();
    if (again.conditions[c].obstacle.has_value() != d.conditions[c].obstacle.has_value()) {
      std::abort();
    }
  }
  Status status;
  const RigidRingModel model;
  const auto problem = Problem::Create(model, d, ResidualOptions(), &status);
  if (!problem) {
    if (status.message.empty()) std::abort();
    return 0;
  }
  Eigen::VectorXd r;
  Eigen::MatrixXd jacobian;
  // May fail (no mode there, a singular static solve), never abort.
  problem->Evaluate(problem->start(), &r, &jacobian);
  return 0;
}
