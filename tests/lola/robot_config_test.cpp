// The robot config (`stride robot --config`): the same <controller> section as a scene's robot,
// parsed by the same code; errors name file:line and what was expected.
#include <gtest/gtest.h>

#include "robot/app/robot_config.hpp"
#include "simulator/scene/scene_parser.hpp"
#include "tests/error_text.hpp"

namespace stride {
namespace {

using test_support::error_of;

TEST(RobotConfig, HipWalkConfigCarriesTheSceneControllerUnchanged) {
  const RobotConfig c =
      parse_robot_config_file(STRIDE_SOURCE_DIR "/scenes/robots/nao/config/hip_walk.xml");
  const sim::SceneDescription scene =
      sim::parse_scene_file(STRIDE_SOURCE_DIR "/scenes/experiments/hip_medium.xml");
  EXPECT_EQ(c.controller, scene.robots[0].controller);
  EXPECT_EQ(c.controller.providers.at("PostureCorrectedRequest"), "HipStrategy");
  EXPECT_EQ(c.urdf, STRIDE_SOURCE_DIR "/scenes/robots/nao/nao.urdf");  // relative to the file
  EXPECT_EQ(c.lola_socket, "/tmp/robocup");
  EXPECT_EQ(c.period, 0.012);
  EXPECT_FALSE(c.stop_on_module_error);
}

TEST(RobotConfig, TimedChangesAndSafetySettings) {
  const RobotConfig c = parse_robot_config_text(R"(<robot_config name="red7">
  <model urdf="/opt/stride/nao.urdf"/>
  <lola socket="/tmp/sim.sock" period="10ms" connect_timeout="2s"/>
  <safety link_timeout="250ms" on_module_error="stop"/>
  <controller>
    <provider representation="JointRequest" module="Stand"/>
    <at time="5s"><parameter module="Stand" field="stiffness" value="0.5"/></at>
  </controller>
</robot_config>)",
                                                "/robots/red7.xml");
  EXPECT_EQ(c.name, "red7");
  EXPECT_EQ(c.urdf, "/opt/stride/nao.urdf");
  EXPECT_EQ(c.lola_socket, "/tmp/sim.sock");
  EXPECT_EQ(c.period, 0.010);
  EXPECT_EQ(c.connect_timeout, 2);
  EXPECT_EQ(c.link_timeout, 0.25);
  EXPECT_TRUE(c.stop_on_module_error);
  ASSERT_EQ(c.controller.changes.size(), 1u);
  EXPECT_EQ(c.controller.changes[0].time, 5);
  EXPECT_EQ(c.controller.changes[0].first, "Stand.stiffness");
  EXPECT_EQ(c.controller.changes[0].line, 7);
}

std::string config_error(const std::string& body) {
  return error_of([&] { parse_robot_config_text(body, "r.xml"); });
}

TEST(RobotConfig, ErrorsNameFileLineAndWhatWasExpected) {
  const std::string model = "<model urdf=\"n.urdf\"/>";
  const std::string controller = "<controller/>";
  EXPECT_EQ(config_error("<scene/>"), "r.xml:1: expected <robot_config> as the root element");
  EXPECT_EQ(config_error("<robot_config>\n" + controller + "</robot_config>"),
            "r.xml:1: <robot_config>: expected a <model urdf=\"...\"> (the robot the controller "
            "computes with)");
  EXPECT_EQ(config_error("<robot_config>" + model + "</robot_config>"),
            "r.xml:1: <robot_config>: expected a <controller> (as a scene's robot has)");
  EXPECT_EQ(config_error("<robot_config>" + model + controller +
                         "\n<safety link_timeout=\"-1\"/></robot_config>"),
            "r.xml:2: <safety>: attribute 'link_timeout': expected a time from 0 to 1 hour");
  EXPECT_EQ(config_error("<robot_config>" + model + controller +
                         "\n<safety on_module_error=\"ignore\"/></robot_config>"),
            "r.xml:2: <safety>: attribute 'on_module_error': 'ignore' (expected one of continue, "
            "stop)");
  EXPECT_EQ(config_error("<robot_config>" + model + controller +
                         "\n<lola period=\"12\"/></robot_config>"),
            "r.xml:2: <lola>: attribute 'period': expected 1 ms to 1 s");
  EXPECT_EQ(
      config_error("<robot_config>" + model + "\n<controller><mr/></controller></robot_config>"),
      "r.xml:2: <mr>: unknown element in <controller> (expected provider, parameter or at)");
  EXPECT_EQ(config_error("<robot_config>" + model + controller + controller + "</robot_config>"),
            "r.xml:1: <controller>: one <controller> per robot config");
  EXPECT_EQ(config_error("<robot_config><modle/></robot_config>"),
            "r.xml:1: <modle>: unknown element (expected model, lola, safety or controller)");
  EXPECT_EQ(config_error("<robot_config"), "r.xml:1: malformed XML (parsing element)");
  EXPECT_EQ(error_of([] { parse_robot_config_file("/nonexistent/robot.xml"); }),
            "/nonexistent/robot.xml:0: cannot open robot config file");
}

}  // namespace
}  // namespace stride
