// The page of `ringid bench --suite=extract`: the criteria, and per variant
// the modes found and labelled and how close their values came.
#include "apps/html/pages.h"
#include "apps/html/text.h"

namespace ringid::html {

void BenchExtractPage(const BenchExtractReport& report, Page* page) {
  const ExtractSuite& suite = report.body;
  page->Summary({{"initial values within a factor of the truth", NumberCell(suite.start_factor, "%g")},
                 {"FRF noise (relative sd)", NumberCell(suite.frf_noise)},
                 {"lines every (Hz)", NumberCell(suite.line_step_hz, "%g")},
                 {"pass", YesNoCell(suite.Pass())}});
  page->Note("Criteria: every mode of the model at the truth found and labelled as the model "
             "labels it, its frequency within " + Format(100 * suite.frequency_tolerance, "%g") +
             " % and its damping ratio within " + Format(100 * suite.damping_tolerance, "%g") +
             " % (relative). close_pair: the camber mode " + Format(suite.pair_gap_hz, "%g") +
             " Hz below the vertical one, both at damping ratio " +
             Format(suite.pair_damping, "%g") + "; the refinement's 95 % intervals of frequency "
             "and damping each cover the truth in " + Format(100 * suite.coverage_range.first, "%.0f") +
             "-" + Format(100 * suite.coverage_range.second, "%.0f") + " % of the modes.");
  for (const std::string& f : suite.Failing()) page->Note("Failing: " + f);
  for (const ExtractVariant& v : suite.variants) {
    page->Summary({{"variant", TextCell(v.name)},
                   {"tires", NumberCell(v.tires, "%.0f")},
                   {"modes at the truth", NumberCell(v.modes, "%.0f")},
                   {"found and labelled", NumberCell(v.found, "%.0f")},
                   {"frequency within the tolerance", NumberCell(v.frequency_within, "%.0f")},
                   {"damping ratio within the tolerance", NumberCell(v.damping_within, "%.0f")},
                   {"worst frequency error (%)", PercentCell(v.worst_frequency)},
                   {"worst damping-ratio error (%)", PercentCell(v.worst_damping)},
                   {"modes with standard errors", NumberCell(v.intervals, "%.0f")},
                   {"frequency intervals covering the truth", NumberCell(v.frequency_covered, "%.0f")},
                   {"damping intervals covering the truth", NumberCell(v.damping_covered, "%.0f")},
                   {"mean frequency error (sd)", NumberCell(v.frequency_bias_sd, "%+.2f")},
                   {"mean damping error (sd)", NumberCell(v.damping_bias_sd, "%+.2f")},
                   {"misses whose own 95 % interval is wider than the tolerance",
                    NumberCell(v.unresolved_misses, "%.0f")},
                   {"frequencies outside the tolerance that their standard errors predict",
                    NumberCell(v.frequency_misses_expected, "%.1f")},
                   {"damping ratios outside the tolerance that their standard errors predict",
                    NumberCell(v.damping_misses_expected, "%.1f")},
                   {"failed extractions", NumberCell(v.failed, "%.0f")},
                   {"seconds per tire", NumberCell(v.seconds_per_tire)}});
  }
  std::vector<Row> rows;
  for (const ExtractVariant& v : suite.variants) {
    for (const ExtractMiss& m : v.misses) {
      rows.push_back({TextCell(v.name), NumberCell(m.tire, "%.0f"), TextCell(m.label),
                      NumberCell(m.frequency_hz, "%.2f"), NumberCell(m.extracted_frequency_hz, "%.2f"),
                      NumberCell(m.frequency_sigma_hz, "%.2f"), NumberCell(m.damping_ratio, "%.4f"),
                      NumberCell(m.extracted_damping_ratio, "%.4f"), NumberCell(m.damping_sigma, "%.4f")});
    }
  }
  page->TableSection("Modes missed or outside a tolerance",
                     {"variant", "tire", "mode", "frequency at the truth (Hz)", "extracted (Hz)", "sd (Hz)",
                      "damping ratio at the truth", "extracted", "sd"},
                     rows);
}

}  // namespace ringid::html
