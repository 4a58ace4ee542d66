#include "apps/schema_doc.h"

#include "report/report.h"
#include "report/schema.h"
#include "validation/suites.h"

namespace ringid {
namespace {

template <class R>
std::string Section(const char* command) {
  return std::string("## ") + ToString(R::kKind) + "\n\nWritten by `" + command + "`.\n\n" +
         ReportSchema<R>() + "\n";
}

}  // namespace

std::string ReportsMarkdown() {
  return "# The reports of ringid\n\n"
         "Made by `ringid schema` from the reports' own field lists; a test keeps this file\n"
         "equal to its output. Every report is one JSON object. A reader refuses a missing,\n"
         "mistyped or unknown field, naming its path. Units are in the field names (`_hz`,\n"
         "`seconds`) or given beside the value (`unit`); fractions (a shrink, a success rate, a\n"
         "coverage) are fractions, not percentages. Schema version " +
         std::to_string(kReportSchemaVersion) + ".\n\n" +
         Section<IdentifyReport>("ringid identify --output=FILE") +
         Section<PredictReport>("ringid predict --output=FILE") +
         Section<IdentifiabilityReport>("ringid identifiability --output=FILE") +
         Section<CompareReport>("ringid compare --output=FILE") +
         Section<DiagnoseReport>("ringid diagnose --output=FILE") +
         Section<CampaignReport>("ringid identify|diagnose --output_dir=DIR (DIR/campaign.json)") +
         Section<BenchPaperReport>("ringid bench --suite=paper --output=FILE") +
         Section<BenchSyntheticReport>("ringid bench --suite=synthetic --output=FILE") +
         Section<BenchConditioningReport>("ringid bench --suite=conditioning --output=FILE") +
         Section<BenchDiagnosisReport>("ringid bench --suite=diagnosis --output=FILE") +
         Section<BenchRollingReport>("ringid bench --suite=rolling --output=FILE") +
         Section<BenchSpeedReport>("ringid bench --suite=speed --output=FILE");
}

}  // namespace ringid
