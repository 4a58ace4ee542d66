// The toolkits of the HTML report: escaping, tables, data series, the shared
// figures' scripts and data, and the gnuplot runner's failures.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <string>

#include "apps/html/figure.h"
#include "apps/html/gnuplot.h"
#include "apps/html/page.h"
#include "estimation/uncertainty.h"
#include "tests/test_support.h"

namespace ringid::html {
namespace {

using ringid::testing::HaveProgram;
using ringid::testing::Scratch;

int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t i = text.find(what); i != std::string::npos; i = text.find(what, i + 1)) ++n;
  return n;
}

// The HTML of a page's blocks.
std::string Html(const Page& page) {
  std::string html;
  for (const auto& block : page.blocks()) html += block.html;
  return html;
}

// An executable shell script at a scratch path.
std::string FakeProgram(const std::string& name, const std::string& body) {
  const std::string path = Scratch(name);
  std::ofstream(path) << "#!/bin/sh\n" << body;
  ::chmod(path.c_str(), 0700);
  return path;
}

// ------------------------------------------------------------------- page

TEST(PageTest, EscapesEveryHtmlSpecialCharacter) {
  EXPECT_EQ(EscapeHtml(R"(<a href="x" title='y'>&amp;</a>)"),
            "&lt;a href=&quot;x&quot; title=&#39;y&#39;&gt;&amp;amp;&lt;/a&gt;");
  EXPECT_EQ(EscapeHtml("model − measured (Hz), χ²"), "model − measured (Hz), χ²");
}

TEST(PageTest, TableHasEveryRowAndMarksNumericCells) {
  Page page;
  page.Table({"mode", "f (Hz)"}, {{TextCell("vertical"), NumberCell(74.512, "%.2f")},
                                  {TextCell("<lateral>"), NumberCell(std::nullopt)},
                                  {TextCell("x"), NumberCell(3.0)}});
  const std::string html = Html(page);
  EXPECT_EQ(Count(html, "<tr>"), 4);  // the head and three rows
  EXPECT_NE(html.find("<tr><th>mode</th><th>f (Hz)</th></tr>"), std::string::npos);
  EXPECT_NE(html.find("<tr><td>vertical</td><td class=\"n\">74.51</td></tr>"), std::string::npos);
  EXPECT_NE(html.find("<tr><td>&lt;lateral&gt;</td><td class=\"n\">–</td></tr>"),
            std::string::npos);
  EXPECT_NE(html.find("<tr><td>x</td><td class=\"n\">3</td></tr>"), std::string::npos);
}

TEST(PageTest, NumbersNotAvailableShowAsADashAndFractionsAsPercent) {
  EXPECT_EQ(NumberCell(std::nan("")).text, "–");
  EXPECT_EQ(NumberCell(std::optional<double>(INFINITY)).text, "–");
  EXPECT_EQ(PercentCell(0.9998).text, "100.0");
  EXPECT_EQ(PercentCell(0.75, "%.0f").text, "75");
  EXPECT_EQ(NameCell(ringid::Identifiability::kPracticallyNo).text, "practically_no");
  EXPECT_EQ(YesNoCell(false).text, "no");
  EXPECT_EQ(ListCell({}).text, "–");
  EXPECT_EQ(ListCell({"a", "b"}).text, "a, b");
}

TEST(PageTest, TableWithoutRowsIsLeftOutWithItsHeading) {
  Page page;
  page.Table({"a"}, {});
  page.TableSection("Advice", {"a"}, {});
  EXPECT_TRUE(page.blocks().empty());
  page.TableSection("Advice", {"a"}, {{TextCell("b")}});
  EXPECT_EQ(Html(page),
            "<h2>Advice</h2>\n<table>\n<tr><th>a</th></tr>\n<tr><td>b</td></tr>\n</table>\n");
}

// ----------------------------------------------------------------- figure

TEST(SeriesTest, WritesMissingAndNonFiniteNumbersAsQuestionMarks) {
  Series s;
  EXPECT_TRUE(s.empty());
  s.Row({1, std::nullopt, NAN, INFINITY, 2.5, 1.0 / 3});
  s.Break();
  s.Row({-0.0});
  EXPECT_FALSE(s.empty());
  EXPECT_EQ(s.text(), "1\t?\t?\t?\t2.5\t0.333333333333\n\n-0\n");
}

TEST(FigureTest, GnuplotStringsDoubleQuotesAndBackquotes) {
  EXPECT_EQ(GnuplotString("it's `rm -rf`\n"), "'it''s ''rm -rf'' '");
  EXPECT_EQ(GnuplotString(""), "''");
  EXPECT_EQ(Tics({"a'b", "c"}), "('a''b' 0, 'c' 1)");
  EXPECT_EQ(Tics({"a", "b"}, true), "('' 0, '' 1)");
}

