#include "console/target/logged_scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "robot/hal/joint_id.hpp"

namespace stride::console {

sim::SceneDescription logged_scene(const sim::SceneDescription& live, int robot,
                                   const model::RobotModel& model, const JointSensorData& joints,
                                   const InertialSensorData& imu,
                                   const std::optional<SimulatedTorsoPose>& pose) {
  sim::SceneDescription scene = live;
  scene.pushes.clear();  // nothing happens in a picture
  sim::RobotPlacement& p = scene.robots.at(static_cast<std::size_t>(robot));
  p.joints.clear();
  for (int i = 0; i < hal::kNumJoints; ++i) {
    const std::string name(hal::kJointNames[static_cast<std::size_t>(i)]);
    const int j = model.joint_index(name);
    const double q = joints.position[static_cast<std::size_t>(i)];
    if (j < 0 || !model.joints[j].movable() || !std::isfinite(q)) continue;
    const auto& jt = model.joints[j];
    p.joints[name] = jt.type == model::JointType::Revolute ? std::clamp(q, jt.lower, jt.upper) : q;
  }
  if (pose) {
    p.xyz = {pose->x, pose->y, pose->z};
    p.rpy = {pose->roll, pose->pitch, pose->yaw};
    p.auto_height = false;
  } else {
    p.xyz = {0, 0, 0};
    p.rpy = {std::isfinite(imu.angles.x()) ? imu.angles.x() : 0.0,
             std::isfinite(imu.angles.y()) ? imu.angles.y() : 0.0, 0.0};
    p.auto_height = true;  // the lowest point on the ground, as the view stands a real robot
  }
  return scene;
}

}  // namespace stride::console
