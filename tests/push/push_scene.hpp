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
  scene.robots[0].controller.parameters["ComStateEstimator.urdf"] = scene.robots[0].urdf;
  return std::make_unique<console::SimSession>(std::move(scene));
}

struct TrueCom {
  Eigen::Vector3d position, velocity;  // ground frame: origin below the ankles' midpoint
};

inline TrueCom true_com(const sim::RobotBody& body) {
  double mass = 0;
  Eigen::Vector3d p = Eigen::Vector3d::Zero(), v = Eigen::Vector3d::Zero();
  for (int l = 0; l < body.link_count(); ++l) {
    const double m = body.model().links[l].inertial.mass;
    if (m <= 0 || !body.body(l)) continue;
    const dReal* lv = dBodyGetLinearVel(body.body(l));
    p += m * body.link_com(l);
    v += m * Eigen::Vector3d(lv[0], lv[1], lv[2]);
    mass += m;
  }
  const auto& model = body.model();
  const Eigen::Vector3d ankles = 0.5 * (body.link_pose(model.link_index("LFoot")).translation() +
                                        body.link_pose(model.link_index("RFoot")).translation());
  Eigen::Vector3d origin = ankles;
  origin.z() = 0;  // the ground plane
  return {p / mass - origin, v / mass};
}

}  // namespace stride::push_test
