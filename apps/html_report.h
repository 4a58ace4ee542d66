// `ringid report`: any JSON report of ringid as one self-contained HTML page,
// with its figures drawn by gnuplot and inlined as SVG.
#ifndef RINGID_APPS_HTML_REPORT_H_
#define RINGID_APPS_HTML_REPORT_H_

#include <string>
#include <vector>

#include "model/archive.h"

namespace ringid {

// Reads a JSON report of ringid (any kind of report/report.h and the bench
// suites), strictly as its typed report. False with one line naming the file
// and the field when it is unreadable, not JSON, not a report of this
// schema version, or a field is missing, mistyped or unknown.
bool LoadReport(const std::string& path, Json* report, std::string* error);

// One figure as a standalone SVG file, named e.g. "identify-frequencies".
struct HtmlFigure {
  std::string name;
  std::string svg;
};

// The page of `report` under `title`. gnuplot (found on PATH) draws the
// figures in a private temporary directory. False with a one-line error when
// the report is not a ringid report, or gnuplot is missing or fails.
bool RenderHtmlReport(const Json& report, const std::string& title, std::string* html,
                      std::string* error, std::vector<HtmlFigure>* figures = nullptr);

}  // namespace ringid

#endif  // RINGID_APPS_HTML_REPORT_H_
