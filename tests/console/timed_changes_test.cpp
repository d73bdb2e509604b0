// Timed controller changes in scenes (<at time> with <parameter>/<provider>): applied at the first
// control frame at or after their time, again after a reset, and checked when the scene loads.
#include <gtest/gtest.h>

#include "console/session/sim_session.hpp"
#include "robot/core/error.hpp"
#include "simulator/scene/scene_parser.hpp"

namespace stride::console {
namespace {

const std::string kScenePath = STRIDE_SOURCE_DIR "/scenes/timed_inline.xml";

std::string scene(const std::string& controller_extra) {
  return R"(<scene name="timed">
  <robot name="nao" urdf="robots/nao/nao.urdf" devices="robots/nao/nao.devices.xml">
    <controller>
      <provider representation="WalkingJointRequest" module="PatternWalk"/>
      <provider representation="PostureCorrectedRequest" module="NoPostureControl"/>
      <provider representation="ArmSwingRequest" module="ArmSwing"/>
      <provider representation="JointRequest" module="WalkingJointRequestAssembler"/>
)" + controller_extra +
         R"(
    </controller>
  </robot>
</scene>)";
}

std::string load_error(const std::string& extra) {
  try {
    SimSession s(sim::parse_scene_text(scene(extra), kScenePath));
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(TimedChanges, ApplyAtTheirTimeInOrderAndAgainAfterReset) {
  SimSession s(sim::parse_scene_text(scene(R"(
      <at time="0.3s">
        <provider representation="PostureCorrectedRequest" module="HipStrategy"/>
        <parameter module="ArmSwing" field="gain_scale" value="0.25"/>
      </at>
      <at time="0.1s"><parameter module="ArmSwing" field="gain_scale" value="0.5"/></at>)"),
                                     kScenePath));
  Runtime& rt = *s.runtime(0);
  const std::string initial = rt.get("module:ArmSwing.gain_scale");
  ASSERT_NE(initial, "0.5");
  s.simulation().run_for(0.095);
  EXPECT_EQ(rt.get("module:ArmSwing.gain_scale"), initial);
  s.simulation().run_for(0.01);  // the frame at 0.1 s
  EXPECT_EQ(rt.get("module:ArmSwing.gain_scale"), "0.5");
  EXPECT_EQ(rt.provider_of("PostureCorrectedRequest"), "NoPostureControl");
  s.simulation().run_for(0.2);
  EXPECT_EQ(rt.provider_of("PostureCorrectedRequest"), "HipStrategy");
  EXPECT_EQ(rt.get("module:ArmSwing.gain_scale"), "0.25");

  s.reset();
  Runtime& fresh = *s.runtime(0);
  EXPECT_EQ(fresh.get("module:ArmSwing.gain_scale"), initial);
  EXPECT_EQ(fresh.provider_of("PostureCorrectedRequest"), "NoPostureControl");
  s.simulation().run_for(0.305);
  EXPECT_EQ(fresh.provider_of("PostureCorrectedRequest"), "HipStrategy");
}

TEST(TimedChanges, SameSceneSameRunBitForBit) {
  const std::string text =
      scene(R"(<at time="0.2"><parameter module="ArmSwing" field="gain_scale" value="0"/></at>)");
  SimSession a(sim::parse_scene_text(text, kScenePath)), b(sim::parse_scene_text(text, kScenePath));
  a.simulation().run_for(0.5);
  b.simulation().run_for(0.5);
  EXPECT_EQ(a.simulation().state_hash(), b.simulation().state_hash());
}

TEST(TimedChanges, BadChangesFailAtLoadNamingFileAndLine) {
  // Line 8 of the scene text is the first line of `extra`.
  EXPECT_NE(load_error(R"(<at time="1"><parameter module="NoSuch" field="x" value="1"/></at>)")
                .find("timed_inline.xml:8: <at>: no module 'NoSuch' with parameters"),
            std::string::npos);
  EXPECT_NE(
      load_error(
          R"(<at time="1"><parameter module="ArmSwing" field="gain_scale" value="abc"/></at>)")
          .find("timed_inline.xml:8: <at>:"),
      std::string::npos);
  EXPECT_NE(
      load_error(
          R"(<at time="1"><provider representation="PostureCorrectedRequest" module="Stand"/></at>)")
          .find("timed_inline.xml:8: <at>:"),
      std::string::npos);
  EXPECT_NE(load_error(R"(<at><parameter module="ArmSwing" field="gain_scale" value="1"/></at>)")
                .find("time"),
            std::string::npos);
  EXPECT_NE(load_error(
                R"(<at time="-1"><parameter module="ArmSwing" field="gain_scale" value="1"/></at>)")
                .find("expected a time >= 0"),
            std::string::npos);
  EXPECT_NE(load_error(R"(<at time="1"><push/></at>)").find("expected provider or parameter"),
            std::string::npos);
  EXPECT_NE(load_error(R"(<at time="1"/>)").find("inside <at>"), std::string::npos);
}

}  // namespace
}  // namespace stride::console
