// The page of `ringid bench --suite=frf`: the criteria, and per variant its
// counts and a row per free parameter (classes, coverage, z).
#include "apps/html/pages.h"
#include "apps/html/text.h"

namespace ringid::html {

void BenchFrfPage(const BenchFrfReport& report, Page* page) {
  const FrfSuite& suite = report.body;
  const auto& [low, high] = suite.coverage_range;
  page->Summary({{"initial values within a factor of the truth", NumberCell(suite.start_factor, "%g")},
                 {"starts per fit", NumberCell(suite.starts, "%.0f")},
                 {"FRF noise (relative sd)", NumberCell(suite.frf_noise)},
                 {"drum speed (m/s)", NumberCell(suite.drum_speed_m_s, "%g")},
                 {"pass", YesNoCell(suite.Pass())}});
  page->Note("Criteria: the best fit (chi-square within 1 of the fit started at the truth) found "
             "in at least " + Format(100 * suite.best_share, "%.0f") + " % of the tires; the 95 % "
             "intervals cover the truth in " + Format(100 * low, "%.0f") + "-" +
             Format(100 * high, "%.0f") + " % (pooled); m_b and I_by within " +
             Format(100 * suite.mass_tolerance, "%g") + " % in at least " +
             Format(100 * suite.mass_share, "%.0f") + " %; on the drum K_cx and sigma_cx both "
             "identifiable in at least " + Format(100 * suite.separated_share, "%.0f") + " %.");
  for (const std::string& f : suite.Failing()) page->Note("Failing: " + f);
  for (const FrfVariant& v : suite.variants) {
    page->Summary({{"variant", TextCell(v.name)},
                   {"tires", NumberCell(v.tires, "%.0f")},
                   {"best found", NumberCell(v.best_found, "%.0f")},
                   {"pooled 95 % coverage (%)", PercentCell(v.coverage_95)},
                   {"m_b and I_by within the tolerance", NumberCell(v.masses_within, "%.0f")},
                   {"K_cx and sigma_cx both identifiable", NumberCell(v.contact_separated, "%.0f")},
                   {"failed fits", NumberCell(v.failed_fits, "%.0f")},
                   {"seconds per fit", NumberCell(v.seconds_per_fit)}});
    CoverageTable("Parameters, " + v.name, v.parameters, page);
  }
}

}  // namespace ringid::html
