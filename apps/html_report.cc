#include "apps/html_report.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <thread>
#include <tuple>

#include "datasets/dataset.h"

extern char** environ;

namespace ringid {
namespace {

using json = nlohmann::json;

constexpr int kMaxReportDepth = 64;
constexpr double kGnuplotSeconds = 120;
const char kBlue[] = "#1f77b4";
const char kOrange[] = "#e6791c";
const char kGreen[] = "#2ca02c";
const char kRed[] = "#d62728";
const char kGrey[] = "#9a9a9a";

// ---------------------------------------------------------------- JSON access
// Reads that never throw: a missing key or a value of the wrong type reads
// as null, an empty list or "".

const json& Null() {
  static const json null;
  return null;
}

const json& EmptyList() {
  static const json list = json::array();
  return list;
}

const json& Get(const json& j, const char* key) {
  if (!j.is_object()) return Null();
  const auto it = j.find(key);
  return it == j.end() ? Null() : *it;
}

bool Has(const json& j, const char* key) { return j.is_object() && j.contains(key); }

const json& List(const json& j, const char* key) {
  const json& v = Get(j, key);
  return v.is_array() ? v : EmptyList();
}

std::optional<double> Num(const json& v) {
  if (!v.is_number()) return std::nullopt;
  const double d = v.get<double>();
  if (!std::isfinite(d)) return std::nullopt;
  return d;
}

std::optional<double> Num(const json& j, const char* key) { return Num(Get(j, key)); }

std::string Str(const json& v) { return v.is_string() ? v.get<std::string>() : ""; }

std::string Str(const json& j, const char* key) { return Str(Get(j, key)); }

bool IsTrue(const json& j, const char* key) {
  const json& v = Get(j, key);
  return v.is_boolean() && v.get<bool>();
}

// ------------------------------------------------------------------- text

std::string Format(double v, const char* format = "%.4g") {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

std::string Join(const std::vector<std::string>& items, const std::string& separator) {
  std::string out;
  for (size_t i = 0; i < items.size(); ++i) out += (i ? separator : "") + items[i];
  return out;
}

// Any JSON value as short plain text.
std::string Text(const json& v) {
  if (v.is_null()) return "–";
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
  if (v.is_number_integer()) return std::to_string(v.get<long long>());
  if (v.is_number_unsigned()) return std::to_string(v.get<unsigned long long>());
  if (v.is_number()) return Format(v.get<double>());
  if (v.is_array()) {
    std::vector<std::string> items;
    for (const json& x : v) items.push_back(x.is_structured() ? "…" : Text(x));
    return Join(items, ", ");
  }
  std::vector<std::string> items;
  for (const auto& [k, x] : v.items())
    items.push_back(k + " = " + (x.is_structured() ? "…" : Text(x)));
  return Join(items, ", ");
}

std::string Escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
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

// A label for a figure: underscores read as spaces, no control characters.
std::string Pretty(const std::string& s) {
  std::string out;
  for (char c : s) out += (c == '_' || static_cast<unsigned char>(c) < 0x20) ? ' ' : c;
  if (out.size() > 40) out = out.substr(0, 37) + "...";
  return out;
}

// A gnuplot single-quoted string ('' is a quote; no backquote substitution).
std::string Q(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'' || c == '`')
      out += "''";
    else if (static_cast<unsigned char>(c) < 0x20)
      out += ' ';
    else
      out += c;
  }
  return out + "'";
}

std::vector<std::string> Pretty(const std::vector<std::string>& labels) {
  std::vector<std::string> out;
  for (const std::string& l : labels) out.push_back(Pretty(l));
  return out;
}

// gnuplot tic marks at 0, 1, ... named by `labels`.
std::string Tics(const std::vector<std::string>& labels, bool blank = false) {
  std::string out = "(";
  for (size_t i = 0; i < labels.size(); ++i) {
    std::string l = labels[i].size() > 40 ? labels[i].substr(0, 37) + "..." : labels[i];
    out += (i ? ", " : "") + Q(blank ? "" : l) + " " + std::to_string(i);
  }
  return out + ")";
}

std::string Stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

// --------------------------------------------------------------- the page

struct Cell {
  std::string text;  // plain text
  bool number = false;
};

Cell C(const json& v) { return {Text(v), v.is_number()}; }
Cell C(const std::string& s) { return {s, false}; }
Cell C(const char* s) { return {s, false}; }
Cell N(std::optional<double> v, const char* format = "%.4g") {
  return {v ? Format(*v, format) : "–", true};
}

// A figure: data files d0, d1, ... and a gnuplot script that plots them.
struct Figure {
  std::string name;     // KIND-WHAT, the file stem with --figures_dir
  std::string caption;  // what is plotted, in which units
  int width = 900;
  int height = 420;
  std::vector<std::string> data;
  std::string script;
};

// Rows of numbers for one data file; a missing number is '?'.
class Series {
 public:
  void Row(std::initializer_list<std::optional<double>> values) {
    bool first = true;
    for (const auto& v : values) {
      text_ += first ? "" : "\t";
      text_ += v && std::isfinite(*v) ? Format(*v, "%.12g") : "?";
      first = false;
    }
    text_ += "\n";
    ++rows_;
  }
  void Break() { text_ += "\n"; }  // ends a line segment
  bool empty() const { return rows_ == 0; }
  const std::string& text() const { return text_; }

 private:
  std::string text_;
  int rows_ = 0;
};

// Adds `s` to `f` and returns its gnuplot variable name.
std::string AddData(Figure* f, const Series& s) {
  f->data.push_back(s.text());
  return "d" + std::to_string(f->data.size() - 1);
}

class Page {
 public:
  struct Block {
    std::string html;
    std::optional<Figure> figure;
  };

  void Html(const std::string& html) { blocks_.push_back({html, std::nullopt}); }
  void Heading(const std::string& text) { Html("<h2>" + Escape(text) + "</h2>\n"); }
  void Para(const std::string& text, const std::string& cls = "") {
    Html("<p" + (cls.empty() ? "" : " class=\"" + cls + "\"") + ">" + Escape(text) + "</p>\n");
  }
  // Two columns: what and its value.
  void Facts(const std::vector<std::pair<std::string, Cell>>& rows) {
    if (rows.empty()) return;
    std::string h = "<table class=\"facts\">\n";
    for (const auto& [what, value] : rows) {
      h += "<tr><th>" + Escape(what) + "</th><td" + (value.number ? " class=\"n\"" : "") + ">" +
           Escape(value.text) + "</td></tr>\n";
    }
    Html(h + "</table>\n");
  }
  void Table(const std::vector<std::string>& head, const std::vector<std::vector<Cell>>& rows) {
    if (rows.empty()) return;
    std::string h = "<table>\n<tr>";
    for (const std::string& c : head) h += "<th>" + Escape(c) + "</th>";
    h += "</tr>\n";
    for (const auto& row : rows) {
      h += "<tr>";
      for (const Cell& c : row) {
        h += std::string("<td") + (c.number ? " class=\"n\"" : "") + ">" + Escape(c.text) + "</td>";
      }
      h += "</tr>\n";
    }
    Html(h + "</table>\n");
  }
  void Add(Figure f) { blocks_.push_back({"", std::move(f)}); }
  const std::vector<Block>& blocks() const { return blocks_; }

