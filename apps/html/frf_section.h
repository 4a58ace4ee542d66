// The measured FRFs of an identify page (estimation/frf_fits.h).
#ifndef RINGID_APPS_HTML_FRF_SECTION_H_
#define RINGID_APPS_HTML_FRF_SECTION_H_

#include <optional>
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

}  // namespace ringid::html

#endif  // RINGID_APPS_HTML_FRF_SECTION_H_
