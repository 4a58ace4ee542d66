// `ringid report`: the kinds of report, each with its page builder, and the
// page drawn with gnuplot into one HTML document.
#include "apps/html_report.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <iterator>

#include "apps/html/gnuplot.h"
#include "apps/html/pages.h"
#include "apps/html/text.h"
#include "datasets/dataset.h"

namespace ringid {
namespace {

using html::Page;

constexpr int kMaxReportDepth = 64;
// A report is ringid's own output: a merged campaign of 10,000 datasets is
// about 7 MB, past the 4 MiB an input file may be.
constexpr long kMaxReportBytes = 512L << 20;

// Reads `json` as report type R and builds its page, provenance last.
template <class R, void (*Build)(const R&, Page*)>
bool Typed(const Json& json, Page* page, std::string* error) {
  R report;
  if (!ReadReport(json, &report, error)) return false;
  Build(report, page);
  html::ProvenanceSection(report.provenance, page);
  return true;
}

// Every kind of report, with its page builder.
struct PageKind {
  ReportKind kind;
  bool (*build)(const Json&, Page*, std::string*);
};
const PageKind kPageKinds[] = {
    {ReportKind::kIdentify, Typed<IdentifyReport, html::IdentifyPage>},
    {ReportKind::kPredict, Typed<PredictReport, html::PredictPage>},
    {ReportKind::kIdentifiability, Typed<IdentifiabilityReport, html::IdentifiabilityPage>},
    {ReportKind::kCompare, Typed<CompareReport, html::ComparePage>},
    {ReportKind::kDiagnose, Typed<DiagnoseReport, html::DiagnosePage>},
    {ReportKind::kCampaign, Typed<CampaignReport, html::CampaignPage>},
    {ReportKind::kForces, Typed<ForcesReport, html::ForcesPage>},
    {ReportKind::kExtract, Typed<ExtractReport, html::ExtractPage>},
    {ReportKind::kPoles, Typed<PolesReport, html::PolesPage>},
    {ReportKind::kBenchPaper, Typed<BenchPaperReport, html::BenchPaperPage>},
    {ReportKind::kBenchSynthetic, Typed<BenchSyntheticReport, html::BenchSyntheticPage>},
    {ReportKind::kBenchConditioning, Typed<BenchConditioningReport, html::BenchConditioningPage>},
    {ReportKind::kBenchDiagnosis, Typed<BenchDiagnosisReport, html::BenchDiagnosisPage>},
    {ReportKind::kBenchRolling, Typed<BenchRollingReport, html::BenchRollingPage>},
    {ReportKind::kBenchSpeed, Typed<BenchSpeedReport, html::BenchSpeedPage>},
    {ReportKind::kBenchForces, Typed<BenchForcesReport, html::BenchForcesPage>},
    {ReportKind::kBenchStatic, Typed<BenchStaticReport, html::BenchStaticPage>},
    {ReportKind::kBenchFrf, Typed<BenchFrfReport, html::BenchFrfPage>},
    {ReportKind::kBenchExtract, Typed<BenchExtractReport, html::BenchExtractPage>},
};

// The page of `report`; false with "FIELD: message" when it does not read.
bool BuildPage(const Json& report, Page* page, std::string* heading, std::string* error) {
  ReportKind kind;
  if (!ReportHeader(report, &kind, error)) return false;
  for (const PageKind& k : kPageKinds) {
    if (k.kind != kind) continue;
    std::string name = ToString(kind);
    std::replace(name.begin(), name.end(), '_', ' ');
    *heading = "ringid " + name + " report";
    const auto dataset = report.find("dataset");
    if (dataset != report.end() && dataset->is_string()) *heading += ": " + dataset->get<std::string>();
    return k.build(report, page, error);
  }
  *error = std::string("report: no page for ") + ToString(kind);
  return false;
}

// The page's blocks as HTML, each figure drawn by gnuplot and inlined.
bool Body(const Page& page, std::string* body, std::string* error,
          std::vector<HtmlFigure>* figures) {
  std::string gnuplot;
  html::TempDir dir;
  bool any_figure = false;
  for (const auto& block : page.blocks()) any_figure |= block.figure.has_value();
  if (any_figure && !html::FindGnuplot(&gnuplot)) {
    *error = "gnuplot not found (apt-get install gnuplot-nox)";
    return false;
  }
  if (any_figure && dir.path().empty()) {
    *error = std::string("cannot make a temporary directory: ") + std::strerror(errno);
    return false;
  }
  int number = 0;
  for (const auto& block : page.blocks()) {
    if (!block.figure) {
      *body += block.html;
      continue;
    }
    const html::Figure& f = *block.figure;
    std::string svg;
    if (!html::DrawSvg(gnuplot, f, dir.path(), &svg, error)) return false;
    ++number;
    const std::string inline_svg =
        html::InlineSvg(svg, "f" + std::to_string(number) + "_", f.caption);
    if (inline_svg.empty()) {
      *error = "gnuplot wrote no SVG (figure " + f.name + ")";
      return false;
    }
    if (figures) figures->push_back({f.name, svg});
    *body += html::FigureHtml(f, number, inline_svg);
  }
  if (number == 0) *body += "<p class=\"note\">This kind of report has no figures.</p>\n";
  return true;
}

}  // namespace

bool LoadReport(const std::string& path, Json* report, std::string* error) {
  std::string text;
  LoadError load;
  if (!ReadInputFile(path, &text, &load, kMaxReportBytes)) {
    *error = load.OneLine();
    return false;
  }
  struct TooDeep {};
  const Json::parser_callback_t guard = [](int depth, Json::parse_event_t, Json&) {
    if (depth > kMaxReportDepth) throw TooDeep{};
    return true;
  };
  try {
    *report = Json::parse(text, guard);
  } catch (const TooDeep&) {
    *error = path + ": nested deeper than " + std::to_string(kMaxReportDepth);
    return false;
  } catch (const Json::parse_error& e) {
    *error = path + ": not valid JSON (at byte " + std::to_string(e.byte) + ")";
    return false;
  } catch (const Json::exception&) {
    *error = path + ": invalid JSON";
    return false;
  }
  Page page;
  std::string heading;
  if (!BuildPage(*report, &page, &heading, error)) {
    *error = path + ": " + *error;
    return false;
  }
  return true;
}

bool RenderHtmlReport(const Json& report, const std::string& title, std::string* html,
                      std::string* error, std::vector<HtmlFigure>* figures) {
  Page page;
  std::string heading;
  if (!BuildPage(report, &page, &heading, error)) return false;
  std::string body;
  if (!Body(page, &body, error, figures)) return false;
  *html = html::HtmlDocument(heading, title, body);
  return true;
}

}  // namespace ringid
