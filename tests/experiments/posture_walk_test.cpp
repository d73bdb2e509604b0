// The medium-speed walk of Sec. 4.3.4.2 on the floor with local unevenness stays up for the whole
// 15 s with either posture strategy (Figs. 4.7 and 4.11), takes the thesis' 61 steps, and moves
// forward; the experiment command rejects bad arguments with one line.
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "console/cli/subcommand.hpp"
#include "console/experiments/experiment_list.hpp"
#include "console/experiments/walk_recording.hpp"
#include "console/sweep/sweep_parser.hpp"
#include "robot/core/error.hpp"

namespace stride::experiments {
namespace {

WalkSummary walk(const std::string& scene) {
  WalkSetup setup{std::string(STRIDE_SOURCE_DIR) + "/scenes/experiments/" + scene + ".xml", 1};
  setup.settle_seconds = 0.3;
  const WalkRecording r = record_walk(setup);
  EXPECT_DOUBLE_EQ(r.walk_duration, 15.0);
  return summarize(r);
}

// fsr_steps: the pattern takes 61; the FSR count may split or miss a landing. The hip walk's 58
// was re-derived at the scenes' converged setting (issue 47; 61 at the old iterative 20), the
// ankle walk's 58 when the law's per-body split went by depth (61 with the split by count).
void expect_stable_walk(const WalkSummary& s, int fsr_steps) {
  EXPECT_FALSE(s.fell);
  EXPECT_NEAR(s.steps, fsr_steps, 2);
  EXPECT_GT(s.distance, 1.0);  // thesis: 2.6-2.9 m; open loop here slips, but goes forward
  EXPECT_LT(std::max(-s.pitch_min, s.pitch_max), 0.35);
  EXPECT_LT(std::max(-s.roll_min, s.roll_max), 0.35);
}

TEST(PostureWalk, HipStrategyMediumSpeedUnevenFloorStaysUpFor15Seconds) {
  expect_stable_walk(walk("hip_medium"), 58);
}

TEST(PostureWalk, AnkleStrategyMediumSpeedUnevenFloorStaysUpFor15Seconds) {
  expect_stable_walk(walk("ankle_medium"), 58);
}

int run(std::vector<std::string> args, std::string& err_text) {
  for (const auto& c : cli::subcommands())
    if (c.name == "experiment") {
      std::ostringstream out, err;
      const int code = c.run(args, out, err);
      err_text = err.str();
      return code;
    }
  ADD_FAILURE() << "no experiment subcommand";
  return -1;
}

TEST(ExperimentCommand, BadArgumentsAreOneLineErrors) {
  std::string err;
  EXPECT_EQ(run({"walkabout"}, err), 2);  // a wrong command line (docs/console.md "Exit codes")
  EXPECT_NE(err.find("unknown experiment 'walkabout'"), std::string::npos) << err;
  EXPECT_EQ(run({"posture", "--seeds", "0"}, err), 2);
  EXPECT_NE(err.find("--seeds"), std::string::npos) << err;
  EXPECT_EQ(run({"posture", "--jobs", "0"}, err), 2);
  EXPECT_NE(err.find("--jobs: expected 1..256"), std::string::npos) << err;
  EXPECT_EQ(run({"posture", "--physics", "solver=fast"}, err), 2);
  EXPECT_NE(err.find("--physics: physics setting 'solver=fast'"), std::string::npos) << err;
  EXPECT_EQ(run({"kalman", "--physics", "solver=exact"}, err), 2);
  EXPECT_NE(err.find("only the sweep studies take it"), std::string::npos) << err;
  EXPECT_EQ(run({"posture", "--scenes", "/nonexistent"}, err), 3);  // an input not there
  EXPECT_NE(err.find("not found"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1);
}

TEST(PostureCases, SelectionNamesScenesOrStrategies) {
  const sweep::Sweep posture(sweep::parse_sweep_file(std::string(STRIDE_SOURCE_DIR) +
                                                     "/scenes/experiments/posture.sweep.xml"),
                             false);
  using Levels = std::vector<std::string>;
  EXPECT_EQ(posture_case_levels(posture, {"hip"}), (Levels{"hip_slow", "hip_medium", "hip_fast"}));
  EXPECT_EQ(posture_case_levels(posture, {"ankle", "none_fast"}),
            (Levels{"ankle_slow", "ankle_medium", "ankle_fast", "none_fast"}));
  EXPECT_EQ(posture_case_levels(posture, {"hip_medium", "hip"}),
            (Levels{"hip_medium", "hip_slow", "hip_fast"}));
  EXPECT_THROW(posture_case_levels(posture, {"hi"}), Error);  // a prefix must be a whole strategy
  EXPECT_THROW(posture_case_levels(posture, {"hip_medium", "walk"}), Error);
}

TEST(ExperimentCommand, CasesIsCheckedBeforeAnyWalk) {
  std::string err;
  EXPECT_EQ(run({"posture", "--cases", "hip,sprint"}, err), 2);
  EXPECT_NE(err.find("--cases: unknown case 'sprint'"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1);
  EXPECT_EQ(run({"kalman", "--cases", "hip"}, err), 2);
  EXPECT_NE(err.find("only posture takes it"), std::string::npos) << err;
  EXPECT_EQ(run({"posture", "--cases", ","}, err), 2);
  EXPECT_NE(err.find("--cases: expected"), std::string::npos) << err;
  // Only the chosen cases' scenes must exist: a directory with none of them names hip_slow.
  const std::string no_cases = std::string(STRIDE_SOURCE_DIR) + "/scenes";
  EXPECT_EQ(run({"posture", "--cases", "hip", "--scenes", no_cases}, err), 3);
  EXPECT_NE(err.find(no_cases + "/hip_slow.xml"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1);
}

}  // namespace
}  // namespace stride::experiments
