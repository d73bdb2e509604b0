#include "simulator/lola/lola_scene.hpp"

#include "robot/hal/lola/lola_protocol.hpp"

namespace stride::sim {

void prepare_lola_robot(SceneDescription& scene, std::size_t robot, LolaController controller) {
  RobotPlacement& r = scene.robots.at(robot);
  if (r.period == 0) r.period = hal::lola::kPeriod;
  if (controller == LolaController::Client) {
    r.has_controller = false;
    r.controller = {};
  }
}

}  // namespace stride::sim
