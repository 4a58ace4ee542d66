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

using json = nlohmann::json;
using html::Get;
using html::Has;
using html::Page;
using html::Str;

constexpr int kMaxReportDepth = 64;

// A kind of report: "report" or "report-suite", its page builder, and for
// bench suites the field that marks a report written before it named itself.
struct ReportKind {
  const char* name;
  void (*build)(const json&, Page*);
  const char* marker;
};

const ReportKind kReportKinds[] = {{"identify", html::IdentifyPage, nullptr},
                                   {"identifiability", html::IdentifiabilityPage, nullptr},
                                   {"compare", html::ComparePage, nullptr},
                                   {"diagnose", html::DiagnosePage, nullptr},
                                   {"predict", html::PredictPage, nullptr},
                                   {"campaign", html::CampaignPage, nullptr},
                                   {"bench-paper", html::BenchPaperPage, "table3"},
                                   {"bench-synthetic", html::BenchSyntheticPage, "tires"},
                                   {"bench-conditioning", html::BenchConditioningPage, "variants"},
                                   {"bench-diagnosis", html::BenchDiagnosisPage, "confusion"}};

const ReportKind* FindKind(const std::string& name) {
  for (const ReportKind& kind : kReportKinds) {
    if (name == kind.name) return &kind;
  }
  return nullptr;
}

// The values of the "report" field: the kinds' names before any suite.
std::vector<std::string> ReportNames() {
  std::vector<std::string> names;
  for (const ReportKind& kind : kReportKinds) {
    const std::string name = kind.name;
    html::AppendOnce(&names, name.substr(0, name.find('-')));
  }
  return names;
}

// The kind of `r`; null with "FIELD: message" when it is none.
const ReportKind* KindOf(const json& r, std::string* error) {
  if (!r.is_object()) {
    *error = "not a ringid report (a JSON object with a \"report\" field)";
    return nullptr;
  }
  if (!Has(r, "report")) {  // bench reports written before they named themselves
    for (const ReportKind& kind : kReportKinds) {
      if (kind.marker && Has(r, kind.marker)) return &kind;
    }
    *error = "report: missing (not a ringid report)";
    return nullptr;
  }
  const std::string report = Str(r, "report");
  const std::vector<std::string> names = ReportNames();
  if (std::find(names.begin(), names.end(), report) == names.end()) {
    *error = "report: unknown kind '" + html::Text(Get(r, "report")) + "' (expected " +
             html::Join(names, ", ") + ")";
    return nullptr;
  }
  if (const ReportKind* kind = FindKind(report)) return kind;
  if (const ReportKind* kind = FindKind(report + "-" + Str(r, "suite"))) return kind;
  *error = "suite: unknown " + report + " suite '" + html::Text(Get(r, "suite")) + "'";
  return nullptr;
}

// "ringid identify report", "ringid bench paper report".
std::string Heading(const ReportKind& kind) {
  std::string name = kind.name;
  std::replace(name.begin(), name.end(), '-', ' ');
  return "ringid " + name + " report";
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

bool LoadReport(const std::string& path, json* report, std::string* error) {
  std::string text;
  LoadError load;
  if (!ReadInputFile(path, &text, &load)) {
    *error = load.OneLine();
    return false;
  }
  struct TooDeep {};
  const json::parser_callback_t guard = [](int depth, json::parse_event_t, json&) {
    if (depth > kMaxReportDepth) throw TooDeep{};
    return true;
  };
  try {
    *report = json::parse(text, guard);
  } catch (const TooDeep&) {
    *error = path + ": nested deeper than " + std::to_string(kMaxReportDepth);
    return false;
  } catch (const json::parse_error& e) {
    *error = path + ": not valid JSON (at byte " + std::to_string(e.byte) + ")";
    return false;
  } catch (const json::exception&) {
    *error = path + ": invalid JSON";
    return false;
  }
  if (!KindOf(*report, error)) {
    *error = path + ": " + *error;
    return false;
  }
  return true;
}

bool RenderHtmlReport(const json& report, const std::string& title, std::string* html,
                      std::string* error, std::vector<HtmlFigure>* figures) {
  const ReportKind* kind = KindOf(report, error);
  if (!kind) return false;
  Page page;
  try {
    kind->build(report, &page);
  } catch (const std::exception& e) {  // a value of a type the reads did not expect
    *error = std::string("cannot read the report: ") + e.what();
    return false;
  }
  std::string body;
  if (!Body(page, &body, error, figures)) return false;
  const std::string dataset = Str(report, "dataset");
  *html = html::HtmlDocument(Heading(*kind) + (dataset.empty() ? "" : ": " + dataset), title, body);
  return true;
}

}  // namespace ringid
