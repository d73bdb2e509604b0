// The reusable CSV + gnuplot helper in console/plot/.
#include "console/plot/gnuplot_plot.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "robot/core/error.hpp"

namespace stride::plot {
namespace {

std::filesystem::path temp_dir() {
  const auto d = std::filesystem::temp_directory_path() / "stride_plot_test";
  std::filesystem::create_directories(d);
  return d;
}

TEST(GnuplotPlot, CsvHasHeaderRowsAndNaN) {
  Table t{{"t", "y"}, {}};
  t.add_row({0.0, 1.5});
  t.add_row({0.1, NAN});
  EXPECT_THROW(t.add_row({1.0}), Error);
  const std::string path = (temp_dir() / "t.csv").string();
  write_csv(path, t);
  std::ifstream in(path);
  std::string a, b, c;
  std::getline(in, a);
  std::getline(in, b);
  std::getline(in, c);
  EXPECT_EQ(a, "t,y");
  EXPECT_EQ(b, "0,1.5");
  EXPECT_EQ(c, "0.1,NaN");
}

TEST(GnuplotPlot, ScriptUsesColumnNumbersAndQuotes) {
  PlotSpec spec{"d.csv", "t",    {{"y", "it's y", ""}, {"v", "", "x"}}, "T", "t [s]",
                "y [m]", "o.png"};
  const std::string s = gnuplot_script(spec, {"t", "x", "y", "v"}, "png");
  EXPECT_NE(s.find("using 1:3"), std::string::npos) << s;
  EXPECT_NE(s.find("using 2:4"), std::string::npos) << s;
  EXPECT_NE(s.find("'it''s y'"), std::string::npos) << s;
  EXPECT_THROW(
      gnuplot_script({"d.csv", "t", {{"nope", "", ""}}, "T", "t [s]", "y [m]"}, {"t"}, "png"),
      Error);
}

TEST(GnuplotPlot, EveryAxisNamesItsUnit) {
  EXPECT_TRUE(labels_unit("t [s]"));
  EXPECT_TRUE(labels_unit("[rad]"));
  EXPECT_TRUE(labels_unit("K_p [-] "));
  EXPECT_FALSE(labels_unit("t"));
  EXPECT_FALSE(labels_unit("t []"));
  EXPECT_FALSE(labels_unit("[s] time"));
  PlotSpec spec{"d.csv", "t", {{"y", "", ""}}, "T", "t [s]", "y", "o.png"};
  try {
    gnuplot_script(spec, {"t", "y"}, "png");
    ADD_FAILURE() << "a y axis without a unit was drawn";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "plot o.png: y axis 'y' names no unit (expected e.g. 'angle [rad]'; one unit "
                 "per panel)");
  }
  spec.y_label = "y [m]";
  spec.x_label = "time";
  EXPECT_THROW(gnuplot_script(spec, {"t", "y"}, "png"), Error);
}

// Two units: two stacked panels sharing x, each with its own label and curves; a reference is a
// dashed line in its curve's colour (horizontal) or grey (vertical, at an x value).
TEST(GnuplotPlot, PanelsSplitUnitsAndReferencesAreDashedLines) {
  PlotSpec spec{"d.csv", "t", {}, "walk", "t [s]", "", "o.png"};
  spec.panels = {
      {"x [m]", {{"x", "torso x", ""}, {"z", "torso z", ""}}, {{0.3, "z true", false, 1}}, ""},
      {"angle [rad]", {{"pitch", "", ""}}, {{2.0, "start", true, -1}}, "[-1:1]"}};
  const std::string s = gnuplot_script(spec, {"t", "x", "z", "pitch"}, "png");
  EXPECT_NE(s.find("set multiplot layout 2,1"), std::string::npos) << s;
  EXPECT_NE(s.find("set ylabel 'x [m]'"), std::string::npos) << s;
  EXPECT_NE(s.find("set ylabel 'angle [rad]'"), std::string::npos) << s;
  EXPECT_LT(s.find("set ylabel 'x [m]'"), s.find("set ylabel 'angle [rad]'"));
  EXPECT_NE(s.find("using 1:3 with lines lw 2 lc 2 title 'torso z'"), std::string::npos) << s;
  EXPECT_NE(s.find("0.3 with lines dt 2 lw 1.5 lc 2 title 'z true'"), std::string::npos) << s;
  EXPECT_NE(s.find("set arrow from 2, graph 0 to 2, graph 1 nohead dt 2 lw 1.5 lc rgb '#555555'"),
            std::string::npos)
      << s;
  EXPECT_NE(s.find("set yrange [-1:1]"), std::string::npos) << s;
  EXPECT_NE(s.find("unset multiplot"), std::string::npos) << s;
  // Each panel's plot command draws only its own curves.
  const std::size_t second = s.find("set ylabel 'angle [rad]'");
  EXPECT_EQ(s.find("'torso x'", second), std::string::npos) << s;
}

TEST(GnuplotPlot, RendersAPng) {
  if (png_terminal().empty()) GTEST_SKIP() << "gnuplot with a png terminal not installed";
  Table t{{"t", "y"}, {}};
  for (int i = 0; i < 50; ++i) t.add_row({i * 0.1, std::sin(i * 0.1)});
  const auto dir = temp_dir();
  write_csv((dir / "sin.csv").string(), t);
  PlotSpec spec{(dir / "sin.csv").string(), "t", {{"y", "sin", ""}}, "sine", "t [s]", "y [-]",
                (dir / "sin.png").string()};
  render_png(spec);
  std::ifstream png(spec.png_path, std::ios::binary);
  char magic[4] = {};
  png.read(magic, 4);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace stride::plot
