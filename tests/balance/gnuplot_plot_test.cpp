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
  PlotSpec spec{"d.csv", "t", {{"y", "it's y", ""}, {"v", "", "x"}}, "T", "t", "y", "o.png"};
  const std::string s = gnuplot_script(spec, {"t", "x", "y", "v"}, "png");
  EXPECT_NE(s.find("using 1:3"), std::string::npos) << s;
  EXPECT_NE(s.find("using 2:4"), std::string::npos) << s;
  EXPECT_NE(s.find("'it''s y'"), std::string::npos) << s;
  EXPECT_THROW(gnuplot_script({"d.csv", "t", {{"nope", "", ""}}}, {"t"}, "png"), Error);
}

TEST(GnuplotPlot, RendersAPng) {
  if (png_terminal().empty()) GTEST_SKIP() << "gnuplot with a png terminal not installed";
  Table t{{"t", "y"}, {}};
  for (int i = 0; i < 50; ++i) t.add_row({i * 0.1, std::sin(i * 0.1)});
  const auto dir = temp_dir();
  write_csv((dir / "sin.csv").string(), t);
  PlotSpec spec{(dir / "sin.csv").string(), "t", {{"y", "sin", ""}}, "sine", "t", "y",
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
