// `ringid report`: any JSON report of ringid as one self-contained HTML page,
// with its figures drawn by gnuplot and inlined as SVG.
#ifndef RINGID_APPS_HTML_REPORT_H_
#define RINGID_APPS_HTML_REPORT_H_

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ringid {

// Reads and parses a JSON report of ringid (identify, identifiability,
// compare, diagnose, predict, campaign or bench). False with one line naming
// the file and the field when it is unreadable, not JSON or not a report.
bool LoadReport(const std::string& path, nlohmann::json* report, std::string* error);

// One figure as a standalone SVG file, named e.g. "identify-frequencies".
struct HtmlFigure {
  std::string name;
  std::string svg;
};

// The page of `report` under `title`. gnuplot (found on PATH) draws the
// figures in a private temporary directory. False with a one-line error when
// the report is not a ringid report, or gnuplot is missing or fails.
bool RenderHtmlReport(const nlohmann::json& report, const std::string& title, std::string* html,
                      std::string* error, std::vector<HtmlFigure>* figures = nullptr);

}  // namespace ringid

#endif  // RINGID_APPS_HTML_REPORT_H_