 private:
  std::vector<Block> blocks_;
};

using Facts = std::vector<std::pair<std::string, Cell>>;

// Adds `what` when `j` has `key` (a null value shows as "–").
void Fact(Facts* f, const std::string& what, const json& j, const char* key) {
  if (Has(j, key)) f->push_back({what, C(Get(j, key))});
}

// -------------------------------------------------------- shared figures

// Reference (with a ± half-width) and model frequency per mode: absolute Hz
// on the left, model − reference on the right with the half-width around 0.
std::optional<Figure> FrequencyFigure(const std::string& name,
                                      const std::vector<std::string>& labels,
                                      const std::vector<std::optional<double>>& reference,
                                      const std::vector<std::optional<double>>& halfwidth,
                                      const std::vector<std::optional<double>>& model,
                                      const std::string& reference_title,
                                      const std::string& band_title,
                                      const std::string& reference_name) {
  const int n = static_cast<int>(labels.size());
  Series s;
  double span = 0;
  bool any = false;
  for (int i = 0; i < n; ++i) {
    std::optional<double> diff;
    if (reference[i] && model[i]) diff = *model[i] - *reference[i];
    s.Row({i, reference[i], halfwidth[i], model[i], diff});
    any |= reference[i].has_value() || model[i].has_value();
    if (diff) span = std::max(span, std::fabs(*diff));
    if (halfwidth[i]) span = std::max(span, std::fabs(*halfwidth[i]));
  }
  if (!any) return std::nullopt;
  if (!(span > 0)) span = 1;
  span *= 1.3;
  Figure f;
  f.name = name;
  f.height = 150 + 34 * n;
  const std::string d = AddData(&f, s);
  std::ostringstream g;
  g << "set multiplot\n"
    << "set tmargin at screen " << 1 - 50.0 / f.height << "\n"
    << "set bmargin at screen " << 55.0 / f.height << "\n"
    << "set yrange [" << n - 0.5 << ":-0.5]\n"
    << "set grid xtics ytics\n"
    << "set key at graph 0.5, graph 1.02 center bottom vertical\n"
    << "set offsets graph 0.06, graph 0.06, 0, 0\n"
    << "set lmargin at screen 0.17\nset rmargin at screen 0.55\n"
    << "set ytics noenhanced " << Tics(Pretty(labels)) << "\n"
    << "set xlabel 'frequency (Hz)'\n"
    << "plot " << d << " using 2:1:3 with xerrorbars pt 7 ps 0.8 lc rgb '" << kBlue << "' title "
    << Q(reference_title) << ", " << d << " using 4:1 with points pt 2 ps 1.5 lw 1.5 lc rgb '"
    << kOrange << "' title 'model'\n"
    << "set lmargin at screen 0.61\nset rmargin at screen 0.97\n"
    << "set offsets 0, 0, 0, 0\n"
    << "set ytics " << Tics(labels, true) << "\n"
    << "set xrange [" << -span << ":" << span << "]\n"
    << "set arrow 1 from 0, graph 0 to 0, graph 1 nohead lc rgb '#888888' dt 2\n"
    << "set xlabel " << Q("model − " + reference_name + " (Hz)") << "\n"
    << "plot " << d << " using (0):1:3 with xerrorbars pt 7 ps 0 lw 2 lc rgb '" << kBlue
    << "' title " << Q(band_title) << ", " << d
    << " using 5:1 with points pt 2 ps 1.5 lw 1.5 lc rgb '" << kOrange << "' title "
    << Q("model − " + reference_name) << "\n"
    << "unset multiplot\n";
  f.script = g.str();
  return f;
}

// A heat map of `value[row][column]` (missing cells grey) with the value
// printed in each cell.
Figure HeatMap(const std::string& name, const std::vector<std::string>& rows,
               const std::vector<std::string>& columns,
               const std::vector<std::vector<std::optional<double>>>& value, double lo, double hi,
               const std::string& palette, const std::string& cell_format,
               const std::string& xlabel, const std::string& ylabel, const std::string& cblabel,
               bool print_values) {
  Figure f;
  f.name = name;
  const int nr = static_cast<int>(rows.size()), nc = static_cast<int>(columns.size());
  f.width = std::clamp(260 + 62 * nc, 520, 1000);
  f.height = std::clamp(190 + 34 * nr, 300, 1000);
  Series s;
  for (int r = 0; r < nr; ++r) {
    for (int c = 0; c < nc; ++c) {
      if (value[r][c]) s.Row({c, r, value[r][c]});
    }
  }
  const std::string d = AddData(&f, s);
  size_t longest = 0;
  for (const std::string& c : columns) longest = std::max(longest, c.size());
  const bool rotate = longest * 6.5 > (f.width - 250.0) / std::max(nc, 1);
  std::ostringstream g;
  g << "unset grid\nunset key\n"
    << "set object 1 rectangle from graph 0, graph 0 to graph 1, graph 1 behind fc rgb '#eeeeee' "
       "fs solid noborder\n"
    << "set xrange [-0.5:" << nc - 0.5 << "]\nset yrange [" << nr - 0.5 << ":-0.5]\n"
    << "set xtics noenhanced scale 0 " << (rotate ? "rotate by -35 left " : "") << Tics(columns)
    << "\n"
    << "set ytics noenhanced scale 0 " << Tics(rows) << "\n"
    << "set cbrange [" << lo << ":" << hi << "]\n"
    << "set palette defined " << palette << "\n"
    << "set xlabel " << Q(xlabel) << "\nset ylabel " << Q(ylabel) << "\nset cblabel " << Q(cblabel)
    << "\n"
    << "set style fill solid 1.0 noborder\n"
    << "plot " << d << " using 1:2:(0.5):(0.5):3 with boxxyerror lc palette";
  if (print_values) {
    const double mid = lo + 0.6 * (hi - lo);
    g << ", " << d << " using 1:2:(sprintf(" << Q(cell_format) << ", $3)):(abs($3) > "
      << (lo < 0 ? 0.6 * hi : mid) << " ? 0xffffff : 0x222222) with labels tc rgb variable";
  }
  g << "\n";
  f.script = g.str();
  return f;
}

// Horizontal bars per row, from `from` to `to` (log x when `log_x`): one
// panel of a multiplot between the given screen margins.
std::string BarPanel(Figure* f, const std::vector<std::string>& labels,
                     const std::vector<std::pair<double, double>>& bars,
                     const std::vector<bool>& highlight, double left, double right,
                     const std::string& xlabel, bool show_labels, bool log_x,
                     const char* on_color = kGreen) {
  Series hi, lo;
  for (size_t i = 0; i < bars.size(); ++i) {
    if (!std::isfinite(bars[i].first) || !std::isfinite(bars[i].second)) continue;
    (highlight[i] ? hi : lo).Row({static_cast<double>(i), bars[i].first, bars[i].second});
  }
  std::ostringstream g;
  g << "set lmargin at screen " << left << "\nset rmargin at screen " << right << "\n"
    << "set ytics noenhanced " << Tics(labels, !show_labels) << "\n"
    << "set xlabel " << Q(xlabel) << "\n"
    << (log_x ? "set logscale x\n" : "unset logscale x\n");
  std::vector<std::string> parts;
  for (auto [series, color] : {std::pair<Series*, const char*>{&hi, on_color}, {&lo, kGrey}}) {
    if (series->empty()) continue;
    parts.push_back(AddData(f, *series) +
                    " using (($2+$3)/2):1:2:3:($1-0.32):($1+0.32) with boxxyerror lc rgb '" +
                    color + "'");
  }
  if (!parts.empty()) g << "plot " << Join(parts, ", ") << "\n";
  return g.str();
}

// ------------------------------------------------------------- identify

void IdentifyPage(const json& r, Page* p) {
  Facts facts;
  Fact(&facts, "dataset", r, "dataset");
  Fact(&facts, "method", r, "method");
  Fact(&facts, "success", r, "success");
  Fact(&facts, "converged", r, "converged");
  Fact(&facts, "solver message", r, "message");
  Fact(&facts, "cost (½ Σ weighted residual²)", r, "cost");
  Fact(&facts, "evaluations", r, "evaluations");
  Fact(&facts, "starts", r, "starts");
  Fact(&facts, "final cost per start", r, "start_costs");
  Fact(&facts, "seconds", r, "seconds");
  Fact(&facts, "frequency weighting", r, "frequency_weighting");
  const json& err = Get(r, "relative_error");
  Fact(&facts, "relative error, in-plane (eq. 19)", err, "in_plane_eq19");
  Fact(&facts, "relative error, out-of-plane (eq. 20)", err, "out_of_plane_eq20");
  const json& cov = Get(r, "covariance");
  Fact(&facts, "covariance computed", cov, "computed");
  Fact(&facts, "covariance error", cov, "error");
  Fact(&facts, "rank of the weighted Jacobian", cov, "rank");
  Fact(&facts, "condition number", cov, "condition_number");
  p->Heading("Summary");
  p->Facts(facts);

  const json& modes = List(r, "modes");
  std::vector<std::vector<Cell>> rows;
  std::vector<std::string> labels;
  std::vector<std::optional<double>> measured, sigma, model;
  for (const json& m : modes) {
    const auto meas = Num(m, "measured_hz"), sig = Num(m, "measured_sigma_hz"),
               mod = Num(m, "model_hz");
    std::optional<double> diff, z;
    if (meas && mod) diff = *mod - *meas;
    if (diff && sig && *sig > 0) z = *diff / *sig;
    rows.push_back({C(Get(m, "label")), C(Get(m, "model_label")), N(meas, "%.3f"), N(sig, "%.3g"),
                    N(mod, "%.3f"), N(diff, "%.3g"), N(z, "%.3g"),
                    N(Num(m, "measured_damping_ratio")), N(Num(m, "model_damping_ratio")),
                    N(Num(m, "mac"), "%.3f")});
    labels.push_back(Str(m, "label"));
    measured.push_back(meas);
    sigma.push_back(sig);
    model.push_back(mod);
  }
  p->Heading("Modes");
  p->Table({"mode", "model mode", "measured (Hz)", "σ (Hz)", "model (Hz)", "model − measured (Hz)",
            "(model − measured) / σ", "measured damping ratio", "model damping ratio", "MAC"},
           rows);

  // Parameters, and the relative 95 % intervals of the free ones.
  const json& params = Get(r, "parameters");
  rows.clear();
  std::vector<std::string> names, no_std;
  std::vector<std::pair<double, double>> intervals;
  std::vector<std::string> classes;
  std::vector<std::string> clipped;
  constexpr double kClipFactor = 100;
  if (params.is_object()) {
    for (const auto& [name, q] : params.items()) {
      const auto value = Num(q, "value"), sd = Num(q, "std");
      const bool free = IsTrue(q, "free");
      std::string role = free ? "free" : "fixed";
      if (!Str(q, "tied_to").empty()) role = "tied to " + Str(q, "tied_to");
      std::optional<double> factor;
      if (free && value && sd && *value != 0) {
        double z = 1.96 * std::fabs(*sd / *value);
        factor = std::exp(std::min(z, 700.0));
        if (z > std::log(kClipFactor)) z = std::log(kClipFactor), clipped.push_back(name);
        names.push_back(name);
        intervals.push_back({std::exp(-z), std::exp(z)});
        classes.push_back(Str(q, "identifiable"));
      } else if (free) {
        no_std.push_back(name);
      }
      rows.push_back({C(name),
                      N(value),
                      C(Get(q, "unit")),
                      C(role),
                      N(sd),
                      {!factor         ? "–"
                       : *factor > 1e6 ? "> 10⁶"
                                       : "× ÷ " + Format(*factor, "%.3g"),
                       true},
                      C(Get(q, "identifiable")),
                      C(Get(q, "reason"))});
    }
  }
  p->Heading("Parameters");
  p->Table({"parameter", "value", "unit", "role", "std", "95 % interval (factor)", "identifiable",
            "reason"},
           rows);

  p->Heading("Figures");
  if (auto f = FrequencyFigure("identify-frequencies", labels, measured, sigma, model,
                               "measured ± 1σ", "± 1σ of the measurement", "measured")) {
    f->caption =
        "Frequency of each mode. Left: measured (dot, with ± 1σ bars) and model (cross), in Hz. "
        "Right: model − measured, in Hz, against the ± 1σ of the measurement drawn around 0.";
    p->Add(*f);
  }

  // MAC of the measured shapes against every model shape.
  std::vector<std::string> shape_rows, columns;
  std::vector<const json*> macs;
  for (const json& m : modes) {
    const json& mac = Get(m, "mac_all");
    if (!mac.is_object() || mac.empty()) continue;
    shape_rows.push_back(Str(m, "label"));
    macs.push_back(&mac);
  }
  if (macs.empty()) {
    p->Para("No MAC figure: the dataset gives no measured mode shape (no mode has mac_all).",
            "note");
  } else {
    for (const json& m : modes) {
      const std::string l = Str(m, "model_label");
      if (!l.empty() && std::find(columns.begin(), columns.end(), l) == columns.end())
        columns.push_back(l);
    }
    for (const json* mac : macs) {
      for (const auto& [l, v] : mac->items()) {
        if (std::find(columns.begin(), columns.end(), l) == columns.end()) columns.push_back(l);
      }
    }
    std::vector<std::vector<std::optional<double>>> value;
    for (const json* mac : macs) {
      value.emplace_back();
      for (const std::string& c : columns) value.back().push_back(Num(*mac, c.c_str()));
    }
    Figure f =
        HeatMap("identify-mac", Pretty(shape_rows), Pretty(columns), value, 0, 1,
                "(0 '#ffffff', 1 '#08519c')", "%.2f", "model mode", "measured mode", "MAC", true);
    f.caption =
        "Modal assurance criterion (MAC, 0 to 1) of each measured mode shape against every "
        "model mode shape; 1 means the same shape.";
    p->Add(f);
  }

  if (names.empty()) {
    p->Para("No interval figure: no free parameter has a standard deviation" +
                std::string(no_std.empty() ? "." : " (" + Join(no_std, ", ") + ")."),
            "note");
  } else {
    Figure f;
    f.name = "identify-parameters";
    f.width = std::clamp(300 + 45 * static_cast<int>(names.size()), 600, 1000);
    f.height = 420;
    double lo = 0.5, hi = 2;
    size_t longest = 0;
    for (const std::string& n : names) longest = std::max(longest, n.size());
    std::map<std::string, Series> by_class;
    for (size_t i = 0; i < names.size(); ++i) {
      lo = std::min(lo, intervals[i].first);
      hi = std::max(hi, intervals[i].second);
      const std::string c =
          classes[i] == "yes" || classes[i] == "practically_no" ? classes[i] : "other";
      by_class[c].Row({static_cast<double>(i), intervals[i].first, intervals[i].second});
    }
    std::ostringstream g;
    g << "set logscale y\nset format y '%g'\nset yrange [" << lo / 1.4 << ":" << hi * 1.4 << "]\n"
      << "set xrange [-0.7:" << names.size() - 0.3 << "]\n"
      << "set xtics noenhanced "
      << (longest * 6.5 > (f.width - 250.0) / names.size() ? "rotate by -35 left " : "")
      << Tics(names) << "\n"
      << "set grid ytics\nset ylabel 'interval / value (log scale)'\n"
      << "set key outside right top title 'identifiable' noenhanced\n"
      << "set arrow 1 from graph 0, first 2 to graph 1, first 2 nohead dt 2 lc rgb '#888888'\n"
      << "set arrow 2 from graph 0, first 0.5 to graph 1, first 0.5 nohead dt 2 lc rgb '#888888'\n"
      << "set arrow 3 from graph 0, first 1 to graph 1, first 1 nohead lc rgb '#bbbbbb'\n";
    std::vector<std::string> parts;
    for (auto [c, color] : {std::pair<std::string, const char*>{"yes", kBlue},
                            {"practically_no", kOrange},
                            {"other", kGrey}}) {
      if (!by_class.count(c)) continue;
      parts.push_back(AddData(&f, by_class[c]) +
                      " using 1:(1):2:3 with yerrorbars pt 7 ps 0.7 lw 2 lc rgb '" + color +
                      "' title " + Q(c));
    }
    g << "plot " << Join(parts, ", ") << "\n";
    f.script = g.str();
    f.caption =
        "95 % interval of each free parameter relative to its value, "
        "[exp(−1.96 std/value), exp(+1.96 std/value)], on a log axis (dimensionless). "
        "Dashed lines: a factor 2 either way, beyond which a parameter is practically "
        "not identifiable.";
    if (!clipped.empty()) {
      f.caption += " Cut at a factor " + Format(kClipFactor, "%.0f") +
                   ", beyond the axis: " + Join(clipped, ", ") + ".";
    }
    p->Add(f);
    if (!no_std.empty()) {
      p->Para(
          "Free parameters without a standard deviation (not drawn): " + Join(no_std, ", ") + ".",
          "note");
    }
  }
}

// ------------------------------------------------------- identifiability

// Tic marks for a log axis over [lo, hi] (0 < lo < hi): decades, or round
// values when the range is less than a few decades (gnuplot would show none).
std::string LogTics(double lo, double hi) {
  std::vector<double> at;
  const int first = static_cast<int>(std::floor(std::log10(lo))),
            last = static_cast<int>(std::ceil(std::log10(hi)));
  if (hi / lo >= 1000) {
    const int every = std::max(1, (last - first + 4) / 5);
    for (int k = first; k <= last; k += every) {
      if (const double t = std::pow(10.0, k); t >= lo && t <= hi) at.push_back(t);
    }
  } else if (hi / lo >= 10) {
    for (int k = first; k <= last; ++k) {
      for (double m : {1, 2, 5}) {
        if (const double t = m * std::pow(10.0, k); t >= lo && t <= hi) at.push_back(t);
      }
    }
  } else {
    const double raw = (hi - lo) / 2.5;
    const double base = std::pow(10.0, std::floor(std::log10(raw)));
    const double step = raw / base < 2 ? base : raw / base < 5 ? 2 * base : 5 * base;
    for (double t = std::ceil(lo / step) * step; t <= hi * (1 + 1e-12); t += step) at.push_back(t);
  }
  std::string out = "set xtics (";
  for (size_t i = 0; i < at.size(); ++i)
    out += (i ? ", " : "") + Q(Format(at[i], "%.3g")) + " " + Format(at[i], "%.12g");
  return out + ")\n";
}

// The profile's 95 % threshold and the unit of its curves: ringid writes
// Δχ² = 2 Δcost (threshold 3.84); curves in cost units would cross 1.92 at
// the reported interval ends.
std::pair<double, std::string> ProfileThreshold(const json& params) {
  int chi2 = 0, cost = 0;
  if (params.is_object()) {
    for (const auto& [name, q] : params.items()) {
      std::vector<std::pair<double, double>> curve;
      for (const json& pt : List(q, "profile_curve")) {
        if (pt.is_array() && pt.size() == 2 && Num(pt[0]) && Num(pt[1])) {
          curve.push_back({*Num(pt[0]), *Num(pt[1])});
        }
      }
      std::sort(curve.begin(), curve.end());
      for (const json& end : List(q, "profile_95")) {
        const auto e = Num(end);
        if (!e) continue;
        for (size_t i = 0; i + 1 < curve.size(); ++i) {
          const auto [a, da] = curve[i];
          const auto [b, db] = curve[i + 1];
          if (!(a <= *e && *e <= b) || a == b) continue;
          const bool logs = a > 0 && b > 0;
          const double t = logs ? std::log(*e / a) / std::log(b / a) : (*e - a) / (b - a);
          const double root = std::sqrt(da) + t * (std::sqrt(db) - std::sqrt(da));
          const double d = root * root;
          if (d > 0)
            (std::fabs(std::log(d / 3.84)) < std::fabs(std::log(d / 1.92)) ? chi2 : cost)++;
          break;
        }
      }
    }
  }
  if (cost > chi2) return {1.92, "Δcost"};
  return {3.84, "Δχ² = 2 Δcost"};
}

void IdentifiabilityPage(const json& r, Page* p) {
  Facts facts;
  Fact(&facts, "dataset", r, "dataset");
  Fact(&facts, "success", r, "success");
  Fact(&facts, "message", r, "message");
  Fact(&facts, "rank", r, "rank");
  Fact(&facts, "weighted residuals", r, "num_residuals");
  Fact(&facts, "condition number", r, "condition_number");
  Fact(&facts, "rank explanation", r, "rank_explanation");
  Fact(&facts, "largest identifiable subset", r, "identifiable_subset");
  Fact(&facts, "seconds", r, "seconds");
  p->Heading("Summary");
  p->Facts(facts);

  const json& params = Get(r, "parameters");
  std::vector<std::vector<Cell>> rows;
  if (params.is_object()) {
    for (const auto& [name, q] : params.items()) {
      auto interval = [&](const char* key) -> Cell {
        const json& v = Get(q, key);
        if (!v.is_array() || v.size() != 2) return C("–");
        const auto a = Num(v[0]), b = Num(v[1]);
        return {"[" + (a ? Format(*a) : "open") + ", " + (b ? Format(*b) : "open") + "]", true};
      };
      rows.push_back({C(name), N(Num(q, "value")), C(Get(q, "identifiable")), N(Num(q, "std")),
                      interval("wald_95"), interval("profile_95"), C(Get(q, "reason"))});
    }
  }
  p->Heading("Parameters");
  p->Table({"parameter", "value", "identifiable", "std", "Wald 95 %", "profile 95 %", "reason"},
           rows);
  rows.clear();
  for (const json& c : List(r, "combinations")) {
    rows.push_back({C(Get(c, "text")), C(Get(c, "meaning")), N(Num(c, "singular_value"))});
  }
  if (!rows.empty()) {
    p->Heading("Free and near-free combinations");
    p->Table({"combination", "meaning", "singular value"}, rows);
  }
  rows.clear();
  for (const json& c : List(r, "collinear_pairs")) {
    rows.push_back({C(Get(c, "parameters")), N(Num(c, "collinearity_index"))});
  }
  if (!rows.empty()) {
    p->Heading("Collinear pairs");
    p->Table({"parameters", "collinearity index"}, rows);
  }
  rows.clear();
  for (const json& a : List(r, "advice")) {
    rows.push_back({C(Get(a, "parameter")), C(Get(a, "observation")), N(Num(a, "information_gain")),
                    C(Get(a, "makes_identifiable"))});
  }
  if (!rows.empty()) {
    p->Heading("Experiment advice");
    p->Table({"parameter", "extra observation", "information gain", "makes it identifiable"}, rows);
  }

  p->Heading("Figures");
  const json& coords = List(r, "coordinates");
  // Singular values.
  Series above, below, zero;
  const auto rank = Num(r, "rank");
  int k = 0, shown = 0;
  double smin = 0;
  for (const json& v : List(r, "singular_values")) {
    ++k;
    const auto s = Num(v);
    if (!s || *s <= 0) continue;
    (rank && k > *rank ? below : above).Row({k, s});
    smin = smin == 0 ? *s : std::min(smin, *s);
    ++shown;
  }
  if (shown == 0) {
    p->Para("No singular value figure: the report has no positive singular value.", "note");
  } else {
    Figure f;
    f.name = "identifiability-singular-values";
    f.width = 760;
    f.height = 380;
    std::ostringstream g;
    g << "set logscale y\nset format y '10^{%L}'\nset grid\n"
      << "set xrange [0.5:" << k + 0.5 << "]\nset xtics 1\n"
      << "set xlabel 'index (largest first)'\nset ylabel 'singular value'\nset key top right\n";
    if (rank) {
      g << "set label 1 "
        << Q("rank " + Text(Get(r, "rank")) + " of " + std::to_string(coords.size()) +
             " free coordinates")
        << " at graph 0.03, graph 0.06 left\n";
    }
    std::vector<std::string> parts;
    if (!above.empty()) {
      parts.push_back(AddData(&f, above) + " using 1:2 with linespoints pt 7 ps 1 lw 1.5 lc rgb '" +
                      kBlue + "' title 'within the rank'");
    }
    if (!below.empty()) {
      parts.push_back(AddData(&f, below) + " using 1:2 with points pt 6 ps 1.2 lc rgb '" + kGrey +
                      "' title 'below the rank tolerance'");
    }
    g << "plot " << Join(parts, ", ") << "\n";
    f.script = g.str();
    f.caption =
        "Singular values of the weighted Jacobian (log coordinates for positive parameters; "
        "dimensionless), largest first, on a log axis. Free coordinates beyond the listed "
        "values change no residual.";
    p->Add(f);
  }

  // Correlation matrix.
  std::vector<std::string> names;
  for (const json& c : coords) names.push_back(Text(c));
  const json& corr = Get(r, "correlation");
  std::vector<std::vector<std::optional<double>>> value;
  bool any = false;
  if (corr.is_array() && corr.size() == names.size()) {
    for (const json& row : corr) {
      value.emplace_back();
      for (size_t c = 0; c < names.size(); ++c) {
        value.back().push_back(row.is_array() && c < row.size() ? Num(row[c]) : std::nullopt);
        any |= value.back().back().has_value();
      }
    }
  }
  if (!any) {
    p->Para(
        "No correlation figure: no correlation is defined (the covariance does not exist where "
        "the data leave directions free).",
        "note");
  } else {
    Figure f = HeatMap("identifiability-correlation", names, names, value, -1, 1,
                       "(-1 '#b2182b', 0 '#ffffff', 1 '#2166ac')", "%.2f", "", "", "correlation",
                       names.size() <= 16);
    f.caption =
        "Correlation of the fitted coordinates (−1 red to +1 blue); grey cells are undefined.";
    p->Add(f);
  }

  // Profile likelihood, one panel per parameter.
  const auto [threshold, unit] = ProfileThreshold(params);
  std::vector<std::string> profiled;
  Figure f;
  f.name = "identifiability-profiles";
  std::ostringstream panels;
  if (params.is_object()) {
    for (const auto& [name, q] : params.items()) {
      Series s;
      bool positive = true;
      int points = 0;
      double lo = INFINITY, hi = -INFINITY;
      for (const json& pt : List(q, "profile_curve")) {
        if (!pt.is_array() || pt.size() != 2) continue;
        const auto v = Num(pt[0]), d = Num(pt[1]);
        if (!v || !d) continue;
        s.Row({v, d});
        positive &= *v > 0;
        lo = std::min(lo, *v), hi = std::max(hi, *v);
        ++points;
      }
      if (points < 2) continue;
      const std::string var = AddData(&f, s);
      const int col = static_cast<int>(profiled.size()) % 4;
      profiled.push_back(name);
      panels << "set title " << Q(name) << " noenhanced\n"
             << (positive ? "set logscale x\n" : "unset logscale x\n")
             << (positive && hi > lo ? LogTics(lo, hi) : "set xtics autofreq\n")
             << (col == 0 ? "set ylabel " + Q(unit) + "\n" : "unset ylabel\n");
      if (const auto v = Num(q, "value")) {
        panels << "set arrow 2 from " << Format(*v, "%.12g") << ", graph 0 to "
               << Format(*v, "%.12g") << ", graph 1 nohead dt 3 lc rgb '#888888'\n";
      } else {
        panels << "unset arrow 2\n";
      }
      panels << "plot " << var << " using 1:2 with linespoints pt 7 ps 0.45 lw 1.5 lc rgb '"
             << kBlue << "' notitle\n";
    }
  }
  if (profiled.empty()) {
    p->Para("No profile figure: the report has no profile curve.", "note");
  } else {
    const int n = static_cast<int>(profiled.size());
    const int cols = std::min(n, 4), rows_n = (n + cols - 1) / cols;
    f.width = 1000;
    f.height = 40 + 210 * rows_n;
    std::ostringstream g;
    g << "set multiplot layout " << rows_n << "," << cols << " margins 0.07, 0.955, "
      << 45.0 / f.height << ", " << 1 - 30.0 / f.height << " spacing 0.06, " << 75.0 / f.height
      << "\n"
      << "set grid\nset yrange [0:" << 3 * threshold << "]\nset format x '%.3g'\n"
      << "set xtics rotate by -30 left font ',8'\nset ytics font ',8'\nset mxtics default\n"
      << "set autoscale xfix\nset offsets graph 0.04, graph 0.04, 0, 0\n"
      << "set arrow 1 from graph 0, first " << threshold << " to graph 1, first " << threshold
      << " nohead dt 2 lw 1.5 lc rgb '" << kRed << "'\n"
      << panels.str() << "unset multiplot\n";
    f.script = g.str();
    f.caption = "Profile likelihood of each parameter: the increase of the misfit, in " + unit +
                " (the other parameters re-optimised), against the parameter's value (log axis "
                "where positive). Red dashed line: the 95 % threshold " +
                Format(threshold, "%.2f") + "; dotted line: the fitted value. Curves beyond " +
                Format(3 * threshold, "%.3g") + " are cut at the top.";
    p->Add(f);
  }
}

// ---------------------------------------------------------------- compare

const std::pair<const char*, const char*> kMethods[] = {{"lm", "Levenberg–Marquardt"},
                                                        {"simplex", "Downhill Simplex"}};

void ComparePage(const json& r, Page* p) {
  Facts facts;
  Fact(&facts, "dataset", r, "dataset");
  Fact(&facts, "success", r, "success");
  Fact(&facts, "message", r, "message");
  Fact(&facts, "starts", r, "starts");
  Fact(&facts, "best cost", r, "best_cost");
  const json& init = Get(r, "initial");
  Fact(&facts, "cost at the dataset's initial values", init, "cost");
  Fact(&facts, "initial values: relative error in-plane (eq. 19)", init,
       "relative_error_in_plane_eq19");
  Fact(&facts, "initial values: relative error out-of-plane (eq. 20)", init,
       "relative_error_out_of_plane_eq20");
  const json& paper = Get(r, "paper_reported");
  Fact(&facts, "paper: relative error in-plane (eq. 19)", paper, "relative_error_in_plane_eq19");
  Fact(&facts, "paper: relative error out-of-plane (eq. 20)", paper,
       "relative_error_out_of_plane_eq20");
  p->Heading("Summary");
  p->Facts(facts);

  std::vector<std::vector<Cell>> rows;
  size_t starts = 0;
  for (const auto& [key, title] : kMethods) {
    const json& m = Get(r, key);
    if (!m.is_object()) continue;
    std::vector<double> costs;
    for (const json& c : List(m, "final_costs")) {
      if (const auto v = Num(c)) costs.push_back(*v);
    }
    std::sort(costs.begin(), costs.end());
    starts = std::max(starts, List(m, "final_costs").size());
    rows.push_back(
        {C(title), C(Get(m, "starts")), N(Num(m, "success_rate")),
         N(costs.empty() ? std::nullopt : std::optional<double>(costs.front())),
         N(costs.empty() ? std::nullopt : std::optional<double>(costs[costs.size() / 2])),
         N(Num(m, "median_evaluations"), "%.0f"), N(Num(m, "seconds_per_fit"))});
  }
  p->Heading("Methods");
  p->Table({"method", "starts", "success rate", "best final cost", "median final cost",
            "median evaluations", "seconds per fit"},
           rows);
  rows.clear();
  for (size_t i = 0; i < starts; ++i) {
    std::vector<Cell> row = {C(std::to_string(i + 1))};
    for (const auto& [key, title] : kMethods) {
      const json& m = Get(r, key);
      const json& c = List(m, "final_costs");
      const json& e = List(m, "evaluations");
      row.push_back(N(i < c.size() ? Num(c[i]) : std::nullopt));
      row.push_back(N(i < e.size() ? Num(e[i]) : std::nullopt, "%.0f"));
    }
    rows.push_back(row);
  }
  p->Heading("Per start");
  p->Table(
      {"start", "LM final cost", "LM evaluations", "simplex final cost", "simplex evaluations"},
      rows);

  p->Heading("Figures");
  const char* colors[] = {kBlue, kOrange};
  const int points[] = {7, 5};
  // Final costs, sorted.
  {
    Figure f;
    f.name = "compare-final-costs";
    f.width = 800;
    f.height = 400;
    std::vector<std::string> parts;
    int dropped = 0;
    double lo = INFINITY, hi = 0;
    for (int k = 0; k < 2; ++k) {
      std::vector<double> costs;
      for (const json& c : List(Get(r, kMethods[k].first), "final_costs")) {
        const auto v = Num(c);
        if (v && *v > 0)
          costs.push_back(*v);
        else
          ++dropped;
      }
      std::sort(costs.begin(), costs.end());
      Series s;
      for (size_t i = 0; i < costs.size(); ++i) s.Row({i + 1.0, costs[i]});
      if (!costs.empty()) lo = std::min(lo, costs.front()), hi = std::max(hi, costs.back());
      if (s.empty()) continue;
      parts.push_back(AddData(&f, s) + " using 1:2 with linespoints pt " +
                      std::to_string(points[k]) + " ps 1 lw 1.5 lc rgb '" + colors[k] + "' title " +
                      Q(kMethods[k].second));
    }
    if (parts.empty()) {
      p->Para("No final-cost figure: the report has no positive final cost.", "note");
    } else {
      std::ostringstream g;
      g << "set logscale y\nset format y '10^{%L}'\nset grid\nset key left center\n"
        << "set xlabel 'start, sorted by final cost'\nset ylabel 'final cost (½ Σ weighted "
           "residual²)'\n"
        << "set offsets 0.3, 0.3, 0, 0\n"
        << (starts <= 30 ? "set xtics 1\n" : "");
      if (const auto c = Num(init, "cost"); c && *c > 0) {
        hi = std::max(hi, *c);
        g << "set arrow 1 from graph 0, first " << *c << " to graph 1, first " << *c
          << " nohead dt 2 lc rgb '#888888'\n"
          << "set label 1 'cost at the initial values' at graph 0.98, first " << *c
          << " right offset 0, -0.8 tc rgb '#666666'\n";
      }
      g << "set yrange [" << lo / 5 << ":" << hi * 20 << "]\n"
        << "plot " << Join(parts, ", ") << "\n";
      f.script = g.str();
      f.caption =
          "Final cost of every start, sorted, per method, on a log axis (cost = ½ Σ weighted "
          "residual², dimensionless). The dashed line is the cost at the dataset's initial values.";
      if (dropped)
        f.caption += " " + std::to_string(dropped) + " zero or missing cost(s) are not drawn.";
      p->Add(f);
    }
  }
  // Cost against evaluations: the traces when present, else the end points.
  {
    Figure f;
    f.name = "compare-convergence";
    f.width = 800;
    f.height = 420;
    std::vector<std::string> parts;
    bool traces = false, log_x = true;
    for (const auto& [key, title] : kMethods) traces |= !List(Get(r, key), "histories").empty();
    for (int k = 0; k < 2; ++k) {
      const json& m = Get(r, kMethods[k].first);
      Series s;
      if (traces) {
        for (const json& h : List(m, "histories")) {
          if (!h.is_array()) continue;
          for (const json& pt : h) {
            if (!pt.is_array() || pt.size() != 2) continue;
            const auto e = Num(pt[0]), c = Num(pt[1]);
            if (!e || !c || *c <= 0) continue;
            log_x &= *e > 0;
            s.Row({e, c});
          }
          s.Break();
        }
      } else {
        const json& e = List(m, "evaluations");
        const json& c = List(m, "final_costs");
        for (size_t i = 0; i < std::min(e.size(), c.size()); ++i) {
          const auto ev = Num(e[i]), co = Num(c[i]);
          if (!ev || !co || *co <= 0) continue;
          log_x &= *ev > 0;
          s.Row({ev, co});
        }
      }
      if (s.empty()) continue;
      parts.push_back(AddData(&f, s) + " using 1:2 " +
                      (traces ? "with lines lw 1.2"
                              : "with points pt " + std::to_string(points[k]) + " ps 1.2") +
                      " lc rgb '" + colors[k] + "' title " + Q(kMethods[k].second));
    }
    if (parts.empty()) {
      p->Para("No convergence figure: the report has no evaluations with a positive cost.", "note");
    } else {
      std::ostringstream g;
      g << "set logscale y\nset format y '10^{%L}'\n"
        << (log_x ? "set logscale x\n" : "") << "set grid\nset key bottom left opaque box\n"
        << "set xlabel 'model evaluations" << (log_x ? " (log scale)" : "") << "'\n"
        << "set ylabel 'cost (½ Σ weighted residual²)'\n"
        << "plot " << Join(parts, ", ") << "\n";
      f.script = g.str();
      f.caption = traces
                      ? "Cost against the number of model evaluations, one line per start, on log "
                        "axes (cost = ½ Σ weighted residual², dimensionless)."
                      : "Final cost against the number of model evaluations, one point per start, "
                        "on log axes (cost = ½ Σ weighted residual², dimensionless).";
      p->Add(f);
    }
  }
}

// --------------------------------------------------------------- diagnose

struct Misfit {
  std::optional<double> frequency, damping, shape, chi2, shrink;
};

std::map<std::string, Misfit> Misfits(const json& where, std::vector<std::string>* order) {
  std::map<std::string, Misfit> out;
  for (const json& w : where) {
    const std::string label = Str(w, "label");
    Misfit m;
    m.frequency = Num(w, "frequency_sigma");
    m.damping = Num(w, "damping_sigma");
    if (const auto s = Num(w, "shape_chi2"); s && *s >= 0) m.shape = std::sqrt(*s);
    m.chi2 = Num(w, "chi2");
    m.shrink = Num(w, "shrink");
    if (order && std::find(order->begin(), order->end(), label) == order->end())
      order->push_back(label);
    out[label] = m;
  }
  return out;
}

void DiagnosePage(const json& r, Page* p) {
  const json& verdict = Get(r, "verdict");
  const json& gap = Get(r, "gap_before");
  const std::string effect = Str(verdict, "effect");
  Facts facts;
  Fact(&facts, "dataset", r, "dataset");
  Fact(&facts, "success", r, "success");
  Fact(&facts, "message", r, "message");
  Fact(&facts, "verdict", verdict, "effect");
  Fact(&facts, "explanation", verdict, "explanation");
  Fact(&facts, "indistinguishable from", verdict, "indistinguishable");
  Fact(&facts, "gap before: χ²", gap, "chi2");
  Fact(&facts, "gap before: degrees of freedom", gap, "dof");
  Fact(&facts, "gap before: χ² in excess of its dof", gap, "excess");
  Fact(&facts, "gap before: p-value", gap, "p_value");
  Fact(&facts, "gap significant", gap, "significant");
  Fact(&facts, "absorbed by re-calibration", r, "absorbed");
  Fact(&facts, "seconds", r, "seconds");
  p->Heading("Summary");
  p->Facts(facts);

  std::vector<std::vector<Cell>> rows;
  for (const json& f : List(r, "ranking")) {
    const json& ev = Get(f, "evidence");
    const auto shrink = Num(f, "shrink");
    rows.push_back({C(Get(f, "effect")), C(Get(f, "fitted")), N(Num(f, "gap_after")),
                    N(shrink ? std::optional<double>(100 * *shrink) : std::nullopt, "%.1f"),
                    N(Num(ev, "likelihood_ratio")), N(Num(ev, "lrt_p_value")),
                    C(Get(ev, "extra_parameters")), N(Num(ev, "aic")), N(Num(ev, "bic")),
                    C(Get(f, "supported")),
                    C(Has(f, "values") ? Get(f, "values") : Get(f, "note"))});
  }
  p->Heading("Effects, best first");
  p->Table({"effect", "fitted", "gap after", "shrink (%)", "likelihood ratio", "p",
            "extra parameters", "AIC", "BIC", "supported", "values"},
           rows);

  std::vector<std::string> labels;
  const auto before = Misfits(List(r, "where"), &labels);
  const bool has_after =
      Get(verdict, "where_after").is_array() && !Get(verdict, "where_after").empty();
  const auto after = Misfits(List(verdict, "where_after"), has_after ? &labels : nullptr);
  rows.clear();
  for (const std::string& l : labels) {
    const Misfit b = before.count(l) ? before.at(l) : Misfit();
    std::vector<Cell> row = {C(l), N(b.frequency, "%.3g"), N(b.damping, "%.3g"), N(b.shape, "%.3g"),
                             N(b.chi2, "%.3g")};
    if (has_after) {
      const Misfit a = after.count(l) ? after.at(l) : Misfit();
      for (const auto& v : {a.frequency, a.damping, a.shape, a.chi2}) row.push_back(N(v, "%.3g"));
    }
    row.push_back(N(b.shrink ? std::optional<double>(100 * *b.shrink) : std::nullopt, "%.1f"));
    rows.push_back(row);
  }
  p->Heading("Where: misfit per mode");
  std::vector<std::string> head = {"mode", "frequency (σ)", "damping (σ)", "√ shape χ²", "χ²"};
  if (has_after) {
    for (const char* h :
         {"after: frequency (σ)", "after: damping (σ)", "after: √ shape χ²", "after: χ²"}) {
      head.push_back(h);
    }
  }
  head.push_back("shrink (%)");
  p->Table(head, rows);

  p->Heading("Figures");
  // Misfit per mode and observable, before and after.
  if (!labels.empty()) {
    Figure f;
    f.name = "diagnose-misfit";
    const int n = static_cast<int>(labels.size());
    f.width = 920;
    f.height = has_after ? 620 : 360;
    double lo = -2.5, hi = 2.5;
    std::vector<std::string> vars;
    for (const auto* set : {&before, &after}) {
      if (set == &after && !has_after) break;
      Series s;
      for (int i = 0; i < n; ++i) {
        const Misfit m = set->count(labels[i]) ? set->at(labels[i]) : Misfit();
        s.Row({i, m.frequency, m.damping, m.shape});
        for (const auto& v : {m.frequency, m.damping, m.shape}) {
          if (v) lo = std::min(lo, *v), hi = std::max(hi, *v);
        }
      }
      vars.push_back(AddData(&f, s));
    }
    size_t longest = 0;
    for (const std::string& l : labels) longest = std::max(longest, Pretty(l).size());
    const bool rotate = longest * 6.5 > 560.0 / n;
    std::ostringstream g;
    const double pad = 0.08 * (hi - lo);
    g << (has_after ? "set multiplot layout 2,1\n" : "")
      << "set style fill solid 0.85 noborder\nset boxwidth 0.25\nset grid ytics\n"
      << "set xrange [-0.6:" << n - 0.4 << "]\nset yrange [" << lo - pad << ":" << hi + pad << "]\n"
      << "set xtics noenhanced " << (rotate ? "rotate by -25 left " : "") << Tics(Pretty(labels))
      << "\n"
      << "set ylabel 'misfit (σ)'\nset key outside right top\n"
      << "set lmargin 9\nset rmargin 26\n"
      << "set arrow 1 from graph 0, first 2 to graph 1, first 2 nohead dt 2 lc rgb '#888888'\n"
      << "set arrow 2 from graph 0, first -2 to graph 1, first -2 nohead dt 2 lc rgb '#888888'\n"
      << "set arrow 3 from graph 0, first 0 to graph 1, first 0 nohead lc rgb '#555555'\n";
    for (size_t k = 0; k < vars.size(); ++k) {
      const std::string& d = vars[k];
      g << (k == 1 ? "unset key\n" : "") << "set title "
        << Q(k == 0 ? "before: the calibrated baseline" : "after: with " + effect)
        << " noenhanced\n"
        << "plot " << d << " using ($1-0.26):2 with boxes lc rgb '" << kBlue
        << "' title 'frequency (σ)', " << d << " using 1:3 with boxes lc rgb '" << kOrange
        << "' title 'damping ratio (σ)', " << d << " using ($1+0.26):4 with boxes lc rgb '"
        << kGreen << "' title '√(shape χ²)'\n";
    }
    if (has_after) g << "unset multiplot\n";
    f.script = g.str();
    f.caption =
        "Misfit of each mode in units of its measurement σ: frequency and damping ratio "
        "(model − measured, signed) and the square root of the mode shape's χ². " +
        std::string(has_after ? "Top: the calibrated baseline; bottom: with " + effect + ". "
                              : "The baseline only (the verdict adds no effect). ") +
        "Dashed lines: ± 2σ.";
    p->Add(f);
  }

  // The ranking of the effects.
  {
    std::vector<std::string> effects;
    std::vector<std::pair<double, double>> shrink, lr;
    std::vector<bool> supported;
    Series thresholds;
    double lr_min = 1, shrink_lo = 0, shrink_hi = 100;
    for (const json& q : List(r, "ranking")) {
      const auto s = Num(q, "shrink");
      const auto l = Num(Get(q, "evidence"), "likelihood_ratio");
      if (!s && !l) continue;
      effects.push_back(Str(q, "effect"));
      shrink.push_back(s ? std::make_pair(std::min(0.0, 100 * *s), std::max(0.0, 100 * *s))
                         : std::make_pair(double(NAN), double(NAN)));
      lr.push_back({NAN, l && *l > 0 ? *l : NAN});
      if (s) shrink_lo = std::min(shrink_lo, 100 * *s), shrink_hi = std::max(shrink_hi, 100 * *s);
      if (l && *l > 0) lr_min = std::min(lr_min, *l);
      supported.push_back(IsTrue(q, "supported"));
      // The LR test's threshold at p = 1e-3 (χ² quantile) for 1 to 6 extra parameters.
      static const double kLrAt1e3[] = {10.828, 13.816, 16.266, 18.467, 20.515, 22.458};
      const double k = Num(Get(q, "evidence"), "extra_parameters").value_or(0);
      if (k >= 1 && k <= 6 && k == std::floor(k)) {
        thresholds.Row(
            {static_cast<double>(effects.size() - 1), kLrAt1e3[static_cast<int>(k) - 1]});
      }
    }
    if (effects.empty()) {
      p->Para("No ranking figure: no effect was fitted.", "note");
    } else {
      const double floor = std::pow(10, std::floor(std::log10(lr_min)));
      for (auto& b : lr) b.first = floor;
      Figure f;
      f.name = "diagnose-ranking";
      const int n = static_cast<int>(effects.size());
      f.width = 920;
      f.height = 110 + 36 * n;
      std::ostringstream g;
      g << "set multiplot\nset style fill solid 0.85 noborder\nset grid xtics\nunset key\n"
        << "set tmargin at screen " << 1 - 20.0 / f.height << "\nset bmargin at screen "
        << 55.0 / f.height << "\n"
        << "set yrange [" << n - 0.5 << ":-0.5]\nset xrange [" << shrink_lo - 5 << ":"
        << shrink_hi + 5 << "]\n"
        << BarPanel(&f, effects, shrink, supported, 0.2, 0.56,
                    "share of the gap removed (shrink, %)", true, false)
        << "set xrange [" << floor << ":*]\nset format x '10^{%L}'\n";
      std::string panel = BarPanel(&f, effects, lr, supported, 0.62, 0.97,
                                   "likelihood ratio (log scale)", false, true);
      if (!thresholds.empty() && panel.find("plot ") != std::string::npos) {
        panel.pop_back();
        panel += ", " + AddData(&f, thresholds) +
                 " using 2:($1-0.45):(0):(0.9) with vectors nohead lw 2.5 lc rgb '" + kRed + "'\n";
      }
      g << panel << "unset multiplot\n";
      f.script = g.str();
      f.caption =
          "Each catalogue effect refitted: left, the share of the gap it removes (%); right, "
          "its likelihood ratio against the baseline (log axis). Green: supported (LR test "
          "p < 10⁻³); grey: not supported. Red marks: the likelihood ratio that gives p = 10⁻³ for "
          "the "
          "effect's number of extra parameters.";
      p->Add(f);
    }
  }

  // The shrink per mode.
  {
    Series s;
    double lo = 0, hi = 100;
    for (size_t i = 0; i < labels.size(); ++i) {
      const auto it = before.find(labels[i]);
      if (it == before.end() || !it->second.shrink) continue;
      const double v = 100 * *it->second.shrink;
      s.Row({static_cast<double>(i), v});
      lo = std::min(lo, v), hi = std::max(hi, v);
    }
    if (s.empty()) {
      p->Para("No shrink figure: the report gives no shrink per mode.", "note");
    } else {
      Figure f;
      f.name = "diagnose-shrink";
      f.width = 900;
      f.height = 340;
      const int n = static_cast<int>(labels.size());
      size_t longest = 0;
      for (const std::string& l : labels) longest = std::max(longest, Pretty(l).size());
      std::ostringstream g;
      g << "set style fill solid 0.85 noborder\nset boxwidth 0.6\nset grid ytics\nunset key\n"
        << "set xrange [-0.6:" << n - 0.4 << "]\nset yrange [" << lo - 5 << ":" << hi + 5 << "]\n"
        << "set xtics noenhanced " << (longest * 6.5 > 700.0 / n ? "rotate by -25 left " : "")
        << Tics(Pretty(labels)) << "\n"
        << "set ylabel 'share of the χ² removed (%)'\n"
        << "set arrow 1 from graph 0, first 0 to graph 1, first 0 nohead lc rgb '#555555'\n"
        << "plot " << AddData(&f, s) << " using 1:2 with boxes lc rgb '" << kBlue << "'\n";
      f.script = g.str();
      f.caption = "Share of each mode's misfit χ² removed by " +
                  (effect.empty() ? "the verdict" : effect) +
                  ", in %; below 0 the mode fits worse.";
      p->Add(f);
    }
  }
}

// ---------------------------------------------------------------- predict

void PredictPage(const json& r, Page* p) {
  Facts facts;
  Fact(&facts, "solved", r, "ok");
  Fact(&facts, "error", r, "error");
  Fact(&facts, "overdamped (no oscillating mode)", r, "overdamped");
  p->Heading("Summary");
  p->Facts(facts);
  std::vector<std::vector<Cell>> rows;
  for (const json& m : List(r, "modes")) {
    rows.push_back({C(Get(m, "label")), C(Get(m, "plane")), N(Num(m, "model_hz"), "%.3f"),
                    N(Num(m, "damping_ratio")), N(Num(m, "label_energy_share"), "%.3f")});
  }
  p->Heading("Modes");
  p->Table(
      {"mode", "plane", "frequency (Hz)", "damping ratio", "energy share of the label's element"},
      rows);
}

// --------------------------------------------------------------- campaign

void CampaignPage(const json& r, Page* p) {
  Facts facts;
  Fact(&facts, "command", r, "command");
  Fact(&facts, "shard", r, "shard");
  Fact(&facts, "jobs", r, "jobs");
  Fact(&facts, "seconds", r, "seconds");
  const json& datasets = List(r, "datasets");
  facts.push_back({"datasets", N(static_cast<double>(datasets.size()), "%.0f")});
  p->Heading("Summary");
  p->Facts(facts);
  std::vector<std::string> columns;
  for (const json& c : List(r, "columns")) {
    if (c.is_string()) columns.push_back(c.get<std::string>());
  }
  if (columns.empty() && !datasets.empty() && datasets[0].is_object()) {
    for (const auto& [k, v] : datasets[0].items()) columns.push_back(k);
  }
  if (std::find(columns.begin(), columns.end(), "report_file") == columns.end()) {
    columns.push_back("report_file");
  }
  std::vector<std::vector<Cell>> rows;
  for (const json& d : datasets) {
    rows.push_back({});
    for (const std::string& c : columns) rows.back().push_back(C(Get(d, c.c_str())));
  }
  p->Heading("Datasets");
  p->Table(columns, rows);
  if (Str(r, "command") != "diagnose") return;

  Series s;
  std::vector<std::string> names;
  for (const json& d : datasets) {
    const auto b = Num(d, "gap_before"), a = Num(d, "gap_after");
    if (!b && !a) continue;
    s.Row({static_cast<double>(names.size()), b, a});
    names.push_back(Stem(Str(d, "dataset")));
  }
  p->Heading("Figures");
  if (s.empty()) {
    p->Para("No gap figure: no dataset has a gap.", "note");
    return;
  }
  Figure f;
  f.name = "campaign-gaps";
  const int n = static_cast<int>(names.size());
  f.width = std::clamp(300 + 28 * n, 700, 2400);
  f.height = 420;
  size_t longest = 0;
  for (const std::string& l : names) longest = std::max(longest, l.size());
  const std::string d = AddData(&f, s);
  std::ostringstream g;
  g << "set style fill solid 0.85 noborder\nset boxwidth 0.38\nset grid ytics\n"
    << "set key outside top center horizontal\n"
    << "set xrange [-0.6:" << n - 0.4 << "]\n"
    << "set xtics noenhanced "
    << (longest * 6.5 > (f.width - 150.0) / n ? "rotate by -60 left " : "") << Tics(names) << "\n"
    << "set ylabel 'gap: χ² in excess of its dof'\n"
    << "set arrow 1 from graph 0, first 0 to graph 1, first 0 nohead lc rgb '#555555'\n"
    << "plot " << d << " using ($1-0.2):2 with boxes lc rgb '" << kBlue
    << "' title 'before (baseline)', " << d << " using ($1+0.2):3 with boxes lc rgb '" << kOrange
    << "' title 'after (with the verdict)'";
  if (n <= 20) {
    for (const auto& [column, shift] : {std::pair<int, double>{2, -0.2}, {3, 0.2}}) {
      g << ", " << d << " using ($1" << (shift < 0 ? "" : "+") << shift << "):" << column
        << ":(sprintf('%.4g', $" << column << ")) with labels offset 0, 0.6 font ',8' notitle";
    }
  }
  g << "\n";
  f.script = g.str();
  f.caption =
      "The gap of each dataset before and after adding the effect of its verdict, as χ² in "
      "excess of its degrees of freedom (0 is a fit as good as the noise).";
  p->Add(f);
}

// ------------------------------------------------------------------ bench

void BenchPaperPage(const json& r, Page* p) {
  std::vector<std::vector<Cell>> rows;
  for (const auto& [key, title] : kMethods) {
    const json& m = Get(Get(r, "identify"), key);
    if (!m.is_object()) continue;
    rows.push_back({C(title), N(Num(m, "eq19")), N(Num(m, "eq20")), C(Get(m, "evaluations")),
                    C(Get(m, "rank")), N(Num(m, "seconds"))});
  }
  p->Heading("Table 1 identified");
  p->Table({"method", "relative error in-plane (eq. 19)", "relative error out-of-plane (eq. 20)",
            "evaluations", "rank", "seconds"},
           rows);
  rows.clear();
  std::vector<std::string> labels;
  std::vector<std::optional<double>> paper, model, rounding;
  for (const json& m : List(r, "table3")) {
    const auto ph = Num(m, "paper_hz"), mh = Num(m, "model_hz");
    std::optional<double> diff, rel;
    if (ph && mh) diff = *mh - *ph;
    if (diff && *ph != 0) rel = 100 * *diff / *ph;
    rows.push_back(
        {C(Get(m, "label")), N(ph, "%.1f"), N(mh, "%.3f"), N(diff, "%.3f"), N(rel, "%.2f")});
    labels.push_back(Str(m, "label"));
    paper.push_back(ph);
    model.push_back(mh);
    rounding.push_back(0.05);
  }
  p->Heading("Table 3 reproduced");
  p->Table({"mode", "paper (Hz)", "model (Hz)", "model − paper (Hz)", "model − paper (%)"}, rows);
  p->Heading("Figures");
  if (auto f = FrequencyFigure("bench-paper-table3", labels, paper, rounding, model,
                               "paper (Table 3)", "± 0.05 Hz, the paper's rounding", "paper")) {
    f->caption =
        "Table 3 of the paper reproduced from its Table 2 parameters. Left: the paper's and the "
        "model's frequency per mode, in Hz. Right: model − paper, in Hz, against ± 0.05 Hz, "
        "the rounding of the paper's table.";
    p->Add(*f);
  }
}

void BenchSyntheticPage(const json& r, Page* p) {
  Facts facts;
  Fact(&facts, "95 % coverage, all tires", r, "coverage_95");
  Fact(&facts, "free parameters", r, "free");
  const json& noise = Get(r, "noise");
  Fact(&facts, "frequency noise (relative sd)", noise, "frequency_relative");
  Fact(&facts, "damping noise (relative sd)", noise, "damping_relative");
  Fact(&facts, "shape noise (sd)", noise, "shape");
  p->Heading("Summary");
  p->Facts(facts);
  std::vector<std::vector<Cell>> rows;
  std::vector<std::string> tires;
  Series cover, band;
  double lo = 90, total = 0, total_n = 0;
  for (const json& t : List(r, "tires")) {
    const auto c = Num(t, "coverage_95"), n = Num(t, "intervals");
    rows.push_back({C(Get(t, "tire")), N(Num(t, "scale")), C(Get(t, "replicates")),
                    C(Get(t, "intervals")),
                    N(c ? std::optional<double>(100 * *c) : std::nullopt, "%.1f"),
                    N(Num(t, "median_error_over_std"), "%.3f"), C(Get(t, "failed_fits"))});
    const double i = static_cast<double>(tires.size());
    tires.push_back(Str(t, "tire"));
    if (c) cover.Row({i, 100 * *c}), lo = std::min(lo, 100 * *c);
    if (n && *n > 0) {
      const double half = 100 * 1.96 * std::sqrt(0.95 * 0.05 / *n);
      band.Row({i, std::max(0.0, 95 - half), std::min(100.0, 95 + half)});
      lo = std::min(lo, 95 - half);
      if (c) total += *c * *n, total_n += *n;
    }
  }
  p->Heading("Tires");
  p->Table({"tire", "scale", "replicates", "intervals", "95 % coverage (%)", "median |error| / std",
            "failed fits"},
           rows);
  p->Heading("Figures");
  if (cover.empty()) {
    p->Para("No coverage figure: no tire has a coverage.", "note");
    return;
  }
  Figure f;
  f.name = "bench-synthetic-coverage";
  f.width = 760;
  f.height = 380;
  std::ostringstream g;
  g << "set grid ytics\nset key outside below center horizontal\n"
    << "set xrange [-0.5:" << tires.size() - 0.5 << "]\nset yrange [" << std::floor(lo - 2)
    << ":101]\n"
    << "set xtics noenhanced " << Tics(tires) << "\n"
    << "set ylabel 'coverage of the 95 % intervals (%)'\n"
    << "set arrow 1 from graph 0, first 95 to graph 1, first 95 nohead dt 2 lw 1.5 lc rgb '" << kRed
    << "'\n"
    << "set label 1 'nominal 95 %' at graph 0.01, first 95 left offset 0, 0.7 tc rgb '" << kRed
    << "'\n"
    << "plot ";
  std::vector<std::string> parts;
  if (!band.empty()) {
    parts.push_back(AddData(&f, band) +
                    " using 1:2:(0):($3-$2) with vectors nohead lw 10 lc rgb '#cfcfcf' "
                    "title 'expected spread if the intervals are right (95 %)'");
  }
  parts.push_back(AddData(&f, cover) + " using 1:2 with points pt 7 ps 1.6 lc rgb '" + kBlue +
                  "' title 'observed coverage'");
  g << Join(parts, ", ") << "\n";
  f.script = g.str();
  f.caption =
      "Monte Carlo coverage of the 95 % intervals per tire, in %. Grey bars: the binomial 95 % "
      "range of the observed coverage around 95 % for that tire's number of intervals.";
  p->Add(f);
}

void BenchConditioningPage(const json& r, Page* p) {
  std::vector<std::vector<Cell>> rows;
  std::vector<std::string> variants;
  std::vector<std::pair<double, double>> rank;
  Series yes, pn, no;
  int free_max = 0;
  for (const json& v : List(r, "variants")) {
    int counts[3] = {0, 0, 0}, n = 0;
    if (const json& c = Get(v, "classes"); c.is_object()) {
      for (const auto& [name, cls] : c.items()) {
        ++n;
        const std::string s = Str(cls);
        ++counts[s == "yes" ? 0 : s == "practically_no" ? 1 : 2];
      }
    }
    free_max = std::max(free_max, n);
    const double i = static_cast<double>(variants.size());
    rows.push_back({C(Get(v, "data")), C(Get(v, "residuals")), C(Get(v, "rank")),
                    N(counts[0], "%.0f"), N(counts[1], "%.0f"), N(counts[2], "%.0f"),
                    N(Num(v, "condition_number")), C(Get(v, "identifiable_subset"))});
    variants.push_back(Str(v, "data"));
    const auto k = Num(v, "rank");
    rank.push_back({0, k ? *k : NAN});
    if (n) {
      yes.Row({i, 0, counts[0]});
      pn.Row({i, counts[0], counts[0] + counts[1]});
      no.Row({i, counts[0] + counts[1], n});
    }
  }
  p->Heading("Data variants");
  p->Table({"data", "residuals", "rank", "yes", "practically_no", "no", "condition number",
            "identifiable subset"},
           rows);
  p->Heading("Figures");
  if (variants.empty()) {
    p->Para("No conditioning figure: the report has no variant.", "note");
    return;
  }
  Figure f;
  f.name = "bench-conditioning-rank";
  const int n = static_cast<int>(variants.size());
  f.width = 920;
  f.height = 130 + 44 * n;
  std::ostringstream g;
  g << "set multiplot\nset style fill solid 0.85 noborder\nset grid xtics\n"
    << "set tmargin at screen " << 1 - 40.0 / f.height << "\nset bmargin at screen "
    << 55.0 / f.height << "\n"
    << "set yrange [" << n - 0.5 << ":-0.5]\nset xrange [0:" << std::max(free_max, 1) + 1 << "]\n"
    << "unset key\n";
  if (free_max) {
    g << "set arrow 1 from " << free_max << ", graph 0 to " << free_max
      << ", graph 1 nohead dt 2 lw 1.5 lc rgb '" << kRed << "'\nset label 1 "
      << Q(std::to_string(free_max) + " free") << " at " << free_max
      << ", graph 1 center offset 0, 0.8 tc rgb '" << kRed << "'\n";
  }
  g << BarPanel(&f, variants, rank, std::vector<bool>(n, true), 0.2, 0.56,
                "rank of the weighted Jacobian", true, false, kBlue);
  g << "unset arrow 1\nunset label 1\n"
    << "set key at screen 0.795, screen 1 center top horizontal\n"
    << "set lmargin at screen 0.62\nset rmargin at screen 0.97\n"
    << "set ytics " << Tics(variants, true) << "\n"
    << "set xlabel 'parameters by class'\n";
  std::vector<std::string> parts;
  for (auto [s, color, title] : {std::tuple<Series*, const char*, const char*>{&yes, kBlue, "yes"},
                                 {&pn, kOrange, "practically_no"},
                                 {&no, kGrey, "no"}}) {
    if (s->empty()) continue;
    parts.push_back(AddData(&f, *s) +
                    " using (($2+$3)/2):1:2:3:($1-0.32):($1+0.32) with boxxyerror lc rgb '" +
                    color + "' title " + Q(title));
  }
  if (!parts.empty()) g << "plot " << Join(parts, ", ") << "\n";
  g << "unset multiplot\n";
  f.script = g.str();
  f.caption =
      "What each kind of data determines. Left: rank of the weighted Jacobian per data "
      "variant, against the number of free parameters (dashed). Right: how many parameters "
      "fall in each identifiability class.";
  p->Add(f);
}

void BenchDiagnosisPage(const json& r, Page* p) {
  Facts facts;
  if (!List(r, "cases").empty())
    facts.push_back({"cases", C(std::to_string(List(r, "cases").size()))});
  Fact(&facts, "accuracy", r, "accuracy");
  Fact(&facts, "false alarms", r, "false_alarms");
  Fact(&facts, "no-effect cases", r, "no_effect_cases");
  Fact(&facts, "named", r, "named");
  Fact(&facts, "absorbed and explained", r, "absorbed_and_explained");
  Fact(&facts, "mean shrink when named", r, "mean_shrink_when_named");
  Fact(&facts, "seconds per diagnosis", r, "seconds_per_diagnosis");
  p->Heading("Summary");
  p->Facts(facts);

  // Confusion: truth -> verdict -> count.
  const json& confusion = Get(r, "confusion");
  std::vector<std::string> truths, verdicts;
  if (confusion.is_object()) {
    if (confusion.contains("none")) truths.push_back("none");
    for (const auto& [t, row] : confusion.items()) {
      if (t != "none") truths.push_back(t);
    }
    auto add = [&](const std::string& v) {
      if (std::find(verdicts.begin(), verdicts.end(), v) == verdicts.end()) verdicts.push_back(v);
    };
    for (const std::string& t : truths) {
      if (Get(Get(confusion, t.c_str()), "none").is_number()) add("none");
    }
    for (const std::string& t : truths) {
      if (Get(Get(confusion, t.c_str()), t.c_str()).is_number()) add(t);
    }
    for (const std::string& t : truths) {
      if (Get(confusion, t.c_str()).is_object()) {
        for (const auto& [v, c] : Get(confusion, t.c_str()).items()) add(v);
      }
    }
  }
  std::vector<std::vector<std::optional<double>>> counts;
  std::vector<std::vector<Cell>> rows;
  double most = 1;
  for (const std::string& t : truths) {
    counts.emplace_back();
    rows.push_back({C(t)});
    for (const std::string& v : verdicts) {
      const auto c = Num(Get(confusion, t.c_str()), v.c_str());
      counts.back().push_back(c);
      rows.back().push_back(N(c, "%.0f"));
      if (c) most = std::max(most, *c);
    }
  }
  std::vector<std::string> head = {"truth \\ verdict"};
  head.insert(head.end(), verdicts.begin(), verdicts.end());
  p->Heading("Confusion");
  p->Table(head, rows);
  rows.clear();
  for (const json& c : List(r, "cases")) {
    rows.push_back({C(Get(c, "case")), C(Get(c, "truth")), N(Num(c, "shift")), N(Num(c, "value")),
                    C(Get(c, "verdict")), C(Get(c, "indistinguishable")),
                    N(Num(c, "gap_p_value"), "%.3g"), C(Get(c, "correct")),
                    C(Get(c, "absorbed_explained")), N(Num(c, "seconds"), "%.2f")});
  }
  p->Heading("Cases");
  p->Table({"case", "truth", "shift", "value", "verdict", "indistinguishable", "gap p-value",
            "correct", "absorbed and explained", "seconds"},
           rows);
  p->Heading("Figures");
  if (truths.empty() || verdicts.empty()) {
    p->Para("No confusion figure: the report has no confusion matrix.", "note");
    return;
  }
  Figure f = HeatMap("bench-diagnosis-confusion", truths, verdicts, counts, 0, most,
                     "(0 '#ffffff', 1 '#08519c')", "%.0f", "verdict", "withheld effect (truth)",
                     "cases", true);
  f.caption =
      "Confusion matrix of the withheld-effect validation: number of cases per withheld "
      "effect (row) and verdict (column); the diagonal is a named effect.";
  p->Add(f);
}

// ------------------------------------------------------------------ kinds

const char* const kKinds[] = {"identify", "identifiability", "compare", "diagnose",
                              "predict",  "campaign",        "bench"};
const char* const kSuites[] = {"paper", "synthetic", "conditioning", "diagnosis"};

// "identify", ..., "bench-paper"; false with "FIELD: message".
bool Kind(const json& r, std::string* kind, std::string* error) {
  if (!r.is_object()) {
    *error = "not a ringid report (a JSON object with a \"report\" field)";
    return false;
  }
  std::string report = Str(r, "report");
  std::string suite = Str(r, "suite");
  if (!Has(r, "report")) {  // bench reports written before they named themselves
    if (Has(r, "table3"))
      suite = "paper";
    else if (Has(r, "tires"))
      suite = "synthetic";
    else if (Has(r, "variants"))
      suite = "conditioning";
    else if (Has(r, "confusion"))
      suite = "diagnosis";
    if (suite.empty()) {
      *error = "report: missing (not a ringid report)";
      return false;
    }
    report = "bench";
  }
  const auto known = [](const auto& list, const std::string& s) {
    return std::find(std::begin(list), std::end(list), s) != std::end(list);
  };
  if (!known(kKinds, report)) {
    *error = "report: unknown kind '" + Text(Get(r, "report")) + "' (expected " +
             Join(std::vector<std::string>(std::begin(kKinds), std::end(kKinds)), ", ") + ")";
    return false;
  }
  if (report == "bench") {
    if (!known(kSuites, suite)) {
      *error = "suite: unknown bench suite '" + Text(Get(r, "suite")) + "'";
      return false;
    }
    report += "-" + suite;
  }
  *kind = report;
  return true;
}

void BuildPage(const std::string& kind, const json& r, Page* p) {
  if (kind == "identify")
    IdentifyPage(r, p);
  else if (kind == "identifiability")
    IdentifiabilityPage(r, p);
  else if (kind == "compare")
    ComparePage(r, p);
  else if (kind == "diagnose")
    DiagnosePage(r, p);
  else if (kind == "predict")
    PredictPage(r, p);
  else if (kind == "campaign")
    CampaignPage(r, p);
  else if (kind == "bench-paper")
    BenchPaperPage(r, p);
  else if (kind == "bench-synthetic")
    BenchSyntheticPage(r, p);
  else if (kind == "bench-conditioning")
    BenchConditioningPage(r, p);
  else if (kind == "bench-diagnosis")
    BenchDiagnosisPage(r, p);
}

// ---------------------------------------------------------------- gnuplot

class TempDir {
 public:
  TempDir() {
    std::error_code ec;
    std::string base = std::filesystem::temp_directory_path(ec).string();
    if (ec || base.empty()) base = "/tmp";
    std::string pattern = base + "/ringid-report-XXXXXX";
    if (::mkdtemp(pattern.data())) path_ = pattern;
  }
  ~TempDir() {
    if (path_.empty()) return;
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

bool FindGnuplot(std::string* path) {
  const char* env = std::getenv("PATH");
  std::stringstream dirs(env ? env : "");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/gnuplot";
    struct stat st;
    if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
        ::access(candidate.c_str(), X_OK) == 0) {
      *path = candidate;
      return true;
    }
  }
  return false;
}

bool WriteText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  return static_cast<bool>(out);
}

