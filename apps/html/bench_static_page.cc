// The page of `ringid bench --suite=static`: the criterion and a row per free
// parameter (classes, coverage of the intervals classed yes, z).
#include "apps/html/pages.h"
#include "apps/html/text.h"

namespace ringid::html {

void BenchStaticPage(const BenchStaticReport& report, Page* page) {
  const StaticSuite& suite = report.body;
  const auto& [low, high] = suite.coverage_range;
  page->Summary({{"tires", NumberCell(suite.tires, "%.0f")},
                 {"initial values within a factor of the truth", NumberCell(suite.start_factor, "%g")},
                 {"starts per fit", NumberCell(suite.starts, "%.0f")},
                 {"failed fits", NumberCell(suite.failed_fits, "%.0f")},
                 {"poor fits (a start that missed the best point)", NumberCell(suite.poor_fits, "%.0f")},
                 {"seconds per fit", NumberCell(suite.seconds_per_fit)},
                 {"static-stiffness noise (relative sd)", NumberCell(suite.static_noise)},
                 {"pass", YesNoCell(suite.Pass())}});
  page->Note("Criterion: each parameter classed yes in at least " +
             Format(100 * suite.identifiable_share, "%.0f") + " % of the fits has its 95 % "
             "intervals cover the truth in " + Format(100 * low, "%.0f") + "-" +
             Format(100 * high, "%.0f") + " % of them.");
  CoverageTable("Parameters", suite.parameters, page);
}

void CoverageTable(const std::string& title, const std::vector<StaticParameter>& parameters,
                   Page* page) {
  std::vector<Row> rows;
  for (const StaticParameter& r : parameters) {
    rows.push_back({TextCell(ToString(r.param)), NumberCell(r.yes, "%.0f"),
                    NumberCell(r.practically_no, "%.0f"), NumberCell(r.no, "%.0f"),
                    NumberCell(static_cast<double>(r.intervals), "%.0f"),
                    PercentCell(r.coverage_95), NumberCell(r.mean_z, "%+.2f"),
                    NumberCell(r.rms_z, "%.2f")});
  }
  page->TableSection(title, {"parameter", "yes", "practically_no", "no", "intervals",
                             "95 % coverage (%)", "mean z", "rms z"},
                     rows);
}

}  // namespace ringid::html
