// The registry of measured quantities (datasets/measurement.h).
#include "datasets/measurement.h"

namespace ringid {

// Each defined in its own file.
const Measurement& FrequencyMeasurement();
const Measurement& DampingMeasurement();
const Measurement& ShapeMeasurement();

const std::vector<const Measurement*>& Measurements() {
  static const std::vector<const Measurement*> all = {
      &FrequencyMeasurement(), &DampingMeasurement(), &ShapeMeasurement()};
  return all;
}

const Measurement& MeasurementOf(Quantity q) {
  for (const Measurement* unit : Measurements()) {
    if (unit->quantity() == q) return *unit;
  }
  return *Measurements().front();  // every Quantity is registered
}

}  // namespace ringid
