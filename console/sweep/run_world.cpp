#include "console/sweep/run_world.hpp"

#include <filesystem>

#include "console/sweep/lola_robot.hpp"
#include "console/sweep/run_session.hpp"

namespace stride::sweep {

RunWorld::RunWorld(const SweepSpec& spec, const RunPlan& run) {
  if (spec.robot_link != RobotLink::Lola) {
    session_ = build_run_session(spec, run, spec.robot_link);
    walk_ = console::walk_pattern_info(*session_);
    return;
  }
  // The run's controller is built here once and never stepped: it checks the run's settings as
  // in process (errors name the scene) and says which pattern, so which walk marks, it plays.
  sim::SceneDescription scene;
  {
    const auto probe = build_run_session(spec, run, RobotLink::Packets);
    walk_ = console::walk_pattern_info(*probe);
    scene = probe->simulation().scene();
  }
  RobotConfig config;
  const sim::RobotPlacement& robot = scene.robots.at(0);
  config.name = robot.name;
  config.urdf = std::filesystem::absolute(robot.urdf).lexically_normal().string();
  config.controller = run_controller(robot.controller, run);
  session_ = std::make_unique<console::SimSession>(run_scene(spec, run, RobotLink::Lola));
  lola_ = std::make_unique<LolaRobot>(std::move(config), session_->simulation().robot(0));
}

RunWorld::~RunWorld() {
  lola_.reset();  // the robot process ends before the world it controls
  session_.reset();
}

void RunWorld::set_frame_observer(console::SimSession::FrameObserver observer) {
  if (lola_) session_->simulation().set_controller(0, lola_.get());
  session_->set_frame_observer(0, std::move(observer));
}

void RunWorld::finish() {
  if (lola_) lola_->finish();
}

}  // namespace stride::sweep
