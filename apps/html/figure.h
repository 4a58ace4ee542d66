// The figure toolkit: a figure is gnuplot data files and a script; shared
// builders take option structs.
#ifndef RINGID_APPS_HTML_FIGURE_H_
#define RINGID_APPS_HTML_FIGURE_H_

#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ringid::html {

inline constexpr char kBlue[] = "#1f77b4";
inline constexpr char kOrange[] = "#e6791c";
inline constexpr char kGreen[] = "#2ca02c";
inline constexpr char kRed[] = "#d62728";
inline constexpr char kGrey[] = "#9a9a9a";
// Styles of reference lines.
inline constexpr char kDashedGrey[] = "dt 2 lc rgb '#888888'";
inline constexpr char kAxisLine[] = "lc rgb '#555555'";

// Rows of numbers for one data file, tab separated; a missing number is '?'.
class Series {
 public:
  void Row(std::initializer_list<std::optional<double>> values);
  void Break();  // a blank line: ends a line segment
  bool empty() const { return rows_ == 0; }
  const std::string& text() const { return text_; }

 private:
  std::string text_;
  int rows_ = 0;
};

// Data files d0, d1, ... and the gnuplot script that plots them.
struct Figure {
  Figure() = default;
  explicit Figure(std::string name, int width = 900, int height = 420)
      : name(std::move(name)), width(width), height(height) {}
  // Adds `series` as the next data file; returns its gnuplot variable.
  std::string AddData(const Series& series);

  std::string name;     // KIND-WHAT, the file stem with --figures_dir
  std::string caption;  // what is plotted, in which units
  int width = 900;
  int height = 420;
  std::vector<std::string> data;
  std::string script;
};

// A gnuplot single-quoted string: '' for a quote, no backquote substitution,
// control characters as spaces.
std::string GnuplotString(const std::string& text);
// A label for a figure: underscores read as spaces, at most 40 characters.
std::string Pretty(const std::string& label);
std::vector<std::string> Pretty(const std::vector<std::string>& labels);
// gnuplot tic marks at 0, 1, ... named by `labels` (or blank).
std::string Tics(const std::vector<std::string>& labels, bool blank = false);

// "set xtics noenhanced ..." for one tic per label, rotated by `angle`
// degrees when the longest label needs more than `room` / labels pixels.
std::string CategoryXTics(const std::vector<std::string>& labels, double room, int angle,
                          bool tic_marks = true);
// "set xtics (...)" for a log axis over [low, high], 0 < low < high: decades,
// or round values where gnuplot would show none.
std::string LogTics(double low, double high);
// A line across the graph at y (or x), drawn with `style`.
std::string HorizontalLine(int id, const std::string& y, const std::string& style);
std::string VerticalLine(int id, const std::string& x, const std::string& style);
// Fixed top and bottom margins, in pixels, for a multiplot.
std::string ScreenMargins(const Figure& figure, double top, double bottom);
// "plot A, B\n", or "" without parts.
std::string PlotCommand(const std::vector<std::string>& parts);
// One plot of horizontal bars from $2 to $3 at row $1.
std::string HorizontalBars(const std::string& data, const std::string& color);

// Reference (± a half-width) and model frequency per mode: Hz on the left,
// model − reference on the right. None when no frequency is known.
struct FrequencyFigureOptions {
  std::string name;
  std::vector<std::string> labels;
  std::vector<std::optional<double>> reference, half_width, model;
  std::string reference_title;  // the key of the reference points
  std::string band_title;       // the key of the half-width around 0
  std::string reference_name;   // as in "model − measured (Hz)"

  void AddMode(const std::string& label, std::optional<double> reference_hz,
               std::optional<double> half_width_hz, std::optional<double> model_hz);
};
std::optional<Figure> FrequencyFigure(const FrequencyFigureOptions& options);

// values[row][column] as coloured cells, missing cells grey.
struct HeatMapOptions {
  std::string name;
  std::vector<std::string> rows, columns;
  std::vector<std::vector<std::optional<double>>> values;
  double low = 0, high = 1;
  std::string palette = "(0 '#ffffff', 1 '#08519c')";
  std::string cell_format = "%.2f";  // the value printed in each cell
  std::string x_label, y_label, color_label;
  bool print_values = true;
};
Figure HeatMap(const HeatMapOptions& options);

// One panel of a multiplot: a horizontal bar per row, between the screen
// margins `left` and `right`; non-finite bars are left out.
struct BarPanelOptions {
  std::vector<std::string> labels;
  std::vector<std::pair<double, double>> bars;  // from, to
  std::vector<bool> highlight;
  double left = 0.2, right = 0.56;
  std::string x_label;
  bool show_labels = true;
  bool log_x = false;
  std::string highlight_color = kGreen;  // others are grey
};
std::string BarPanel(Figure* figure, const BarPanelOptions& options);

}  // namespace ringid::html

#endif  // RINGID_APPS_HTML_FIGURE_H_
