// The walk recorder observes the scene's own run: a timed change in the scene (a posture strategy
// switched on mid-walk) shows in the recorded frames, and the trace's columns are WalkFrame's
// reflected fields, in order.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "console/experiments/walk_recording.hpp"

namespace stride::experiments {
namespace {

namespace fs = std::filesystem;

// A short medium-speed walk (1 s standing, 8 waist steps) with no posture control until the
// hip strategy is switched on at 2 s by the scene itself.
std::string scene_file() {
  const std::string robots = std::string(STRIDE_SOURCE_DIR) + "/scenes/robots/nao/";
  const fs::path path =
      fs::temp_directory_path() / ("stride_walk_recording_" + std::to_string(::getpid()) + ".xml");
  std::ofstream(path) << R"(<scene name="timed_walk">
  <physics step="1ms" seed="1" iterations="20"/>
  <ground friction="0.8"/>
  <robot name="nao" urdf=")"
                      << robots << R"(nao.urdf" devices=")" << robots << R"(nao.devices.xml">
    <joints LHipPitch="-0.3" RHipPitch="-0.3" LKneePitch="0.6" RKneePitch="0.6"
            LAnklePitch="-0.3" RAnklePitch="-0.3" LShoulderPitch="1.5" RShoulderPitch="1.5"/>
    <controller>
      <provider representation="WalkingJointRequest" module="PatternWalk"/>
      <provider representation="PostureCorrectedRequest" module="NoPostureControl"/>
      <provider representation="ArmSwingRequest" module="ArmSwing"/>
      <provider representation="JointRequest" module="WalkingJointRequestAssembler"/>
      <parameter module="PatternWalk" field="preset" value="medium"/>
      <parameter module="PatternWalk" field="steps" value="8"/>
      <parameter module="PatternWalk" field="start_delay" value="1"/>
      <at time="2s"><provider representation="PostureCorrectedRequest" module="HipStrategy"/></at>
    </controller>
  </robot>
</scene>)";
  return path.string();
}

TEST(WalkRecording, TheScenesTimedChangesApplyWhileRecorded) {
  WalkSetup setup{scene_file(), 1};
  setup.settle_seconds = 0.1;
  const WalkRecording r = record_walk(setup);
  fs::remove(setup.scene);
  ASSERT_GT(r.frames.size(), 100u);
  // Before 2 s nothing corrects the pattern's hip angles; after it the hip strategy does.
  double before = 0, after = 0;
  for (const console::WalkFrame& f : r.frames) {
    const double correction = std::abs(f.hip_pitch_mod_l - f.hip_pitch_ref_l);
    (f.t < 1.99 ? before : after) = std::max(f.t < 1.99 ? before : after, correction);
  }
  EXPECT_EQ(before, 0.0);
  EXPECT_GT(after, 1e-4);
}

TEST(WalkRecording, TraceColumnsAreTheReflectedFields) {
  WalkRecording r;
  r.frames.resize(2);
  r.frames[1].t = 0.01;
  r.frames[1].fell = 1;
  const plot::Table t = trace_table(r);
  std::vector<std::string> names;
  for_each_field<console::WalkFrame>([&](const auto& f) { names.emplace_back(f.name); });
  EXPECT_EQ(t.columns, names);
  ASSERT_GT(t.columns.size(), 40u);
  EXPECT_EQ(t.columns.front(), "t");
  EXPECT_EQ(t.columns.back(), "fell");
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[1].front(), 0.01);
  EXPECT_EQ(t.rows[1].back(), 1.0);
}

}  // namespace
}  // namespace stride::experiments
