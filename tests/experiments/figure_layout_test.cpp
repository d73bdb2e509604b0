// A study's figures are laid out for a person: one folder per figure family with an index.html
// over all of them; the ground truth is drawn last (on top) in the Kalman and torso figures; the
// ZMP figures name their frame, and the feet-frame figure puts CoP and reference in one frame.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "console/experiments/experiment_list.hpp"
#include "console/experiments/figure_index.hpp"
#include "console/experiments/posture_figures.hpp"
#include "console/plot/gnuplot_plot.hpp"
#include "console/sweep/sweep_engine.hpp"
#include "console/sweep/sweep_parser.hpp"

namespace stride::experiments {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("stride_figure_layout_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string read(const fs::path& path) {
  std::ostringstream s;
  s << std::ifstream(path).rdbuf();
  return s.str();
}

// Where in a gnuplot script each curve's title stands (npos when absent).
std::size_t title_at(const std::string& gp, const std::string& title) {
  return gp.find("title '" + title + "'");
}

// A posture trace of three frames: feet midpoint at (1, 0.1) heading +y (yaw pi/2), the CoP 2 cm
// ahead along x, i.e. 2 cm to the robot's right; the walk started with the feet at y = 0.1.
void write_trace(const fs::path& path, bool feet) {
  std::string header =
      "t,hip_pitch_ref_l,hip_pitch_mod_l,hip_roll_ref_l,hip_roll_mod_l,ankle_pitch_ref_l,"
      "ankle_pitch_mod_l,ankle_roll_ref_l,ankle_roll_mod_l,true_pitch,true_roll,est_pitch,"
      "est_roll,waist_v_ref,waist_v,cop_x,cop_y,zmp_ref_x,zmp_ref_y";
  std::string rows[3] = {"1.5,0,0,0,0,0,0,0,0,0.01,0.02,0.011,0.019,0,0,1.02,0.1,0,0.1",
                         "1.6,0,0,0,0,0,0,0,0,0.01,0.02,0.011,0.019,0.1,0.1,nan,nan,0,0.13",
                         "1.7,0,0,0,0,0,0,0,0,0.01,0.02,0.011,0.019,0.1,0.1,1.02,0.1,0,0.07"};
  std::ofstream out(path);
  out << header << (feet ? ",feet_x,feet_y,torso_yaw\n" : "\n");
  for (const std::string& r : rows) out << r << (feet ? ",1,0.1,1.5707963267948966\n" : "\n");
}

TEST(FigureLayout, PostureFiguresGoIntoFamilyFoldersWithAnIndex) {
  if (plot::png_terminal().empty()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path d = fresh_dir("posture");
  write_trace(d / "trace.csv", true);
  write_posture_case_figures(d.string(), (d / "trace.csv").string(), "hip_medium", "Fig. 4.7");
  for (const std::string& family : posture_figure_families()) {
    EXPECT_TRUE(fs::exists(d / "figures" / family / "hip_medium.png")) << family;
    EXPECT_TRUE(fs::exists(d / "figures" / family / "hip_medium.gp")) << family;
  }
  EXPECT_EQ(write_figure_index(d.string(), "posture"), (d / "index.html").string());
  const std::string index = read(d / "index.html");
  for (const std::string& family : posture_figure_families()) {
    const std::string src = "figures/" + family + "/hip_medium.png";
    EXPECT_NE(index.find("<h2>figures/" + family + "</h2>"), std::string::npos) << family;
    EXPECT_NE(index.find("<img src=\"" + src + "\""), std::string::npos) << src;
  }
  const auto families = figure_families(d.string());
  ASSERT_EQ(families.size(), posture_figure_families().size());
  EXPECT_EQ(families.front().folder, "figures/joint_angles");  // folders in name order
  fs::remove_all(d);
}

TEST(FigureLayout, TorsoTruthIsDrawnLastAndZmpFiguresNameTheirFrame) {
  if (plot::png_terminal().empty()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path d = fresh_dir("frames");
  write_trace(d / "trace.csv", true);
  write_posture_case_figures(d.string(), (d / "trace.csv").string(), "hip_medium", "Fig. 4.7");
  const std::string torso = read(d / "figures/torso_inclination/hip_medium.gp");
  for (const char* estimate : {"pitch (Kalman)", "roll (Kalman)"})
    for (const char* truth : {"pitch (ground truth)", "roll (ground truth)"}) {
      ASSERT_NE(title_at(torso, truth), std::string::npos) << truth;
      EXPECT_LT(title_at(torso, estimate), title_at(torso, truth)) << estimate << " " << truth;
    }
  const std::string world = read(d / "figures/zmp_world/hip_medium.gp");
  EXPECT_NE(world.find("set xlabel 'x, world frame [m]'"), std::string::npos) << world;
  EXPECT_NE(world.find("set ylabel 'y, world frame [m]'"), std::string::npos);
  EXPECT_NE(title_at(world, "true feet midpoint (where the walk went)"), std::string::npos);
  const std::string feet = read(d / "figures/zmp_feet_frame/hip_medium.gp");
  EXPECT_NE(feet.find("set ylabel 'lateral from the feet midpoint, heading frame [m]'"),
            std::string::npos)
      << feet;
  // Heading +y, the CoP 2 cm along +x of the feet: 2 cm to the right, -0.02; the reference is
  // the plan's ZMP less the walking line's y (the feet's first y, 0.1). Airborne: NaN.
  EXPECT_EQ(read(d / "figures/zmp_feet_frame/hip_medium.csv"),
            "t,cop_lateral,zmp_ref_lateral\n1.5,-0.02,0\n1.6,NaN,0.03\n1.7,-0.02,-0.03\n");
  fs::remove_all(d);
}

TEST(FigureLayout, AnOlderTraceWithoutFeetColumnsLeavesOutOnlyTheFeetFrameFigure) {
  if (plot::png_terminal().empty()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path d = fresh_dir("old_trace");
  write_trace(d / "trace.csv", false);
  write_posture_case_figures(d.string(), (d / "trace.csv").string(), "ankle_slow", "Fig. 4.10");
  EXPECT_TRUE(fs::exists(d / "figures/zmp_world/ankle_slow.png"));
  EXPECT_TRUE(fs::exists(d / "figures/joint_angles/ankle_slow.png"));
  EXPECT_FALSE(fs::exists(d / "figures/zmp_feet_frame"));
  EXPECT_EQ(read(d / "figures/joint_angles/ankle_slow.gp").find("hip_pitch"), std::string::npos);
  fs::remove_all(d);
}

TEST(FigureLayout, IndexEscapesNamesAndIsLeftOutWithoutPictures) {
  const fs::path d = fresh_dir("escape");
  EXPECT_EQ(write_figure_index(d.string(), "empty"), "");
  EXPECT_FALSE(fs::exists(d / "index.html"));
  fs::create_directories(d / "a<b");
  std::ofstream(d / "a<b" / "x y&.png") << "png";
  std::ofstream(d / "top.png") << "png";
  write_figure_index(d.string(), "t<1>");
  const std::string index = read(d / "index.html");
  EXPECT_NE(index.find("<title>t&lt;1&gt;</title>"), std::string::npos) << index;
  EXPECT_NE(index.find("<img src=\"a%3Cb/x%20y%26.png\""), std::string::npos) << index;
  EXPECT_NE(index.find("<figcaption>x y&amp;.png</figcaption>"), std::string::npos);
  EXPECT_LT(index.find("<h2>top folder</h2>"), index.find("<h2>a&lt;b</h2>"));
  fs::remove_all(d);
}

// The real Kalman study (one walk): Figs. 4.1 and 4.2 in their family folder, the ground truth
// the last curve of each, and the index naming both.
TEST(FigureLayout, KalmanStudyDrawsTheTruthLast) {
  if (plot::png_terminal().empty()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path d = fresh_dir("kalman");
  ExperimentOptions o;
  o.sweeps_dir = std::string(STRIDE_SOURCE_DIR) + "/scenes/experiments";
  o.out_dir = (d / "out").string();
  std::ostringstream out, err;
  ASSERT_EQ(run_experiment("kalman", o, out, err), 0) << err.str();
  for (const char* figure : {"fig4.1_q", "fig4.2_r"}) {
    const fs::path stem = d / "out/figures/kalman_pitch_estimates" / figure;
    ASSERT_TRUE(fs::exists(stem.string() + ".png")) << figure;
    const std::string gp = read(stem.string() + ".gp");
    const std::size_t truth = title_at(gp, "ground truth");
    ASSERT_NE(truth, std::string::npos) << figure;
    EXPECT_LT(title_at(gp, "IMU angle"), truth) << figure;
    EXPECT_EQ(gp.find("title '", truth + 1), std::string::npos) << figure << ": truth not last";
    EXPECT_LT(gp.find("title 'Q "), truth) << figure;
  }
  EXPECT_NE(out.str().find("figures: " + (d / "out/index.html").string() + " (2 figures"),
            std::string::npos)
      << out.str();
  fs::remove_all(d);
}

// A sweep's own <plot> (the knee-energy, gains and push experiments draw theirs so) goes into the
// family folder of its tally, its CSV beside it, nothing into the output's top folder.
TEST(FigureLayout, ASweepsPlotIsInItsTallysFolder) {
  if (plot::png_terminal().empty()) GTEST_SKIP() << "gnuplot not installed";
  const fs::path d = fresh_dir("sweep");
  const sweep::Sweep s(
      sweep::parse_sweep_text(R"(<sweep name="stand" scenes="../../scenes">
  <scene file="nao_stand_controlled.xml"/>
  <seeds from="1" to="2"/>
  <run seconds="0.05"/>
  <record><value name="z" key="frame.torso_z"/></record>
  <tally name="by_seed" by="seed"><mean name="z" of="z"/></tally>
  <plot tally="by_seed" x="seed" y="z" x_label="seed [-]" y_label="torso height [m]"/>
</sweep>)",
                              std::string(STRIDE_SOURCE_DIR) + "/tests/sweep/stand.sweep.xml"));
  sweep::SweepOptions o;
  o.out_dir = d.string();
  o.print_tallies = false;
  o.plots = true;
  std::ostringstream text;
  const auto result =
      sweep::run_sweep(s, sweep::Tallies(s), *sweep::in_process_executor(), o, text);
  ASSERT_TRUE(result.complete) << text.str();
  EXPECT_TRUE(fs::exists(d / "figures/by_seed/seed_z.png")) << text.str();
  EXPECT_EQ(read(d / "figures/by_seed/seed_z.csv").substr(0, 7), "seed,z\n");
  for (const auto& e : fs::directory_iterator(d))
    EXPECT_NE(e.path().extension(), ".png") << e.path() << ": a figure outside a family folder";
  fs::remove_all(d);
}

}  // namespace
}  // namespace stride::experiments
