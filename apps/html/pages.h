// One page builder per kind of report, each reading its typed report
// (report/report.h, validation/suites.h): field names live only there.
#ifndef RINGID_APPS_HTML_PAGES_H_
#define RINGID_APPS_HTML_PAGES_H_

#include "apps/html/page.h"
#include "report/extract_report.h"
#include "report/poles_report.h"
#include "report/report.h"
#include "validation/extract_suite.h"
#include "validation/suites.h"

namespace ringid::html {

void IdentifyPage(const IdentifyReport& report, Page* page);
void IdentifiabilityPage(const IdentifiabilityReport& report, Page* page);
void ComparePage(const CompareReport& report, Page* page);
void DiagnosePage(const DiagnoseReport& report, Page* page);
void PredictPage(const PredictReport& report, Page* page);
void CampaignPage(const CampaignReport& report, Page* page);
void ForcesPage(const ForcesReport& report, Page* page);
void ExtractPage(const ExtractReport& report, Page* page);
void PolesPage(const PolesReport& report, Page* page);
void BenchPaperPage(const BenchPaperReport& report, Page* page);
void BenchSyntheticPage(const BenchSyntheticReport& report, Page* page);
void BenchConditioningPage(const BenchConditioningReport& report, Page* page);
void BenchDiagnosisPage(const BenchDiagnosisReport& report, Page* page);
void BenchRollingPage(const BenchRollingReport& report, Page* page);
void BenchSpeedPage(const BenchSpeedReport& report, Page* page);
void BenchForcesPage(const BenchForcesReport& report, Page* page);
void BenchStaticPage(const BenchStaticReport& report, Page* page);
// A row per parameter: its classes, intervals, coverage and z (the static and frf suites).
void CoverageTable(const std::string& title, const std::vector<StaticParameter>& parameters,
                   Page* page);
void BenchFrfPage(const BenchFrfReport& report, Page* page);
void BenchExtractPage(const BenchExtractReport& report, Page* page);

// Monte Carlo coverage of the 95 % intervals per item (a tire, a parameter), in %, with the
// binomial 95 % range expected around 95 % for the item's number of intervals.
struct CoverageSeries {
  std::vector<std::string> names;
  Series observed, band;
  double low = 90;  // the lowest value either holds
  // The next item; a coverage that is not finite draws no point.
  void Add(const std::string& name, double coverage_95, long intervals);
};
// The plot of `coverage` in `figure`: its script's common lines (y from `y_low`), then
// `extra` (the page's tics and lines), then the band and the observed points.
void DrawCoverage(const CoverageSeries& coverage, double y_low, const std::string& extra,
                  Figure* figure);

// Where the report came from: version, command line, inputs and digests.
void ProvenanceSection(const Provenance& provenance, Page* page);

// A fitting method's title.
inline const char* MethodTitle(Method method) {
  return method == Method::kLevenbergMarquardt ? "Levenberg–Marquardt" : "Downhill Simplex";
}

}  // namespace ringid::html

#endif  // RINGID_APPS_HTML_PAGES_H_
