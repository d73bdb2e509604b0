// Bad input: one line naming file:line and what was expected; nothing is built.
#include <fstream>
#include <regex>

#include <gtest/gtest.h>

#include "robot/core/error.hpp"
#include "tests/simulator/sim_test_util.hpp"

namespace stride {
namespace {

// Builds the scene and returns the error message (empty if it loaded).
std::string load_error(const std::string& xml) {
  try {
    test::scene_from_text(xml, "bad.xml");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

void expect_error(const std::string& xml, const std::string& file_line, const std::string& part) {
  const std::string msg = load_error(xml);
  ASSERT_FALSE(msg.empty()) << "scene loaded but should not have";
  EXPECT_EQ(msg.find('\n'), std::string::npos) << "one line: " << msg;
  EXPECT_NE(msg.find(file_line), std::string::npos) << msg;
  EXPECT_NE(msg.find(part), std::string::npos) << msg;
}

const std::string kNao = R"(urdf="../../scenes/robots/nao/nao.urdf")";

TEST(BadScene, MalformedXml) {
  expect_error("<scene>\n<ground friction=\"0.8\">\n</scene>", "bad.xml:2",
               "malformed XML (mismatched element)");
}

TEST(BadScene, UnknownElement) {
  expect_error("<scene>\n<grund/>\n</scene>", "bad.xml:2", "unknown element");
}

TEST(BadScene, UnknownAttribute) {
  expect_error("<scene>\n<ground frction=\"0.3\"/>\n</scene>", "bad.xml:2",
               "unknown attribute 'frction'");
}

TEST(BadScene, MissingUrdf) {
  expect_error("<scene>\n<robot name=\"r\" urdf=\"nowhere.urdf\"/>\n</scene>", "bad.xml:2",
               "nowhere.urdf': cannot open: No such file or directory");
}

TEST(BadScene, UrdfJointWithoutLimits) {
  expect_error("<scene>\n<robot urdf=\"no_limits.urdf\"/>\n</scene>", "no_limits.urdf:9",
               "revolute joint without <limit>");
}

TEST(BadScene, NegativeMass) {
  expect_error("<scene>\n<robot urdf=\"negative_mass.urdf\"/>\n</scene>", "negative_mass.urdf:4",
               "link 'a' mass: value -1 kg outside [0, 100000]");
}

TEST(BadScene, NanInAnAttribute) {
  expect_error("<scene>\n<physics step=\"nan\"/>\n</scene>", "bad.xml:2", "step");
  expect_error("<scene>\n<box size=\"1 NaN 1\"/>\n</scene>", "bad.xml:2", "size");
}

TEST(BadScene, PushOnMissingBody) {
  expect_error("<scene>\n<robot name=\"nao\" " + kNao +
                   "/>\n<push robot=\"nao\" body=\"Tail\" force=\"1 0 0\"/>\n</scene>",
               "bad.xml:3", "no link named 'Tail'");
}

TEST(BadScene, PushOnMissingRobot) {
  expect_error("<scene>\n<push robot=\"ghost\" body=\"torso\" force=\"1 0 0\"/>\n</scene>",
               "bad.xml:2", "no robot named 'ghost'");
}

// MuJoCo's contact attributes and its CG solver mean nothing to ODE: an error, not ignored.
TEST(BadScene, MujocoSettingOnOdeIsAnError) {
  expect_error("<scene>\n<physics cone=\"pyramidal\"/>\n</scene>", "bad.xml:2", "a MuJoCo setting");
  expect_error("<scene>\n<physics contact_timeconst=\"5ms\"/>\n</scene>", "bad.xml:2",
               "contact_timeconst");
  expect_error("<scene>\n<physics solver=\"cg\"/>\n</scene>", "bad.xml:2", "MuJoCo's solver");
}

TEST(BadScene, ContactSpringNeedsBothValuesAndNotErpCfm) {
  expect_error("<scene>\n<physics contact_stiffness=\"4e4\"/>\n</scene>", "bad.xml:2",
               "contact_stiffness and contact_damping together");
  expect_error("<scene>\n<physics contact_damping=\"10\"/>\n</scene>", "bad.xml:2",
               "contact_damping");
  expect_error(
      "<scene>\n<physics contact_stiffness=\"4e4\" contact_damping=\"10\" "
      "contact_erp=\"0.5\"/>\n</scene>",
      "bad.xml:2", "not both");
  expect_error("<scene>\n<physics contact_stiffness=\"-1\" contact_damping=\"10\"/>\n</scene>",
               "bad.xml:2", "stiffness > 0");
  expect_error("<scene>\n<physics contact_stiffness=\"4e4\" contact_damping=\"-2\"/>\n</scene>",
               "bad.xml:2", "damping >= 0");
  expect_error("<scene>\n<physics contact_stiffness=\"inf\" contact_damping=\"1\"/>\n</scene>",
               "bad.xml:2", "contact_stiffness");
  expect_error("<scene>\n<physics contact_spring_per=\"body\"/>\n</scene>", "bad.xml:2",
               "contact_spring_per");
  expect_error(
      "<scene>\n<physics contact_stiffness=\"4e4\" contact_damping=\"10\" "
      "contact_spring_per=\"foot\"/>\n</scene>",
      "bad.xml:2", "contact_spring_per");
}

TEST(BadScene, UnitOfTheWrongKind) {
  expect_error("<scene>\n<physics step=\"5deg\"/>\n</scene>", "bad.xml:2", "expected a time");
}

TEST(BadScene, UnknownJointInInitialPose) {
  expect_error("<scene>\n<robot " + kNao + ">\n<joints LKnee=\"0.5\"/>\n</robot>\n</scene>",
               "bad.xml:3", "'LKnee' is not a movable joint");
}

TEST(BadScene, IncludeCycle) {
  expect_error("<scene>\n<include file=\"cycle_a.xml\"/>\n</scene>", "cycle_b.xml:2",
               "include cycle");
}

TEST(BadScene, MeshCollisionIsRejectedClearly) {
  expect_error("<scene>\n<robot urdf=\"mesh.urdf\"/>\n</scene>", "mesh.urdf:6",
               "mesh collision geometry is not supported");
}

TEST(BadScene, IncludeReusesAFile) {
  auto sim = test::scene_from_text("<scene>\n<include file=\"flat_physics.xml\"/>\n</scene>");
  EXPECT_EQ(sim->scene().physics.iterations, 33);
  EXPECT_DOUBLE_EQ(sim->scene().physics.step, 0.002);
}

// <motor> and <servo> inside <robot> change the device file's motor of that name or servo of that
// joint, checked where written.
TEST(BadScene, MotorOverrides) {
  const std::string robot =
      "<scene>\n<robot " + kNao + R"( devices="../../scenes/robots/nao/nao.devices.xml">)" + "\n";
  expect_error(robot + R"(<motor name="pitch" damping="1"/></robot></scene>)", "bad.xml:3",
               "damping is only for a spring");
  expect_error(robot + R"(<motor name="elbow" gain="50"/></robot></scene>)", "bad.xml:3",
               "no such motor");
  expect_error(robot + R"(<motor name="pitch" gian="50"/></robot></scene>)", "bad.xml:3",
               "unknown attribute 'gian'");
  expect_error(robot + R"(<motor name="pitch" spring="-5"/></robot></scene>)", "bad.xml:3",
               "expected a value > 0");
  expect_error(robot + R"(<motor name="pitch"/></robot></scene>)", "bad.xml:3",
               "at least one motor attribute");
  expect_error(robot + R"(<motor name="pitch" spring="100" backlash="1deg"/></robot></scene>)",
               "bad.xml:3", "backlash is only for the velocity servo");
  expect_error(robot + R"(<motor name="pitch" integral="50"/></robot></scene>)", "bad.xml:3",
               "integral is only for a spring");
  expect_error(
      "<scene>\n<robot " + kNao + ">\n" + R"(<motor name="pitch" gain="5"/></robot></scene>)",
      "bad.xml:3", "there is none");
  expect_error(robot + R"(<calibration sd="0"/></robot></scene>)", "bad.xml:3",
               "attribute 'sd': expected an angle in (0, 10deg]");
  expect_error(robot + R"(<calibration sd="20deg"/></robot></scene>)", "bad.xml:3",
               "expected an angle in (0, 10deg]");
  expect_error(robot + R"(<calibration/></robot></scene>)", "bad.xml:3", "sd");
  expect_error(robot + R"(<calibration sd="1deg" joints=" , "/></robot></scene>)", "bad.xml:3",
               "expected joint names");
  expect_error(robot + R"(<calibration sd="1deg" joints="LHipPitch,LHipPitch"/></robot></scene>)",
               "bad.xml:3", "'LHipPitch' is listed twice");
  expect_error(robot + R"(<calibration sd="1deg" joints="LElbow"/></robot></scene>)", "bad.xml:3",
               "no servo for 'LElbow'");
  expect_error(
      robot + R"(<calibration sd="1deg"/>)" + "\n" + R"(<calibration sd="1deg"/></robot></scene>)",
      "bad.xml:3)", "bad.xml:4: <calibration>: given twice in one <robot> (first at ");
  expect_error("<scene>\n<robot " + kNao + ">\n" + R"(<calibration sd="1deg"/></robot></scene>)",
               "bad.xml:3", "there is none");
  expect_error(robot + R"(<servo joint="LElbow" offset="1deg"/></robot></scene>)", "bad.xml:3",
               "no servo for that joint");
  expect_error(robot + R"(<servo joint="LHipPitch" offset="3 bananas"/></robot></scene>)",
               "bad.xml:3", "offset");
  expect_error(robot + R"(<servo joint="LHipPitch"/></robot></scene>)", "bad.xml:3",
               "expected an offset or a motor attribute");
  expect_error(robot + R"(<servo joint="LHipRoll" spring="0"/></robot></scene>)", "bad.xml:3",
               "attribute 'spring': expected a value > 0");
  expect_error(robot + R"(<servo joint="LHipRoll" integral="50"/></robot></scene>)", "bad.xml:3",
               "<servo joint=\"LHipRoll\">: integral is only for a spring");
  expect_error(robot + R"(<servo joint="LElbow" spring="400"/></robot></scene>)", "bad.xml:3",
               "no servo for that joint");
  expect_error(robot + R"(<servo joint="LHipPitch" offset="1deg" motor="pitch"/></robot></scene>)",
               "bad.xml:3", "unknown attribute 'motor'");
  expect_error("<scene>\n<robot " + kNao + ">\n" +
                   R"(<servo joint="LHipPitch" offset="1deg"/></robot></scene>)",
               "bad.xml:3", "there is none");
  EXPECT_EQ(load_error(robot + R"(<motor name="pitch" gain="50" spring="150"/></robot></scene>)"),
            "");
  EXPECT_EQ(load_error(robot + R"(<servo joint="LHipRoll" spring="400" offset="1deg"/>)" +
                       R"(<servo joint="RHipRoll" spring="400"/></robot></scene>)"),
            "");
}

}  // namespace
}  // namespace stride
