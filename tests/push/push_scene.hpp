#pragma once
// The push scene with a chosen balance module, and the simulator's ground-truth CoM state.
#include <memory>
#include <string>

#include <ode/ode.h>

#include "console/session/sim_session.hpp"
#include "simulator/scene/scene_parser.hpp"

namespace stride::push_test {

inline std::string scene_path() {
  return std::string(STRIDE_SOURCE_DIR) + "/scenes/push/stand_balance.xml";
}

inline std::unique_ptr<console::SimSession> balance_session(const std::string& module) {
  sim::SceneDescription scene = sim::parse_scene_file(scene_path());
  scene.robots[0].controller.providers["JointRequest"] = module;
  return std::make_unique<console::SimSession>(std::move(scene));
}

struct TrueCom {
  Eigen::Vector3d position, velocity;  // ground frame: origin below the ankles' midpoint
};

inline TrueCom true_com(const sim::RobotBody& body) {
  const auto& model = body.model();
  const Eigen::Vector3d ankles = 0.5 * (body.link_pose(model.link_index("LFoot")).translation() +
                                        body.link_pose(model.link_index("RFoot")).translation());
  Eigen::Vector3d origin = ankles;
  origin.z() = 0;  // the ground plane
  return {body.centre_of_mass() - origin, body.centre_of_mass_velocity()};
}

}  // namespace stride::push_test
