// The issue-31 figures from a sweep's output: the push map's cells counted from runs.csv (failed
// and unpushed walks left out), the phase portrait's curves in the capture-point form, and the
// landing study's FSR window.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "console/experiments/figure_index.hpp"
#include "console/experiments/landing_figures.hpp"
#include "console/experiments/push_figures.hpp"
#include "console/plot/gnuplot_plot.hpp"
#include "robot/core/error.hpp"
#include "tests/error_text.hpp"

namespace stride::experiments {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("stride_push_figures_" + name);
  fs::remove_all(d);
  fs::create_directories(d / "traces");
  return d;
}

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

std::string read(const fs::path& path) {
  std::ostringstream s;
  s << std::ifstream(path).rdbuf();
  return s.str();
}

constexpr const char* kRecoveryRuns =
    "run,scene,control,push,N,dir,phase,seed,status,fell,tipped,distance,lost,reason\n"
    "0,w.xml,posture,0,0,none,0,1,ok,0,none,0.9,0,\n"
    "1,w.xml,posture,fwd10,10,forward,0,1,ok,0,none,0.9,0,\n"
    "2,w.xml,posture,fwd10,10,forward,0,2,ok,1,backward,0.2,1,\n"
    "3,w.xml,posture,fwd10,10,forward,0.25,1,ok,0,forward,0.3,1,\n"
    "4,w.xml,posture,fwd10,10,forward,0.25,2,failed,,,,,\"ODE: bad\"\n"
    "5,w.xml,recovery,left20,20,left,0.5,1,ok,1,right,0.1,1,\n";

void write_portrait_runs(const fs::path& d) {
  const std::string bounds = "6,-0.06,0.1,-0.02,0.03,-0.08,0.13";
  write(d / "runs.csv",
        "run,control,impulse,seed,status,fell,recovered,omega,ankle_lo,ankle_hi,hip_lo,hip_hi,"
        "combined_lo,combined_hi\n"
        "0,position,-3,1,ok,1,0," +
            bounds +
            "\n"
            "1,position,0.5,1,ok,0,1," +
            bounds +
            "\n"  // not an impulse the portrait draws
            "2,position,2,1,ok,0,1," +
            bounds + "\n");
  for (const char* run : {"0", "1", "2"})
    write(d / "traces" / ("run-" + std::string(run) + ".csv"),
          "t,x,xdot,capture_point\n1.45,0.01,0.3,0.06\n1.46,0.012,0.2,0.045\n");
  write(d / "traces" / "run-2.csv", "t,x,xdot,capture_point\n1.45,0.02,-0.1,0.0033\n");
}

void write_landing_runs(const fs::path& d) {
  write(d / "runs.csv",
        "run,scene,landing,floor_mm,speed,seed,status,impulse\n"
        "0,l.xml,off,3,medium,1,ok,1.6\n1,l.xml,on,3,medium,1,ok,1.5\n"
        "2,l.xml,on,3,fast,1,ok,1.5\n");  // not traced
  // 0.4 s frames from 6 s: 6, 6.4, 6.8 lie within the second, 7.2 not.
  for (const char* run : {"0", "1"})
    write(d / "traces" / ("run-" + std::string(run) + ".csv"),
          "t,fsr_left,fsr_right\n6,0,25\n6.4,25,0\n6.8,48.5,0\n7.2,0,30\n");
}

TEST(StudyFigures, TheMapCountsWalksLostPerPushPhaseAndControl) {
  const fs::path d = fresh_dir("map");
  write(d / "runs.csv", kRecoveryRuns);
  const RunsCsv runs = read_runs_csv(d.string());
  EXPECT_EQ(runs.rows.size(), 5u);  // the failed walk is left out
  const std::vector<MapCell> cells = push_map_cells(runs);
  ASSERT_EQ(cells.size(), 3u);  // the unpushed walk is no cell
  EXPECT_EQ(cells[0].control, "posture");
  EXPECT_EQ(cells[0].direction, "forward");
  EXPECT_EQ(cells[0].push, 10);
  EXPECT_EQ(cells[0].phase, 0);
  EXPECT_EQ(cells[0].walks, 2);
  EXPECT_EQ(cells[0].lost, 1);
  EXPECT_EQ(cells[1].phase, 0.25);
  EXPECT_EQ(cells[1].walks, 1);
  EXPECT_EQ(cells[1].lost, 1);
  EXPECT_EQ(cells[2].control, "recovery");
  EXPECT_EQ(cells[2].direction, "left");
  EXPECT_EQ(cells[2].push, 20);
  write_push_map(d.string(), false);
  EXPECT_EQ(read(d / "push_map.csv"),
            "control,dir,N,phase,walks,lost\n"
            "posture,forward,10,0,2,1\n"
            "posture,forward,10,0.25,1,1\n"
            "recovery,left,20,0.5,1,1\n");
  fs::remove_all(d);
}