std::string ReadText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `gnuplot -d script` with its output in `log`; false with a one-line
// error when it cannot start, fails or takes too long.
bool RunGnuplot(const std::string& gnuplot, const std::string& script, const std::string& log,
                std::string* error) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  std::vector<std::string> args = {gnuplot, "-d", script};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, gnuplot.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) {
    *error = "cannot run " + gnuplot + ": " + std::strerror(rc);
    return false;
  }
  const auto t0 = std::chrono::steady_clock::now();
  int status = 0;
  while (true) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) {
      *error = "lost the gnuplot process";
      return false;
    }
    if (std::chrono::steady_clock::now() - t0 > std::chrono::duration<double>(kGnuplotSeconds)) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      *error = "gnuplot took longer than " + Format(kGnuplotSeconds, "%.0f") + " s";
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return true;
  // The first line gnuplot wrote that says what went wrong.
  std::stringstream lines(ReadText(log));
  std::string line, first;
  while (std::getline(lines, line)) {
    if (line.find_first_not_of(" \t^") == std::string::npos) continue;
    if (first.empty()) first = line;
    if (line.find("rror") != std::string::npos) {
      first = line;
      break;
    }
  }
  *error = "gnuplot failed" + (first.empty() ? std::string() : ": " + first);
  return false;
}