TEST(FigureTest, HeatMapOfATwoByTwoMatrix) {
  HeatMapOptions map;
  map.name = "test-map";
  map.rows = {"r0", "r1"};
  map.columns = {"c0", "c1"};
  map.values = {{0.5, std::nullopt}, {1.0, 0.25}};
  map.color_label = "MAC";
  const Figure f = HeatMap(map);
  EXPECT_EQ(f.name, "test-map");
  EXPECT_EQ(f.width, 520);  // the smallest
  EXPECT_EQ(f.height, 300);
  ASSERT_EQ(f.data.size(), 1u);
  EXPECT_EQ(f.data[0], "0\t0\t0.5\n0\t1\t1\n1\t1\t0.25\n");  // column, row, value; no empty cell
  for (const char* line : {"set xrange [-0.5:1.5]\nset yrange [1.5:-0.5]\n",
                           "set xtics noenhanced scale 0 ('c0' 0, 'c1' 1)\n",
                           "set ytics noenhanced scale 0 ('r0' 0, 'r1' 1)\n", "set cbrange [0:1]\n",
                           "set cblabel 'MAC'\n",
                           "plot d0 using 1:2:(0.5):(0.5):3 with boxxyerror lc palette, "
                           "d0 using 1:2:(sprintf('%.2f', $3))"}) {
    EXPECT_NE(f.script.find(line), std::string::npos) << line << "\nin:\n" << f.script;
  }
  map.print_values = false;
  EXPECT_EQ(HeatMap(map).script.find("sprintf"), std::string::npos);
}

TEST(FigureTest, FrequencyFigureOfTwoModes) {
  FrequencyFigureOptions o;
  o.name = "test-frequencies";
  o.reference_title = "measured";
  o.band_title = "band";
  o.reference_name = "measured";
  o.AddMode("in_phase", 50.0, 0.1, 50.25);
  o.AddMode("vertical", 60.0, std::nullopt, std::nullopt);
  const auto f = FrequencyFigure(o);
  ASSERT_TRUE(f);
  EXPECT_EQ(f->height, 150 + 34 * 2);
  ASSERT_EQ(f->data.size(), 1u);
  // index, reference, half-width, model, model − reference.
  EXPECT_EQ(f->data[0], "0\t50\t0.1\t50.25\t0.25\n1\t60\t?\t?\t?\n");
  for (const char* line :
       {"set yrange [1.5:-0.5]\n", "set ytics noenhanced ('in phase' 0, 'vertical' 1)\n",
        "set xrange [-0.325:0.325]\n",  // 1.3 × the largest |difference|
        "set xlabel 'model − measured (Hz)'\n", "title 'band'"}) {
    EXPECT_NE(f->script.find(line), std::string::npos) << line << "\nin:\n" << f->script;
  }
  FrequencyFigureOptions none;
  none.AddMode("x", std::nullopt, 0.1, std::nullopt);
  EXPECT_FALSE(FrequencyFigure(none));
}

TEST(FigureTest, LogTicsAreDecadesOrRoundValues) {
  EXPECT_EQ(LogTics(1, 1e6), "set xtics ('1' 1, '100' 100, '1e+04' 10000, '1e+06' 1000000)\n");
  EXPECT_EQ(LogTics(1, 50), "set xtics ('1' 1, '2' 2, '5' 5, '10' 10, '20' 20, '50' 50)\n");
  EXPECT_EQ(LogTics(2, 3),
            "set xtics ('2' 2, '2.2' 2.2, '2.4' 2.4, '2.6' 2.6, '2.8' 2.8, '3' 3)\n");
}

TEST(FigureTest, CategoryTicsRotateOnlyLabelsTooLongForTheirRoom) {
  EXPECT_EQ(CategoryXTics({"a", "b"}, 100, -35), "set xtics noenhanced ('a' 0, 'b' 1)\n");
  EXPECT_EQ(CategoryXTics({"a long label", "b"}, 100, -25, false),
            "set xtics noenhanced scale 0 rotate by -25 left ('a long label' 0, 'b' 1)\n");
}

