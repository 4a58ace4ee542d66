// What the FRF kind (datasets/measurement_frf.cc) compares, line by line, for
// the reports: each measured function beside the model's over the band.
#ifndef RINGID_DATASETS_MEASUREMENT_FRF_H_
#define RINGID_DATASETS_MEASUREMENT_FRF_H_

#include <complex>
#include <vector>

#include "datasets/dataset.h"
#include "datasets/measurement.h"
#include "datasets/measurement_options.h"

namespace ringid {

// One function of a condition's frf block over the lines in the band.
struct FrfLines {
  int function = 0;  // index into Frf::functions
  std::vector<double> frequency_hz;
  std::vector<std::complex<double>> measured, model;
  std::vector<double> sigma;
};

// Condition c's functions (c holds an frf block) against the model at `at`
// over the band of `o`: the FRF kind's rows are the real and imaginary parts
// of (model - measured) / sigma of these. False where the model gives no
// response (a singular line, a coordinate it lacks).
bool CompareFrfs(const Dataset& d, int c, const ModelAt& at, const MeasurementOptions& o,
                 std::vector<FrfLines>* functions);

}  // namespace ringid

#endif  // RINGID_DATASETS_MEASUREMENT_FRF_H_
