#pragma once
// Which module provides what, and parameter values, as a scene or robot configuration gives them;
// the robot's model for modules that need one; what a module's exception does.
#include <map>
#include <memory>
#include <string>

#include "robot/model/robot_model.hpp"

namespace stride {

enum class ModuleErrorPolicy {
  Propagate,  // the exception leaves Runtime::step() (a simulation stops with the error)
  Hold,       // caught: the frame sends the last safe command, the error is recorded once
};

enum class LogErrorPolicy {
  Propagate,    // a failed log write leaves Runtime::step() (a console run stops with the error)
  StopLogging,  // the log ends there, log_stopped() says why, the frame goes on (the robot)
};

struct RuntimeConfig {
  std::map<std::string, std::string> providers;   // representation -> module
  std::map<std::string, std::string> parameters;  // "Module.field" -> text value
  // The robot's model (its URDF, loaded once by whoever builds the configuration); modules that
  // need it get it at construction (ModuleContext::robot_model()). May be null.
  std::shared_ptr<const model::RobotModel> model;
  ModuleErrorPolicy on_module_error = ModuleErrorPolicy::Propagate;
  LogErrorPolicy on_log_error = LogErrorPolicy::Propagate;
};

}  // namespace stride