// The SVG of gnuplot for inlining: from <svg on, ids prefixed so that
// several figures can share a page.
std::string InlineSvg(const std::string& svg, const std::string& prefix, const std::string& label) {
  const size_t start = svg.find("<svg");
  if (start == std::string::npos) return "";
  std::string s = svg.substr(start);
  const auto name_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  };
  std::set<std::string> ids;
  for (size_t i = s.find("id="); i != std::string::npos; i = s.find("id=", i + 3)) {
    if (i + 3 >= s.size() || (s[i + 3] != '\'' && s[i + 3] != '"')) continue;
    const size_t end = s.find(s[i + 3], i + 4);
    if (end != std::string::npos) ids.insert(s.substr(i + 4, end - i - 4));
  }
  std::string out;
  out.reserve(s.size() + 4096);
  for (size_t i = 0; i < s.size();) {
    size_t name = std::string::npos;
    if (s[i] == '#')
      name = i + 1;
    else if (s.compare(i, 3, "id=") == 0 && i + 3 < s.size() &&
             (s[i + 3] == '\'' || s[i + 3] == '"'))
      name = i + 4;
    if (name == std::string::npos) {
      out += s[i++];
      continue;
    }
    size_t end = name;
    while (end < s.size() && name_char(s[end])) ++end;
    out.append(s, i, name - i);
    if (ids.count(s.substr(name, end - name))) out += prefix;
    out.append(s, name, end - name);
    i = end;
  }
  const size_t tag = out.find("<svg") + 4;
  out.insert(tag, " role=\"img\" aria-label=\"" + Escape(label) + "\"");
  while (!out.empty() && std::isspace(static_cast<unsigned char>(out.back()))) out.pop_back();
  return out;
}

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
  std::string kind;
  if (!Kind(*report, &kind, error)) {
    *error = path + ": " + *error;
    return false;
  }
  return true;
}

