#include "apps/html/figure.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "apps/html/text.h"

namespace ringid::html {

void Series::Row(std::initializer_list<std::optional<double>> values) {
  bool first = true;
  for (const auto& value : values) {
    text_ += first ? "" : "\t";
    text_ += value && std::isfinite(*value) ? Format(*value, "%.12g") : "?";
    first = false;
  }
  text_ += "\n";
  ++rows_;
}

void Series::Break() { text_ += "\n"; }

std::string Figure::AddData(const Series& series) {
  data.push_back(series.text());
  return "d" + std::to_string(data.size() - 1);
}

std::string GnuplotString(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'' || c == '`')
      out += "''";
    else if (static_cast<unsigned char>(c) < 0x20)
      out += ' ';
    else
      out += c;
  }
  return out + "'";
}

std::string Pretty(const std::string& label) {
  std::string out;
  for (char c : label) out += (c == '_' || static_cast<unsigned char>(c) < 0x20) ? ' ' : c;
  if (out.size() > 40) out = out.substr(0, 37) + "...";
  return out;
}

std::vector<std::string> Pretty(const std::vector<std::string>& labels) {
  std::vector<std::string> out;
  for (const std::string& label : labels) out.push_back(Pretty(label));
  return out;
}

std::string Tics(const std::vector<std::string>& labels, bool blank) {
  std::string out = "(";
  for (size_t i = 0; i < labels.size(); ++i) {
    const std::string& label = labels[i];
    const std::string shown = label.size() > 40 ? label.substr(0, 37) + "..." : label;
    out += (i ? ", " : "") + GnuplotString(blank ? "" : shown) + " " + std::to_string(i);
  }
  return out + ")";
}

std::string CategoryXTics(const std::vector<std::string>& labels, double room, int angle,
                          bool tic_marks) {
  size_t longest = 0;
  for (const std::string& label : labels) longest = std::max(longest, label.size());
  const bool rotate =
      longest * 6.5 > room / std::max<double>(static_cast<double>(labels.size()), 1);
  return std::string("set xtics noenhanced ") + (tic_marks ? "" : "scale 0 ") +
         (rotate ? "rotate by " + std::to_string(angle) + " left " : "") + Tics(labels) + "\n";
}

std::string LogTics(double low, double high) {
  std::vector<double> at;
  const int first = static_cast<int>(std::floor(std::log10(low))),
            last = static_cast<int>(std::ceil(std::log10(high)));
  const auto keep = [&](double t) {
    if (t >= low && t <= high) at.push_back(t);
  };
  if (high / low >= 1000) {
    const int every = std::max(1, (last - first + 4) / 5);
    for (int k = first; k <= last; k += every) keep(std::pow(10.0, k));
  } else if (high / low >= 10) {
    for (int k = first; k <= last; ++k) {
      for (double m : {1, 2, 5}) keep(m * std::pow(10.0, k));
    }
  } else {
    const double raw = (high - low) / 2.5;
    const double base = std::pow(10.0, std::floor(std::log10(raw)));
    const double step = raw / base < 2 ? base : raw / base < 5 ? 2 * base : 5 * base;
    for (double t = std::ceil(low / step) * step; t <= high * (1 + 1e-12); t += step)
      at.push_back(t);
  }
  std::string out = "set xtics (";
  for (size_t i = 0; i < at.size(); ++i) {
    out += (i ? ", " : "") + GnuplotString(Format(at[i], "%.3g")) + " " + Format(at[i], "%.12g");
  }
  return out + ")\n";
}

std::string HorizontalLine(int id, const std::string& y, const std::string& style) {
  return "set arrow " + std::to_string(id) + " from graph 0, first " + y + " to graph 1, first " +
         y + " nohead " + style + "\n";
}

std::string VerticalLine(int id, const std::string& x, const std::string& style) {
  return "set arrow " + std::to_string(id) + " from " + x + ", graph 0 to " + x +
         ", graph 1 nohead " + style + "\n";
}

std::string ScreenMargins(const Figure& figure, double top, double bottom) {
  std::ostringstream out;
  out << "set tmargin at screen " << 1 - top / figure.height << "\nset bmargin at screen "
      << bottom / figure.height << "\n";
  return out.str();
}

std::string PlotCommand(const std::vector<std::string>& parts) {
  return parts.empty() ? "" : "plot " + Join(parts, ", ") + "\n";
}

std::string HorizontalBars(const std::string& data, const std::string& color) {
  return data + " using (($2+$3)/2):1:2:3:($1-0.32):($1+0.32) with boxxyerror lc rgb '" + color +
         "'";
}

void FrequencyFigureOptions::AddMode(const std::string& label, std::optional<double> reference_hz,
                                     std::optional<double> half_width_hz,
                                     std::optional<double> model_hz) {
  labels.push_back(label);
  reference.push_back(reference_hz);
  half_width.push_back(half_width_hz);
  model.push_back(model_hz);
}

namespace {

// The data of a frequency figure, and the half-range of its right panel.
Series FrequencyRows(const FrequencyFigureOptions& o, double* span, bool* any) {
  Series rows;
  for (size_t i = 0; i < o.labels.size(); ++i) {
    std::optional<double> diff;
    if (o.reference[i] && o.model[i]) diff = *o.model[i] - *o.reference[i];
    rows.Row({static_cast<double>(i), o.reference[i], o.half_width[i], o.model[i], diff});
    *any |= o.reference[i].has_value() || o.model[i].has_value();
    if (diff) *span = std::max(*span, std::fabs(*diff));
    if (o.half_width[i]) *span = std::max(*span, std::fabs(*o.half_width[i]));
  }
  return rows;
}

}  // namespace

