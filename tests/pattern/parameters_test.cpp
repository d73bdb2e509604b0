// Parameter validation and the `stride pattern` command line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "behaviours/walking/pattern/pattern_parameters.hpp"
#include "console/cli/subcommand.hpp"
#include "console/plot/gnuplot_plot.hpp"
#include "robot/core/error.hpp"

namespace stride::cli {
int pattern_main(Args args, std::ostream& out, std::ostream& err);
}

namespace stride::walking {
namespace {

std::string error_of(void (*edit)(PatternParameters&)) {
  PatternParameters p;
  edit(p);
  return validation_error(p).value_or("");
}

TEST(PatternParameters, Table4_3DefaultsAreValidAndDerived) {
  const PatternParameters p;
  EXPECT_FALSE(validation_error(p).has_value());
  EXPECT_DOUBLE_EQ(p.T_step(), 0.25);
  EXPECT_DOUBLE_EQ(p.T_s() * 2, 0.25 * 0.99);          // T_ssp = T_step (1 - tau_dsp)
  EXPECT_NEAR(p.T_d() - p.T_s(), 0.25 * 0.01, 1e-15);  // T_dsp = T_step tau_dsp
  EXPECT_NEAR(max_waist_height(), 0.085 + 0.1 + 0.1029 + 0.04519, 1e-15);
  for (const std::string& name : preset_names())
    EXPECT_FALSE(validation_error(preset(name)).has_value()) << name;
}

TEST(PatternParameters, ErrorsNameTheParameter) {
  EXPECT_NE(error_of([](auto& p) { p.T_stride = -0.5; }).find("T_stride must be > 0"),
            std::string::npos);
  EXPECT_NE(error_of([](auto& p) { p.tau_dsp = 1.0; }).find("tau_dsp"), std::string::npos);
  EXPECT_NE(error_of([](auto& p) { p.z_max = 0.34; }).find("z_max = 0.34 m is beyond the leg"),
            std::string::npos);
  EXPECT_NE(error_of([](auto& p) { p.z_min = 0.33; }).find("z_max must be >= z_min"),
            std::string::npos);
  EXPECT_NE(error_of([](auto& p) { p.d_0 = 0.03; }).find("d_0"), std::string::npos);
  EXPECT_NE(error_of([](auto& p) {
              p.z_min = 0.330, p.z_max = 0.332, p.A_l = 0.025;  // Fig. 3.14 on this model
            }).find("beyond the leg's reach at mid single support (hip-ankle 0.20335"),
            std::string::npos);
  EXPECT_NE(error_of([](auto& p) {
              p.rhythmic = {0, 0};
            }).find("alpha (Eq. 3.15) is 0"),
            std::string::npos);
  EXPECT_NE(error_of([](auto& p) {
              p.rhythmic = {0.2, 0.1};
            }).find("rhythmic V_max"),
            std::string::npos);
  EXPECT_NE(error_of([](auto& p) { p.H_foot = 0; }).find("H_foot"), std::string::npos);
  EXPECT_NE(error_of([](auto& p) {
              p.steps = 3;
              p.development = linear_levels(p.rhythmic, 3);
            }).find("steps = 3 is fewer than the 3 development + 1 decay steps"),
            std::string::npos);
  for (auto edit : {+[](PatternParameters& p) { p.T_stride = -1; },
                    +[](PatternParameters& p) {
                      p.development = {{0.1, 0.05}};
                    }}) {
    const std::string e = error_of(edit);
    EXPECT_FALSE(e.empty());
    EXPECT_EQ(e.find('\n'), std::string::npos) << "one line";
  }
  PatternParameters p;
  p.T_stride = 0;
  EXPECT_THROW(validate(p), Error);
}

TEST(PatternParameters, SetByTable4_3Name) {
  PatternParameters p;
  set_parameter(p, "A_s", "0.004");
  EXPECT_NEAR(p.z_min, p.z_max - 0.008, 1e-15);
  set_parameter(p, "development_levels", "0.01:0.02,0.03:0.04");
  ASSERT_EQ(p.development.size(), 2u);
  EXPECT_DOUBLE_EQ(p.development[1].V_max, 0.04);
  set_parameter(p, "decay_steps", "4");
  ASSERT_EQ(p.decay.size(), 3u);
  EXPECT_NEAR(p.decay[0].V_min, 0.25 * p.rhythmic.V_min, 1e-15);
  EXPECT_THROW(set_parameter(p, "T_strid", "1"), Error);
  EXPECT_THROW(set_parameter(p, "T_stride", "1s"), Error);
  EXPECT_THROW(set_parameter(p, "steps", "2.5"), Error);
  EXPECT_THROW(set_parameter(p, "decay_levels", "0.1"), Error);
}

int run(std::vector<std::string> args, std::string& out, std::string& err) {
  std::ostringstream o, e;
  const int rc = cli::pattern_main(args, o, e);
  out = o.str(), err = e.str();
  return rc;
}

TEST(PatternCommand, BadSetIsOneLineNamingTheParameterAndExit2) {
  std::string out, err;
  EXPECT_EQ(run({"--set", "foo=1", "--csv", "x.csv"}, out, err), 2);
  EXPECT_EQ(err, "stride pattern: unknown pattern parameter 'foo'\n");
  EXPECT_EQ(run({"--set", "T_stride=-1", "--csv", "x.csv"}, out, err), 2);
  EXPECT_EQ(err, "stride pattern: T_stride must be > 0 s (got -1)\n");
  EXPECT_EQ(run({"--set", "H_foot=high", "--csv", "x.csv"}, out, err), 2);
  EXPECT_EQ(err, "stride pattern: parameter H_foot: expected a number, got 'high'\n");
}

TEST(PatternCommand, WritesTheWholeWalkAtTheControlPeriod) {
  const auto csv = std::filesystem::temp_directory_path() / "stride_pattern_test.csv";
  std::string out, err;
  ASSERT_EQ(run({"--preset", "medium", "--set", "steps=20", "--csv", csv.string()}, out, err), 0)
      << err;
  std::ifstream f(csv);
  std::string header, line, last;
  std::getline(f, header);
  EXPECT_EQ(header.rfind("time,waist_x,waist_y,waist_z,left_x,left_y,left_z,right_x,", 0), 0u);
  int rows = 0;
  while (std::getline(f, line)) ++rows, last = line;
  EXPECT_EQ(rows, 501);  // 20 steps of 0.25 s at 10 ms, both ends included
  EXPECT_EQ(last.rfind("5,", 0), 0u);
  EXPECT_NE(header.find(",LKneePitch,"), std::string::npos);
  EXPECT_NE(out.find("21 foot steps in 5 s"), std::string::npos) << out;
  std::filesystem::remove(csv);
}

TEST(PatternCommand, PlotsTheChapter3Figures) {
  if (plot::png_terminal().empty()) GTEST_SKIP() << "gnuplot not installed";
  const auto dir = std::filesystem::temp_directory_path() / "stride_pattern_plots";
  std::string out, err;
  ASSERT_EQ(
      run({"--preset", "medium", "--set", "steps=8", "--conventional", "--plots", dir.string()},
          out, err),
      0)
      << err;
  for (const char* png : {"fig3_8_waist_velocity", "fig3_10_lateral_first_step", "fig3_14_waist_3d",
                          "fig3_15_forward", "fig3_16_transverse", "fig3_16_sagittal",
                          "fig3_17_knees", "fig3_18_stick_left", "fig3_18_stick_right"}) {
    const auto path = dir / (std::string(png) + ".png");
    EXPECT_TRUE(std::filesystem::exists(path)) << path;
    if (std::filesystem::exists(path)) {
      EXPECT_GT(std::filesystem::file_size(path), 1000u);
    }
  }
  EXPECT_NE(out.find("conventional pattern"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace stride::walking