bool RenderHtmlReport(const json& report, const std::string& title, std::string* html,
                      std::string* error, std::vector<HtmlFigure>* figures) {
  std::string kind;
  if (!Kind(report, &kind, error)) return false;
  Page page;
  try {
    BuildPage(kind, report, &page);
  } catch (const std::exception& e) {  // a value of a type the reads above did not expect
    *error = std::string("cannot read the report: ") + e.what();
    return false;
  }
  std::string gnuplot;
  TempDir dir;
  bool any_figure = false;
  for (const auto& b : page.blocks()) any_figure |= b.figure.has_value();
  if (any_figure) {
    if (!FindGnuplot(&gnuplot)) {
      *error = "gnuplot not found (apt-get install gnuplot-nox)";
      return false;
    }
    if (dir.path().empty()) {
      *error = std::string("cannot make a temporary directory: ") + std::strerror(errno);
      return false;
    }
  }
  const std::string heading =
      "ringid " + (kind.rfind("bench-", 0) == 0 ? "bench " + kind.substr(6) : kind) + " report";
  std::string dataset = Str(report, "dataset");
  std::string body;
  int number = 0;
  for (const auto& block : page.blocks()) {
    if (!block.figure) {
      body += block.html;
      continue;
    }
    const Figure& f = *block.figure;
    ++number;
    const std::string base = dir.path() + "/" + f.name;
    std::ostringstream script;
    script << "set terminal svg size " << f.width << "," << f.height
           << " dynamic enhanced font 'sans,10'\n"
           << "set output " << Q(base + ".svg") << "\n"
           << "set encoding utf8\nset datafile separator \"\\t\"\nset datafile missing '?'\n"
           << "set key noenhanced\nset border lc rgb '#444444'\nset grid lc rgb '#e3e3e3' lt 1\n"
           << "set clip two\n";
    for (size_t k = 0; k < f.data.size(); ++k) {
      const std::string file = base + "." + std::to_string(k) + ".dat";
      if (!WriteText(file, f.data[k])) {
        *error = "cannot write " + file;
        return false;
      }
      script << "d" << k << " = " << Q(file) << "\n";
    }
    script << f.script;
    if (!WriteText(base + ".gp", script.str())) {
      *error = "cannot write " + base + ".gp";
      return false;
    }
    if (!RunGnuplot(gnuplot, base + ".gp", base + ".log", error)) {
      *error += " (figure " + f.name + ")";
      return false;
    }
    const std::string svg = ReadText(base + ".svg");
    const std::string inline_svg = InlineSvg(svg, "f" + std::to_string(number) + "_", f.caption);
    if (inline_svg.empty()) {
      *error = "gnuplot wrote no SVG (figure " + f.name + ")";
      return false;
    }
    if (figures) figures->push_back({f.name, svg});
    body += "<figure id=\"" + Escape(f.name) +
            "\">\n<div style=\"max-width:" + std::to_string(f.width) + "px\">" + inline_svg +
            "</div>\n<figcaption><b>Figure " + std::to_string(number) + ".</b> " +
            Escape(f.caption) + "</figcaption>\n</figure>\n";
  }
  if (number == 0) body += "<p class=\"note\">This kind of report has no figures.</p>\n";
  *html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
      Escape(heading + (dataset.empty() ? "" : ": " + dataset)) + "</title>\n<style>\n" + kStyle +
      "</style>\n</head>\n<body>\n<h1>" +
      Escape(heading + (dataset.empty() ? "" : ": " + dataset)) + "</h1>\n<p class=\"meta\">" +
      Escape(title) + "</p>\n" + body + "</body>\n</html>\n";
  return true;
}

}  // namespace ringid