std::optional<Figure> FrequencyFigure(const FrequencyFigureOptions& o) {
  const int n = static_cast<int>(o.labels.size());
  double span = 0;
  bool any = false;
  const Series rows = FrequencyRows(o, &span, &any);
  if (!any) return std::nullopt;
  if (!(span > 0)) span = 1;
  span *= 1.3;
  Figure f(o.name, 900, 150 + 34 * n);
  const std::string d = f.AddData(rows);
  const std::string difference = "model − " + o.reference_name;
  std::ostringstream g;
  g << "set multiplot\n"
    << ScreenMargins(f, 50, 55) << "set yrange [" << n - 0.5 << ":-0.5]\n"
    << "set grid xtics ytics\n"
    << "set key at graph 0.5, graph 1.02 center bottom vertical\n"
    << "set offsets graph 0.06, graph 0.06, 0, 0\n"
    << "set lmargin at screen 0.17\nset rmargin at screen 0.55\n"
    << "set ytics noenhanced " << Tics(Pretty(o.labels)) << "\n"
    << "set xlabel 'frequency (Hz)'\n"
    << "plot " << d << " using 2:1:3 with xerrorbars pt 7 ps 0.8 lc rgb '" << kBlue << "' title "
    << GnuplotString(o.reference_title) << ", " << d
    << " using 4:1 with points pt 2 ps 1.5 lw 1.5 lc rgb '" << kOrange << "' title 'model'\n"
    << "set lmargin at screen 0.61\nset rmargin at screen 0.97\n"
    << "set offsets 0, 0, 0, 0\n"
    << "set ytics " << Tics(o.labels, true) << "\n"
    << "set xrange [" << -span << ":" << span << "]\n"
    << VerticalLine(1, "0", kDashedGrey) << "set xlabel " << GnuplotString(difference + " (Hz)")
    << "\n"
    << "plot " << d << " using (0):1:3 with xerrorbars pt 7 ps 0 lw 2 lc rgb '" << kBlue
    << "' title " << GnuplotString(o.band_title) << ", " << d
    << " using 5:1 with points pt 2 ps 1.5 lw 1.5 lc rgb '" << kOrange << "' title "
    << GnuplotString(difference) << "\n"
    << "unset multiplot\n";
  f.script = g.str();
  return f;
}

Figure HeatMap(const HeatMapOptions& o) {
  const int rows = static_cast<int>(o.rows.size()), columns = static_cast<int>(o.columns.size());
  Figure f(o.name, std::clamp(260 + 62 * columns, 520, 1000),
           std::clamp(190 + 34 * rows, 300, 1000));
  Series cells;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      if (o.values[r][c]) cells.Row({c, r, o.values[r][c]});
    }
  }
  const std::string d = f.AddData(cells);
  std::ostringstream g;
  g << "unset grid\nunset key\n"
    << "set object 1 rectangle from graph 0, graph 0 to graph 1, graph 1 behind fc rgb '#eeeeee' "
       "fs solid noborder\n"
    << "set xrange [-0.5:" << columns - 0.5 << "]\nset yrange [" << rows - 0.5 << ":-0.5]\n"
    << CategoryXTics(o.columns, f.width - 250.0, -35, false) << "set ytics noenhanced scale 0 "
    << Tics(o.rows) << "\n"
    << "set cbrange [" << o.low << ":" << o.high << "]\n"
    << "set palette defined " << o.palette << "\n"
    << "set xlabel " << GnuplotString(o.x_label) << "\nset ylabel " << GnuplotString(o.y_label)
    << "\nset cblabel " << GnuplotString(o.color_label) << "\n"
    << "set style fill solid 1.0 noborder\n"
    << "plot " << d << " using 1:2:(0.5):(0.5):3 with boxxyerror lc palette";
  if (o.print_values) {
    const double mid = o.low + 0.6 * (o.high - o.low);
    g << ", " << d << " using 1:2:(sprintf(" << GnuplotString(o.cell_format) << ", $3)):(abs($3) > "
      << (o.low < 0 ? 0.6 * o.high : mid) << " ? 0xffffff : 0x222222) with labels tc rgb variable";
  }
  g << "\n";
  f.script = g.str();
  return f;
}

std::string BarPanel(Figure* figure, const BarPanelOptions& o) {
  Series on, off;
  for (size_t i = 0; i < o.bars.size(); ++i) {
    const auto [from, to] = o.bars[i];
    if (!std::isfinite(from) || !std::isfinite(to)) continue;
    (o.highlight[i] ? on : off).Row({static_cast<double>(i), from, to});
  }
  std::ostringstream g;
  g << "set lmargin at screen " << o.left << "\nset rmargin at screen " << o.right << "\n"
    << "set ytics noenhanced " << Tics(o.labels, !o.show_labels) << "\n"
    << "set xlabel " << GnuplotString(o.x_label) << "\n"
    << (o.log_x ? "set logscale x\n" : "unset logscale x\n");
  std::vector<std::string> parts;
  if (!on.empty()) parts.push_back(HorizontalBars(figure->AddData(on), o.highlight_color));
  if (!off.empty()) parts.push_back(HorizontalBars(figure->AddData(off), kGrey));
  return g.str() + PlotCommand(parts);
}

}  // namespace ringid::html
