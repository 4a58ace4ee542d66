// The measured FRFs of an identify page (estimation/frf_fits.h).
#ifndef RINGID_APPS_HTML_FRF_SECTION_H_
#define RINGID_APPS_HTML_FRF_SECTION_H_

#include <optional>
#include <string>
#include <vector>

#include "apps/html/page.h"
#include "estimation/frf_fits.h"

namespace ringid::html {

// Each function's lines, chi-square and FRAC as a table with a note on
// what they mean; nothing without FRFs.
void FrfTable(const std::optional<std::vector<FrfFit>>& frfs, Page* page);
// Per function a figure of its magnitude, phase and normalised residuals
// over frequency, measured against fitted.
void FrfFigures(const std::optional<std::vector<FrfFit>>& frfs, Page* page);

// What a figure calls the model's curve (its key and caption) and the model
// in its residuals, "(fitted − measured) / σ".
struct FrfModelNames {
  std::string curve = "fitted model";
  std::string residual = "fitted";
};
// One function's figure (FrfFigures'), named `name`.
Figure FrfFigure(const FrfFit& f, const std::string& name, const FrfModelNames& names = {});

}  // namespace ringid::html

#endif  // RINGID_APPS_HTML_FRF_SECTION_H_
