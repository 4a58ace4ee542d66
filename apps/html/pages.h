// One page builder per kind of report: each reads its JSON report with the
// never-throwing readers and adds sections and figures to the page.
#ifndef RINGID_APPS_HTML_PAGES_H_
#define RINGID_APPS_HTML_PAGES_H_

#include "apps/html/json_access.h"
#include "apps/html/page.h"

namespace ringid::html {

void IdentifyPage(const json& report, Page* page);
void IdentifiabilityPage(const json& report, Page* page);
void ComparePage(const json& report, Page* page);
void DiagnosePage(const json& report, Page* page);
void PredictPage(const json& report, Page* page);
void CampaignPage(const json& report, Page* page);
void BenchPaperPage(const json& report, Page* page);
void BenchSyntheticPage(const json& report, Page* page);
void BenchConditioningPage(const json& report, Page* page);
void BenchDiagnosisPage(const json& report, Page* page);

// The two fitting methods, their report key and title (compare and bench).
struct Method {
  const char* key;
  const char* title;
};
inline constexpr Method kMethods[] = {{"lm", "Levenberg–Marquardt"},
                                      {"simplex", "Downhill Simplex"}};

}  // namespace ringid::html

#endif  // RINGID_APPS_HTML_PAGES_H_
