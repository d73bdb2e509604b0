// The walk report's tip record: the first time the torso passes kTipAngle, and which way. A
// standing NAO pushed hard at the torso tips the way it is pushed (NAOqi signs: pitch > 0 leans
// forward, roll > 0 leans right); one left alone never tips.
#include <string>

#include <gtest/gtest.h>

#include "simulator/report/run_report.hpp"
#include "tests/simulator/sim_test_util.hpp"

namespace stride {
namespace {

std::string pushed_scene(const std::string& force) {
  return R"(<scene><physics seed="3" iterations="20"/><ground friction="0.8"/>
    <robot name="nao" urdf="../../scenes/robots/nao/nao.urdf" devices="../../scenes/robots/nao/nao.devices.xml">
      <joints LHipPitch="-0.3" RHipPitch="-0.3" LKneePitch="0.6" RKneePitch="0.6"
              LAnklePitch="-0.3" RAnklePitch="-0.3" LShoulderPitch="1.5" RShoulderPitch="1.5"/>
      <sensors noise="off"/>
    </robot>)" +
         (force.empty() ? std::string()
                        : R"(<push robot="nao" body="torso" force=")" + force +
                              R"(" start="0.5" duration="0.3"/>)") +
         "</scene>";
}

sim::WalkMetricsResult after(const std::string& force, double seconds) {
  auto sim = test::scene_from_text(pushed_scene(force));
  sim->run_for(seconds);
  return sim->walk_metrics(0).result();
}

TEST(WalkTip, StandingRobotNeverTips) {
  const auto r = after("", 2.0);
  EXPECT_EQ(r.tipped, sim::Tip::None);
  EXPECT_EQ(r.tipped_at, -1);
  EXPECT_FALSE(r.fell);
}

TEST(WalkTip, PushedRobotTipsTheWayItIsPushedAfterThePushAndBeforeItLies) {
  struct Case {
    const char* force;
    sim::Tip way;
  };
  for (const Case& c : {Case{"60 0 0", sim::Tip::Forward}, Case{"-60 0 0", sim::Tip::Backward},
                        Case{"0 -60 0", sim::Tip::Right}, Case{"0 60 0", sim::Tip::Left}}) {
    const auto r = after(c.force, 3.0);
    EXPECT_EQ(r.tipped, c.way) << c.force << ": " << sim::tip_name(r.tipped);
    EXPECT_GT(r.tipped_at, 0.5) << c.force;
    ASSERT_TRUE(r.fell) << c.force;
    EXPECT_LE(r.tipped_at, r.fell_at) << c.force;  // kTipAngle is below the fall tilt
  }
}

TEST(WalkTip, RunReportNamesTheWay) {
  auto sim = test::scene_from_text(pushed_scene("60 0 0"));
  sim->run_for(3.0);
  const std::string json = sim::run_report_json(*sim, sim::RunTiming{});
  EXPECT_NE(json.find("\"tipped\":\"forward\""), std::string::npos) << json;
}

}  // namespace
}  // namespace stride
