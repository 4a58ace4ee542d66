// A page as a browser reads it: headless Chromium parses the HTML and dumps
// its DOM; the figures are checked in that DOM.
#ifndef RINGID_TESTS_BROWSER_CHECK_H_
#define RINGID_TESTS_BROWSER_CHECK_H_

#include <string>
#include <vector>

namespace ringid::testing {

// The chromium executable on PATH, or "".
std::string Chromium();

// The DOM of the page at `url_path` as Chromium parsed it (--dump-dom),
// with a private profile in `profile_dir`. False with the command and its
// stderr in `error` when Chromium fails or dumps nothing.
bool DumpDom(const std::string& url_path, const std::string& profile_dir, std::string* dom,
             std::string* error);

// What is wrong with the figures of a dumped DOM, one line per problem; none
// when it has `expected_figures` <figure>s, each holding one <svg> with its
// axes (<path> or <polyline> outside <defs>) and plotted marks (in a
// gnuplot_plot group), no HTML swallowed by the SVG, and its caption
// "Figure N." as a child.
std::vector<std::string> FigureProblems(const std::string& dom, int expected_figures);

// Every "<svg ... </svg>" of `html` in one XHTML document, which browsers
// read with their strict XML parser: a cut or unbalanced SVG is an error
// there even where the lenient HTML parser mends it.
std::string SvgsAsXhtml(const std::string& html);
// What is wrong in Chromium's dump of that document: a parser error, or
// not `expected_figures` <svg>s.
std::vector<std::string> XmlProblems(const std::string& dom, int expected_figures);

// Both checks of the page at `html_path` in Chromium.
struct BrowserCheck {
  bool ran = false;                   // Chromium dumped both documents
  std::string error;                  // else why not
  std::vector<std::string> problems;  // with the figures
};
BrowserCheck CheckFiguresInChromium(const std::string& html_path, int expected_figures);

}  // namespace ringid::testing

#endif  // RINGID_TESTS_BROWSER_CHECK_H_
