#include "apps/html/page.h"

#include <cmath>

#include <algorithm>
#include <sstream>

#include "apps/html/text.h"

namespace ringid::html {

std::string EscapeHtml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

Cell TextCell(const std::string& text) { return {text, false}; }

Cell NumberCell(std::optional<double> value, const char* format) {
  return {value && std::isfinite(*value) ? Format(*value, format) : "–", true};
}

Cell NumberCell(double value, const char* format) {
  return NumberCell(std::optional<double>(value), format);
}

Cell PercentCell(std::optional<double> share, const char* format) {
  return NumberCell(share ? std::optional<double>(100 * *share) : std::nullopt, format);
}

Cell YesNoCell(bool value) { return TextCell(value ? "yes" : "no"); }

Cell ListCell(const std::vector<std::string>& items) {
  return TextCell(items.empty() ? "–" : Join(items, ", "));
}

Cell IntervalCell(std::optional<double> lower, std::optional<double> upper) {
  const auto end = [](std::optional<double> x) {
    return x && std::isfinite(*x) ? Format(*x) : std::string("open");
  };
  return {"[" + end(lower) + ", " + end(upper) + "]", true};
}

Cell IntervalCell(const std::optional<std::pair<double, double>>& interval) {
  if (!interval) return {"–", true};
  return IntervalCell(interval->first, interval->second);
}

namespace {

std::string Td(const Cell& cell) {
  return std::string("<td") + (cell.number ? " class=\"n\"" : "") + ">" + EscapeHtml(cell.text) +
         "</td>";
}

}  // namespace

void Page::Heading(const std::string& text) { Html("<h2>" + EscapeHtml(text) + "</h2>\n"); }

void Page::Note(const std::string& text) {
  Html("<p class=\"note\">" + EscapeHtml(text) + "</p>\n");
}

void Page::Facts(const FactRows& rows) {
  if (rows.empty()) return;
  std::string html = "<table class=\"facts\">\n";
  for (const auto& [what, value] : rows) {
    html += "<tr><th>" + EscapeHtml(what) + "</th>" + Td(value) + "</tr>\n";
  }
  Html(html + "</table>\n");
}

void Page::Summary(const FactRows& rows) {
  Heading("Summary");
  Facts(rows);
}

void Page::Table(const std::vector<std::string>& head, const std::vector<Row>& rows) {
  if (rows.empty()) return;
  std::string html = "<table>\n<tr>";
  for (const std::string& title : head) html += "<th>" + EscapeHtml(title) + "</th>";
  html += "</tr>\n";
  for (const Row& row : rows) {
    html += "<tr>";
    for (const Cell& cell : row) html += Td(cell);
    html += "</tr>\n";
  }
  Html(html + "</table>\n");
}

void Page::TableSection(const std::string& heading, const std::vector<std::string>& head,
                        const std::vector<Row>& rows) {
  if (rows.empty()) return;
  Heading(heading);
  Table(head, rows);
}

void Page::AddFigure(Figure figure) { blocks_.push_back({"", std::move(figure)}); }

std::string FigureHtml(const Figure& figure, int number, const std::string& inline_svg) {
  return "<figure id=\"" + EscapeHtml(figure.name) +
         "\">\n<div style=\"max-width:" + std::to_string(figure.width) + "px\">" + inline_svg +
         "</div>\n<figcaption><b>Figure " + std::to_string(number) + ".</b> " +
         EscapeHtml(figure.caption) + "</figcaption>\n</figure>\n";
}

namespace {

const char kStyle[] =
    "body{font:14px/1.45 system-ui,-apple-system,'Segoe UI',Roboto,sans-serif;color:#1d1d1f;"
    "max-width:1060px;margin:24px auto;padding:0 18px}\n"
    "h1{font-size:22px;margin:0 0 4px}\n"
    "h2{font-size:17px;margin:30px 0 8px;padding-bottom:3px;border-bottom:1px solid #ddd}\n"
    "p.meta{color:#666;margin:0 0 12px}\n"
    "p.note{color:#555;font-size:13px}\n"
    "table{border-collapse:collapse;margin:6px 0 14px;font-size:13px}\n"
    "th,td{border:1px solid #dcdcdc;padding:3px 8px;text-align:left;vertical-align:top}\n"
    "th{background:#f3f5f7;font-weight:600}\n"
    "table.facts th{min-width:240px}\n"
    "td.n{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}\n"
    "figure{margin:18px 0 30px}\n"
    "figure svg{display:block;width:100%;height:auto}\n"
    "figcaption{font-size:13px;color:#333;margin-top:6px}\n";

}  // namespace

std::string HtmlDocument(const std::string& heading, const std::string& meta,
                         const std::string& body) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
         EscapeHtml(heading) + "</title>\n<style>\n" + kStyle + "</style>\n</head>\n<body>\n<h1>" +
         EscapeHtml(heading) + "</h1>\n<p class=\"meta\">" + EscapeHtml(meta) + "</p>\n" + body +
         "</body>\n</html>\n";
}

}  // namespace ringid::html
