// The page toolkit: HTML escaping, table cells, and a page built of
// headings, notes, tables and figures.
#ifndef RINGID_APPS_HTML_PAGE_H_
#define RINGID_APPS_HTML_PAGE_H_

#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "apps/html/figure.h"
#include "model/enum_names.h"

namespace ringid::html {

// `text` with & < > " ' as character references.
std::string EscapeHtml(const std::string& text);

// A table cell: plain text, right-aligned when it is a number.
struct Cell {
  std::string text;
  bool number = false;
};
using Row = std::vector<Cell>;

Cell TextCell(const std::string& text);
// "–" when missing.
Cell NumberCell(std::optional<double> value, const char* format = "%.4g");
// 100 × `share`, as a percentage: every fraction a page shows (a shrink, a
// success rate, a coverage) is shown this way.
Cell PercentCell(std::optional<double> share, const char* format = "%.1f");
Cell YesNoCell(bool value);
// A number that may be NaN (not available): "–" then.
Cell NumberCell(double value, const char* format = "%.4g");
// An enum by its report name.
template <class E, class = std::enable_if_t<std::is_enum_v<E>>>
Cell NameCell(E value) {
  return TextCell(ToString(value));
}
// A list of names joined by ", ".
Cell ListCell(const std::vector<std::string>& items);
// "[a, b]", an end that is not a number "open"; "–" without an interval.
Cell IntervalCell(std::optional<double> lower, std::optional<double> upper);
Cell IntervalCell(const std::optional<std::pair<double, double>>& interval);

using FactRows = std::vector<std::pair<std::string, Cell>>;

class Page {
 public:
  struct Block {
    std::string html;
    std::optional<Figure> figure;
  };

  void Heading(const std::string& text);
  // A paragraph in the note style: why a figure is missing, what is left out.
  void Note(const std::string& text);
  // Two columns: what and its value.
  void Facts(const FactRows& rows);
  // The heading "Summary" and its facts.
  void Summary(const FactRows& rows);
  void Table(const std::vector<std::string>& head, const std::vector<Row>& rows);
  // A heading and its table, or nothing without rows.
  void TableSection(const std::string& heading, const std::vector<std::string>& head,
                    const std::vector<Row>& rows);
  void AddFigure(Figure figure);
  const std::vector<Block>& blocks() const { return blocks_; }

 private:
  void Html(const std::string& html) { blocks_.push_back({html, std::nullopt}); }
  std::vector<Block> blocks_;
};

// A figure as it stands on the page: its SVG, number and caption.
std::string FigureHtml(const Figure& figure, int number, const std::string& inline_svg);

// The whole document: `heading` as title and h1, `meta` under it.
std::string HtmlDocument(const std::string& heading, const std::string& meta,
                         const std::string& body);

}  // namespace ringid::html

#endif  // RINGID_APPS_HTML_PAGE_H_
