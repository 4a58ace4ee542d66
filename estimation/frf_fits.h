// Each measured frequency response function against the fitted model's
// (issue 36): its chi-square, its FRAC and the curves a page draws.
#ifndef RINGID_ESTIMATION_FRF_FITS_H_
#define RINGID_ESTIMATION_FRF_FITS_H_

#include <complex>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "datasets/measurement_options.h"
#include "model/parameters.h"
#include "model/rigid_ring_model.h"

namespace ringid {

// The frequency response assurance criterion of Heylen & Lammens ("FRAC: a
// consistent way of comparing frequency response functions", Identification
// in Engineering Systems, Swansea 1996) of two functions over the same
// lines: |sum a* b|^2 / (sum |a|^2 sum |b|^2), 0 to 1. Symmetric, and blind
// to a complex factor (b = 2a or b = i a give 1): the shape of the function
// over frequency, not its scale, which chi-square sees. NaN where either is
// zero at every line (standing, the model's function from one plane to the
// other).
double Frac(const std::vector<std::complex<double>>& a, const std::vector<std::complex<double>>& b);

// One measured function against the fitted model over the lines fitted.
struct FrfFit {
  std::optional<std::string> condition;  // where the dataset names conditions
  std::string output, input;             // the frf block's names
  // Its share of the fit's chi-square: sum over its lines of the squared real
  // and imaginary parts of (model - measured) / sigma.
  double chi2 = 0;
  double frac = 0;  // Frac(measured, model); null where the model's is zero
  // The lines fitted (those in the band) and, at each, the measured value,
  // the model's and sigma (of the real and of the imaginary part each).
  std::vector<double> frequency_hz;
  std::vector<double> measured_re, measured_im, model_re, model_im, sigma;

  int lines() const { return static_cast<int>(frequency_hz.size()); }
  int values() const { return 2 * lines(); }  // chi2's terms: re and im per line

  template <class Archive>
  void Serialize(Archive* a) {
    a->VisitIfSet("condition", &condition);
    a->Visit("output", &output);
    a->Visit("input", &input);
    a->Visit("chi2", &chi2);
    a->Visit("frac", &frac);
    a->Visit("frequency_hz", &frequency_hz);
    a->Visit("measured_re", &measured_re);
    a->Visit("measured_im", &measured_im);
    a->Visit("model_re", &model_re);
    a->Visit("model_im", &model_im);
    a->Visit("sigma", &sigma);
    a->Derived("lines", lines());  // after the curves they count, which a reader checks
    a->Derived("values", values());
  }
};

// Every measured function of `dataset`, condition by condition, against the
// model at each condition's parameters (`parameters(c)`) over the band of
// `o`; empty where the dataset has no FRF. A condition whose model gives no
// response (a singular line) is left out.
std::vector<FrfFit> FrfFits(const ModalModel& model, const Dataset& dataset,
                            const std::function<Parameters(int)>& parameters,
                            const MeasurementOptions& o);

}  // namespace ringid

#endif  // RINGID_ESTIMATION_FRF_FITS_H_
