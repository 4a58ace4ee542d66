// Finding and running gnuplot, and inlining the SVG it draws.
#ifndef RINGID_APPS_HTML_GNUPLOT_H_
#define RINGID_APPS_HTML_GNUPLOT_H_

#include <string>

#include "apps/html/figure.h"

namespace ringid::html {

inline constexpr double kGnuplotSeconds = 120;

// A private temporary directory, removed with its files; path() is empty
// when it could not be made.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// The first executable "gnuplot" on PATH.
bool FindGnuplot(std::string* path);

// One run of `program -d script`, its output (stdout and stderr) in `log`.
struct GnuplotRun {
  std::string program;
  std::string script;
  std::string log;
  double timeout_seconds = kGnuplotSeconds;
};
// False with a one-line error when gnuplot cannot start, fails (the line of
// its log that names the error) or takes longer than the timeout (killed).
bool RunGnuplot(const GnuplotRun& run, std::string* error);

// Draws `figure` with `program` in `dir` (files named after the figure).
bool DrawSvg(const std::string& program, const Figure& figure, const std::string& dir,
             std::string* svg, std::string* error);

// gnuplot's SVG for inlining in HTML: from "<svg" on, ids prefixed with
// `id_prefix` so that figures can share a page, labelled for screen readers.
// "" when there is no <svg.
std::string InlineSvg(const std::string& svg, const std::string& id_prefix,
                      const std::string& label);

}  // namespace ringid::html

#endif  // RINGID_APPS_HTML_GNUPLOT_H_
