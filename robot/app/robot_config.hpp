#pragma once
// A physical robot's configuration (`stride robot --config robot.xml`), parsed to plain data:
//   <robot_config name="nao">
//     <model urdf="../robots/nao/nao.urdf"/>              the model the controller computes with
//     <lola socket="/tmp/robocup" period="12ms" connect_timeout="10s"/>    the link
//     <safety link_timeout="1s" on_module_error="continue|stop"/>
//     <controller> ... </controller>                     the same section a scene's robot has
//   </robot_config>
#include <string>

#include "robot/hal/controller_config.hpp"
#include "robot/hal/lola/lola_protocol.hpp"

namespace stride {

struct RobotConfig {
  std::string name = "nao";
  std::string file;  // where it was read from
  std::string urdf;  // resolved against the config file's folder
  std::string lola_socket{hal::lola::kDefaultSocket};
  double period = hal::lola::kPeriod;  // s
  double connect_timeout = 10;         // s to wait for LoLA's socket at start
  double link_timeout = 1.0;  // s without the link (closed or silent) before exiting non-zero
  bool stop_on_module_error = false;  // else the loop goes on, holding frames whose module failed
  ControllerConfig controller;
};

// Every error is one line: "file:line: <element>: what was expected"; nothing half-read.
RobotConfig parse_robot_config_file(const std::string& path);
RobotConfig parse_robot_config_text(const std::string& text, const std::string& virtual_path);

}  // namespace stride
