#pragma once
// Shared test helpers: the NAO URDF model and random joint configurations within the limits.
#include <random>

#include "robot/hal/joint_id.hpp"
#include "robot/model/kinematics/nao_joint_map.hpp"
#include "robot/model/urdf_loader.hpp"

namespace stride::model::test {

inline const RobotModel& nao_model() {
  static const RobotModel model = load_urdf(STRIDE_SOURCE_DIR "/scenes/robots/nao/nao.urdf");
  return model;
}

// Uniform within each joint's URDF limits; LoLA order.
inline std::array<double, hal::kNumJoints> random_lola(std::mt19937& rng) {
  static const NaoJointMap map = make_nao_joint_map(nao_model());
  std::array<double, hal::kNumJoints> q{};
  for (int i = 0; i < hal::kNumJoints; ++i) {
    const int j = map.model_index[i];
    if (j < 0) continue;
    const Joint& jt = nao_model().joints[j];
    q[i] = std::uniform_real_distribution<double>(jt.lower, jt.upper)(rng);
  }
  return q;
}

inline double pose_error(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.matrix() - b.matrix()).cwiseAbs().maxCoeff();
}

}  // namespace stride::model::test
