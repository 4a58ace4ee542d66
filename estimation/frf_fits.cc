#include "estimation/frf_fits.h"

#include <cmath>
#include <limits>

#include "datasets/measurement.h"
#include "datasets/measurement_frf.h"

namespace ringid {

double Frac(const std::vector<std::complex<double>>& a,
            const std::vector<std::complex<double>>& b) {
  std::complex<double> cross = 0;
  double aa = 0, bb = 0;
  for (size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
    cross += std::conj(a[k]) * b[k];
    aa += std::norm(a[k]);
    bb += std::norm(b[k]);
  }
  if (!(aa > 0 && bb > 0)) return std::numeric_limits<double>::quiet_NaN();
  return std::norm(cross) / (aa * bb);
}

std::vector<FrfFit> FrfFits(const ModalModel& model, const Dataset& dataset,
                            const std::function<Parameters(int)>& parameters,
                            const MeasurementOptions& o) {
  std::vector<FrfFit> fits;
  for (int c = 0; c < static_cast<int>(dataset.conditions.size()); ++c) {
    const std::optional<Frf>& frf = dataset.conditions[c].frf;
    if (!frf) continue;
    const Parameters p = parameters(c);
    const ModelAt at{&model, &p, nullptr, nullptr};
    std::vector<FrfLines> functions;
    if (!CompareFrfs(dataset, c, at, o, &functions)) continue;
    for (const FrfLines& lines : functions) {
      const FrfFunction& fn = frf->functions[lines.function];
      FrfFit f;
      if (dataset.NamesConditions()) f.condition = dataset.conditions[c].name;
      f.output = frf->outputs[fn.output].name;
      f.input = frf->inputs[fn.input].name;
      f.frequency_hz = lines.frequency_hz;
      f.sigma = lines.sigma;
      for (size_t l = 0; l < lines.frequency_hz.size(); ++l) {
        f.chi2 += std::norm((lines.model[l] - lines.measured[l]) / lines.sigma[l]);
        f.measured_re.push_back(lines.measured[l].real());
        f.measured_im.push_back(lines.measured[l].imag());
        f.model_re.push_back(lines.model[l].real());
        f.model_im.push_back(lines.model[l].imag());
      }
      f.frac = Frac(lines.measured, lines.model);
      fits.push_back(std::move(f));
    }
  }
  return fits;
}

}  // namespace ringid
