#pragma once
// A run's world: its scene file with the run's scene edits and seed, then its providers and
// module parameters applied to robot 0's controller, as `mr` and `set module:...` would.
#include <memory>

#include "console/session/sim_session.hpp"
#include "console/sweep/run_plan.hpp"
#include "robot/hal/controller_config.hpp"

namespace stride::sweep {

// The run's scene: its file with the run's scene edits, seed and perturbed start, robot 0 made
// ready for `link` (sim::prepare_lola_robot: LoLA's period; through LoLA, no controller here).
sim::SceneDescription run_scene(const SweepSpec& spec, const RunPlan& run, RobotLink link);

// The run's world with robot 0's controller in this process (directly or through LoLA's packets;
// not RobotLink::Lola), the run's providers and parameters applied to it. Throws stride::Error
// naming the scene and the setting that failed.
std::unique_ptr<console::SimSession> build_run_session(const SweepSpec& spec, const RunPlan& run,
                                                       RobotLink link);
inline std::unique_ptr<console::SimSession> build_run_session(const SweepSpec& spec,
                                                              const RunPlan& run) {
  return build_run_session(
      spec, run, spec.robot_link == RobotLink::Lola ? RobotLink::Packets : spec.robot_link);
}

// The run's providers and parameters written into a controller configuration (the scene's
// robot 0's), as a robot config hands them to a robot process.
ControllerConfig run_controller(ControllerConfig scene_controller, const RunPlan& run);

bool is_provider_setting(const Setting& s);   // "provider:Representation"
bool is_parameter_setting(const Setting& s);  // "Module.field"

// Checks a setting's target ("scene", "seed", "provider:X", "scene:...@attr", "Module.field");
// throws stride::Error saying what was expected.
void check_setting_target(const std::string& target);

}  // namespace stride::sweep