TEST(StudyFigures, AMissingColumnIsNamedWithTheFile) {
  const fs::path d = fresh_dir("missing");
  write(d / "runs.csv", "run,control,N,dir,status,lost\n0,posture,10,forward,ok,0\n");
  const std::string e = test_support::error_of([&] { write_push_map(d.string(), false); });
  EXPECT_NE(e.find("runs.csv: no column 'phase'"), std::string::npos) << e;
  fs::remove_all(d);
}

TEST(StudyFigures, ThePortraitTakesSeedOnesTracesOfTheChosenImpulses) {
  const fs::path d = fresh_dir("portrait");
  write_portrait_runs(d);
  write_phase_portraits(d.string(), false);
  // Runs -3 (two frames) and 2 (one) side by side as (x, capture point), NaN-padded.
  EXPECT_EQ(read(d / "figures/phase_portraits/position.csv"),
            "x_1,cp_1,x_2,cp_2\n0.01,0.06,0.02,0.0033\n0.012,0.045,NaN,NaN\n");
  fs::remove_all(d);
}

TEST(StudyFigures, TheLandingFigureKeepsOneSecondOfEachTracedWalk) {
  const fs::path d = fresh_dir("landing");
  write_landing_runs(d);
  write_landing_figure(d.string(), false);
  EXPECT_EQ(read(d / "fsr_touchdown_runs.csv"),
            "case,t,fsr_left,fsr_right\n1,6,0,25\n1,6.4,25,0\n1,6.8,48.5,0\n"
            "2,6,0,25\n2,6.4,25,0\n2,6.8,48.5,0\n");
  fs::remove_all(d);
}

// Issue 49: every study's figures in <out>/figures/<family>/ as the posture study's are, none
// left in the output's top folder, and index.html showing each family.
TEST(StudyFigures, EveryStudyDrawsIntoItsFamilyFolder) {
  if (plot::png_terminal().empty()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path map = fresh_dir("layout_map"), portrait = fresh_dir("layout_portrait"),
                 landing = fresh_dir("layout_landing");
  write(map / "runs.csv", kRecoveryRuns);
  write_push_map(map.string(), true);
  write_portrait_runs(portrait);
  write_phase_portraits(portrait.string(), true);
  write_landing_runs(landing);
  write_landing_figure(landing.string(), true);
  const std::pair<fs::path, std::vector<std::string>> expected[] = {
      {map, {"figures/push_map/forward.png", "figures/push_map/left.png"}},
      {portrait, {"figures/phase_portraits/position.png"}},
      {landing, {"figures/fsr_touchdown/landing_off_and_on.png"}}};
  for (const auto& [d, pictures] : expected) {
    for (const auto& e : fs::directory_iterator(d))
      EXPECT_NE(e.path().extension(), ".png") << e.path() << ": a figure outside a family folder";
    for (const std::string& p : pictures) {
      EXPECT_TRUE(fs::exists(d / p)) << d / p;
      EXPECT_TRUE(fs::exists((d / p).replace_extension(".gp"))) << d / p;
    }
    const std::vector<FigureFamily> families = figure_families(d.string());
    ASSERT_EQ(families.size(), 1u) << d;
    EXPECT_EQ(families[0].folder, fs::path(pictures[0]).parent_path().string());
    EXPECT_EQ(families[0].pictures.size(), pictures.size());
    ASSERT_FALSE(write_figure_index(d.string(), "study").empty());
    const std::string index = read(d / "index.html");
    for (const std::string& p : pictures)
      EXPECT_NE(index.find("<img src=\"" + p + "\""), std::string::npos) << index;
    fs::remove_all(d);
  }
}

}  // namespace
}  // namespace stride::experiments
