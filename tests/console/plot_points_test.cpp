// Issue 49 point 5: what `plot stop` draws. Angles are unwrapped (no wall of +-pi spikes), a long
// recording is drawn from a min/max envelope (a compact .gp that keeps the peaks), long key names
// go in a legend below the graph without their "representation:", and debug values carry their
// unit and share the axis of the same quantity in radians.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "console/interpreter/console_plot.hpp"
#include "console/interpreter/interpreter.hpp"
#include "console/interpreter/key_units.hpp"
#include "console/target/local_target.hpp"

namespace stride::console {
namespace {

namespace fs = std::filesystem;

TEST(ConsolePlot, AnglesAreUnwrappedOtherColumnsNot) {
  plot::Table t{{"t", "yaw", "x"}, {}};
  const double a[] = {3.0, 3.1, -3.1, -3.0, 3.1};  // across +-pi twice
  for (int i = 0; i < 5; ++i) t.add_row({0.1 * i, a[i], a[i]});
  unwrap_angles(t, {"rad", "m"});
  EXPECT_DOUBLE_EQ(t.rows[2][1], -3.1 + 2 * M_PI);
  EXPECT_DOUBLE_EQ(t.rows[3][1], -3.0 + 2 * M_PI);
  EXPECT_DOUBLE_EQ(t.rows[4][1], 3.1);  // back the other way
  for (int i = 0; i < 5; ++i) {
    EXPECT_DOUBLE_EQ(t.rows[i][2], a[i]);  // metres stay as they were
    if (i > 0) EXPECT_LT(std::abs(t.rows[i][1] - t.rows[i - 1][1]), 0.3);
  }
}

TEST(ConsolePlot, ALongRecordingIsAnEnvelopeThatKeepsItsPeaks) {
  plot::Table t{{"t", "v"}, {}};
  for (int i = 0; i < 100000; ++i) t.add_row({i * 1e-3, i == 54321 ? 7.0 : std::sin(i * 1e-3)});
  const plot::Table d = decimated(t, 4000);
  EXPECT_LE(d.rows.size(), 4002u);
  EXPECT_GE(d.rows.size(), 3000u);
  double peak = 0;
  for (const auto& r : d.rows) peak = std::max(peak, r[1]);
  EXPECT_EQ(peak, 7.0);
  EXPECT_EQ(d.rows.front()[0], 0.0);
  EXPECT_EQ(d.rows.back()[0], t.rows.back()[0]);
  EXPECT_EQ(decimated(d, 5000).rows.size(), d.rows.size());  // short enough: as it is
}

TEST(ConsolePlot, DebugValuesSayTheirUnitByName) {
  EXPECT_EQ(unit_of_debug_value("pitch"), "rad");
  EXPECT_EQ(unit_of_debug_value("measured_roll_rate"), "rad/s");
  EXPECT_EQ(unit_of_debug_value("zmp_x"), "m");
  EXPECT_EQ(unit_of_debug_value("gain"), "");
  EXPECT_EQ(legend_label("representation:TorsoState.pitch"), "TorsoState.pitch");
  EXPECT_EQ(legend_label(std::string(50, 'a')).size(), 36u);
}

TEST(ConsolePlot, PlotStopDrawsOneRadianAxisBelowLegendCompactly) {
  const fs::path dir =
      fs::temp_directory_path() / ("stride_plot_points_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  LocalTarget target;
  std::ostringstream out;
  Interpreter console(target, out);
  console.execute("load " STRIDE_SOURCE_DIR "/scenes/experiments/hip_medium.xml");
  console.execute("dr posture:kalman quiet");
  console.execute(
      "plot robot.torso.pitch debug:posture:kalman.pitch "
      "representation:TorsoState.pitch to " +
      (dir / "p.csv").string());
  console.execute("step 6000");
  console.execute("plot stop");
  std::ifstream gp(dir / "p.gp");
  std::stringstream text;
  text << gp.rdbuf();
  const std::string s = text.str();
  EXPECT_NE(s.find("set key outside below"), std::string::npos);
  EXPECT_EQ(s.find("multiplot"), std::string::npos) << "one axis: every key is in radians";
  EXPECT_NE(s.find("set ylabel '[rad]'"), std::string::npos);
  EXPECT_NE(s.find("title 'TorsoState.pitch'"), std::string::npos);
  EXPECT_NE(s.find("title 'debug:posture:kalman.pitch'"), std::string::npos);
  EXPECT_EQ(s.find("representation:"), std::string::npos);
  int data_lines = 0;  // rows in the .gp's datablocks: three envelopes, not 3 x 6000 rows
  bool in_block = false;
  std::istringstream lines(s);
  for (std::string line; std::getline(lines, line);) {
    if (line == "EOD") in_block = false;
    if (in_block) ++data_lines;
    if (line.ends_with("<< EOD")) in_block = true;
  }
  EXPECT_GT(data_lines, 3 * 2000);
  EXPECT_LE(data_lines, 3 * 4002);
  std::ifstream csv(dir / "p.csv");
  int rows = -1;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_EQ(rows, 6000);  // the CSV keeps every row
  EXPECT_TRUE(fs::exists(dir / "p.png"));
  EXPECT_FALSE(fs::exists(dir / "p.drawn.csv"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace stride::console
