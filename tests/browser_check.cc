#include "tests/browser_check.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <set>

#include "tests/test_support.h"

namespace ringid::testing {
namespace {

// An element of the dumped DOM.
struct Element {
  std::string name;
  std::string id;
  std::string text;  // all the text inside it
  Element* parent = nullptr;
  std::vector<std::unique_ptr<Element>> children;
};

// HTML elements that have no end tag.
const std::set<std::string> kVoid = {"area",  "base", "br",   "col",    "embed", "hr", "img",
                                     "input", "link", "meta", "source", "track", "wbr"};

bool EndsName(char c) { return c == ' ' || c == '\n' || c == '\t' || c == '/' || c == '>'; }

// Reads the start tag at `i` (after '<'): its name, id and whether it closes
// itself; returns the index after '>'.
size_t ReadStartTag(const std::string& dom, size_t i, Element* e, bool* self_closing) {
  size_t end = i;
  while (end < dom.size() && !EndsName(dom[end])) ++end;
  e->name = dom.substr(i, end - i);
  *self_closing = false;
  for (i = end; i < dom.size() && dom[i] != '>'; ++i) {
    if (dom[i] == '"' || dom[i] == '\'') {
      const size_t close = dom.find(dom[i], i + 1);
      if (close == std::string::npos) return dom.size();
      if (i >= 4 && dom.compare(i - 3, 3, "id=") == 0 && EndsName(dom[i - 4]))
        e->id = dom.substr(i + 1, close - i - 1);
      i = close;
    }
    *self_closing = dom[i] == '/';
  }
  return i + 1;
}

// The dump as a tree; Chromium writes every non-void element's end tag.
std::unique_ptr<Element> ParseDom(const std::string& dom) {
  auto root = std::make_unique<Element>();
  root->name = "#document";
  Element* open = root.get();
  size_t i = 0;
  while (i < dom.size()) {
    if (dom[i] != '<') {
      const size_t end = std::min(dom.find('<', i), dom.size());
      for (Element* e = open; e; e = e->parent) e->text.append(dom, i, end - i);
      i = end;
    } else if (dom.compare(i, 4, "<!--") == 0) {
      i = std::min(dom.find("-->", i), dom.size() - 3) + 3;
    } else if (dom.compare(i, 2, "<!") == 0) {  // the doctype
      i = std::min(dom.find('>', i), dom.size() - 1) + 1;
    } else if (dom.compare(i, 2, "</") == 0) {  // closes the nearest open element of its name
      const size_t end = std::min(dom.find('>', i), dom.size() - 1);
      const std::string name = dom.substr(i + 2, end - i - 2);
      Element* e = open;
      while (e != root.get() && e->name != name) e = e->parent;
      if (e != root.get()) open = e->parent;
      i = end + 1;
    } else {
      auto child = std::make_unique<Element>();
      bool self_closing = false;
      i = ReadStartTag(dom, i + 1, child.get(), &self_closing);
      child->parent = open;
      Element* added = open->children.emplace_back(std::move(child)).get();
      if (!self_closing && !kVoid.count(added->name)) open = added;
    }
  }
  return root;
}

// The descendants of `e` named in `names`, not looking inside `skip`.
void Collect(const Element& e, const std::set<std::string>& names, std::vector<const Element*>* out,
             const std::string& skip = "") {
  for (const auto& child : e.children) {
    if (names.count(child->name)) out->push_back(child.get());
    if (child->name != skip) Collect(*child, names, out, skip);
  }
}

std::vector<const Element*> Find(const Element& e, const std::set<std::string>& names,
                                 const std::string& skip = "") {
  std::vector<const Element*> out;
  Collect(e, names, &out, skip);
  return out;
}

// The problems of one figure, numbered `number`.
void CheckFigure(const Element& figure, int number, std::vector<std::string>* problems) {
  const std::string what = "figure " + std::to_string(number) + " (" + figure.id + "): ";
  const auto svgs = Find(figure, {"svg"});
  if (svgs.size() != 1) {
    problems->push_back(what + std::to_string(svgs.size()) + " <svg> elements");
    if (svgs.empty()) return;
  }
  const Element& svg = *svgs[0];
  for (const Element* e : Find(svg, {"figure", "figcaption", "div", "p", "h2", "table", "body"}))
    problems->push_back(what + "HTML <" + e->name + "> inside the <svg>: the SVG is broken");
  if (Find(svg, {"path", "polyline"}, "defs").empty())
    problems->push_back(what + "no <path> or <polyline> outside <defs>");
  size_t marks = 0;
  for (const Element* g : Find(svg, {"g"})) {
    if (g->id.find("gnuplot_plot_") == std::string::npos) continue;
    marks += Find(*g, {"path", "polyline", "polygon", "use", "rect", "circle", "text"}).size();
  }
  if (marks == 0) problems->push_back(what + "nothing plotted (no mark in a gnuplot_plot group)");
  bool captioned = false;
  for (const auto& child : figure.children) {
    captioned |= child->name == "figcaption" &&
                 child->text.rfind("Figure " + std::to_string(number) + ".", 0) == 0;
  }
  if (!captioned)
    problems->push_back(what + "no caption \"Figure " + std::to_string(number) + ".\"");
}

}  // namespace

std::string Chromium() { return HaveProgram("chromium") ? "chromium" : ""; }

bool DumpDom(const std::string& url_path, const std::string& profile_dir, std::string* dom,
             std::string* error) {
  const std::string out = url_path + ".dom", err = url_path + ".dom.err";
  const std::string command =
      "timeout 120 chromium --headless --no-sandbox --disable-gpu"
      " --virtual-time-budget=5000 --user-data-dir=" +
      profile_dir + " --dump-dom file://" + url_path + " > " + out + " 2> " + err;
  const int status = std::system(command.c_str());
  *dom = ReadFile(out);
  if (status == 0 && !dom->empty()) return true;
  *error = command + " (status " + std::to_string(status) + "): " + ReadFile(err);
  return false;
}

std::vector<std::string> FigureProblems(const std::string& dom, int expected_figures) {
  const auto root = ParseDom(dom);
  const auto figures = Find(*root, {"figure"});
  std::vector<std::string> problems;
  if (static_cast<int>(figures.size()) != expected_figures) {
    problems.push_back(std::to_string(expected_figures) + " figures in the page, " +
                       std::to_string(figures.size()) + " in the browser's DOM");
  }
  for (size_t i = 0; i < figures.size(); ++i) CheckFigure(*figures[i], i + 1, &problems);
  return problems;
}

std::string SvgsAsXhtml(const std::string& html) {
  std::string xhtml = "<html xmlns=\"http://www.w3.org/1999/xhtml\"><body>\n";
  for (size_t i = html.find("<svg"); i != std::string::npos; i = html.find("<svg", i + 1)) {
    const size_t end = html.find("</svg>", i);
    const size_t next = html.find("<svg", i + 1);
    // A figure's text up to its end tag, or up to the next figure without one.
    xhtml += html.substr(i, end != std::string::npos && end < next ? end + 6 - i : next - i);
    xhtml += "\n";
  }
  return xhtml + "</body></html>\n";
}

std::vector<std::string> XmlProblems(const std::string& dom, int expected_figures) {
  std::vector<std::string> problems;
  const size_t error = dom.find("<parsererror");
  if (error != std::string::npos) {
    const size_t message = dom.find("error on line", error);
    problems.push_back("the SVG is not well-formed: " +
                       (message == std::string::npos
                            ? std::string("parser error")
                            : dom.substr(message, dom.find_first_of("<\n", message) - message)));
  }
  const auto svgs = Find(*ParseDom(dom), {"svg"});
  if (static_cast<int>(svgs.size()) != expected_figures) {
    problems.push_back(std::to_string(expected_figures) + " figures, " +
                       std::to_string(svgs.size()) + " SVGs read as XML");
  }
  return problems;
}

BrowserCheck CheckFiguresInChromium(const std::string& html_path, int expected_figures) {
  BrowserCheck check;
  const std::string xhtml_path = html_path + ".svgs.xhtml";
  std::ofstream(xhtml_path) << SvgsAsXhtml(ReadFile(html_path));
  std::string page_dom, xml_dom;
  if (!DumpDom(html_path, html_path + ".chromium", &page_dom, &check.error) ||
      !DumpDom(xhtml_path, html_path + ".chromium", &xml_dom, &check.error)) {
    return check;
  }
  check.ran = true;
  check.problems = FigureProblems(page_dom, expected_figures);
  for (const std::string& p : XmlProblems(xml_dom, expected_figures)) check.problems.push_back(p);
  return check;
}

}  // namespace ringid::testing