TEST(FigureTest, BarPanelLeavesOutBarsThatAreNotFinite) {
  Figure f("test-bars");
  BarPanelOptions o;
  o.labels = {"a", "b", "c"};
  o.bars = {{0, 1}, {0, NAN}, {1, 2}};
  o.highlight = {true, false, false};
  o.x_label = "x";
  const std::string panel = BarPanel(&f, o);
  ASSERT_EQ(f.data.size(), 2u);
  EXPECT_EQ(f.data[0], "0\t0\t1\n");  // highlighted
  EXPECT_EQ(f.data[1], "2\t1\t2\n");  // grey
  EXPECT_NE(panel.find("plot d0 using"), std::string::npos);
  EXPECT_NE(panel.find("lc rgb '#2ca02c', d1 using"), std::string::npos);
  EXPECT_NE(panel.find("lc rgb '#9a9a9a'\n"), std::string::npos);
}

// ---------------------------------------------------------------- gnuplot

TEST(GnuplotTest, InlineSvgPrefixesItsOwnIdsAndNamesTheFigure) {
  const std::string svg =
      "<?xml version=\"1.0\"?>\n<svg width='10'><defs><path id='gpPt0'/></defs>"
      "<use xlink:href='#gpPt0' fill='#ffffff'/><g id=\"plot\"></g></svg>\n\n";
  EXPECT_EQ(InlineSvg(svg, "f2_", "a < b & \"c\""),
            "<svg role=\"img\" aria-label=\"a &lt; b &amp; &quot;c&quot;\" width='10'><defs>"
            "<path id='f2_gpPt0'/></defs><use xlink:href='#f2_gpPt0' fill='#ffffff'/>"
            "<g id=\"f2_plot\"></g></svg>");
  EXPECT_EQ(InlineSvg("no picture", "f1_", ""), "");
}

TEST(GnuplotTest, FailingScriptIsAnErrorNamingItsLine) {
  RINGID_REQUIRE_TOOL(HaveProgram("gnuplot"), "gnuplot");
  std::string gnuplot;
  ASSERT_TRUE(FindGnuplot(&gnuplot));
  const std::string script = Scratch("bad.gp");
  std::ofstream(script) << "set terminal svg\nset output '/dev/null'\nplot sin(x) with nonsense\n";
  std::string error;
  EXPECT_FALSE(RunGnuplot({gnuplot, script, Scratch("bad.log")}, &error));
  EXPECT_EQ(error.rfind("gnuplot failed: ", 0), 0u) << error;
  EXPECT_NE(error.find("line 3: unrecognized plot type"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

TEST(GnuplotTest, ExitOneIsAnErrorWithTheLineThatNamesTheError) {
  const std::string fake = FakeProgram(
      "fake_gnuplot_exit1", "echo 'plot x'\necho '   ^'\necho 'line 1: Error here'\nexit 1\n");
  std::string error;
  EXPECT_FALSE(RunGnuplot({fake, "script.gp", Scratch("exit1.log")}, &error));
  EXPECT_EQ(error, "gnuplot failed: line 1: Error here");
}

TEST(GnuplotTest, SlowGnuplotIsKilledAtTheTimeout) {
  const std::string fake = FakeProgram("fake_gnuplot_slow", "exec sleep 30\n");
  std::string error;
  const auto start = std::chrono::steady_clock::now();
  GnuplotRun run{fake, "script.gp", Scratch("slow.log")};
  run.timeout_seconds = 1;
  EXPECT_FALSE(RunGnuplot(run, &error));
  EXPECT_EQ(error, "gnuplot took longer than 1 s");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
}

TEST(GnuplotTest, MissingProgramCannotRun) {
  std::string error;
  EXPECT_FALSE(RunGnuplot({"/nonexistent/gnuplot", "script.gp", Scratch("none.log")}, &error));
  EXPECT_EQ(error.rfind("cannot run /nonexistent/gnuplot: ", 0), 0u) << error;
}

TEST(GnuplotTest, DrawSvgDrawsAHeatMap) {
  RINGID_REQUIRE_TOOL(HaveProgram("gnuplot"), "gnuplot");
  std::string gnuplot;
  ASSERT_TRUE(FindGnuplot(&gnuplot));
  HeatMapOptions map;
  map.name = "test-draw";
  map.rows = {"r0"};
  map.columns = {"c0", "c1"};
  map.values = {{0.25, 0.75}};
  TempDir dir;
  ASSERT_FALSE(dir.path().empty());
  std::string svg, error;
  ASSERT_TRUE(DrawSvg(gnuplot, HeatMap(map), dir.path(), &svg, &error)) << error;
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find(">0.25<"), std::string::npos);  // the printed cells
  EXPECT_NE(svg.find(">0.75<"), std::string::npos);
  EXPECT_NE(svg.find("gnuplot_plot_1"), std::string::npos);
}

}  // namespace
}  // namespace ringid::html
