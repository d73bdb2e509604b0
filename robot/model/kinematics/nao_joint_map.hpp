#pragma once
// Maps between LoLA-ordered NAO joint arrays and a RobotModel's joint vector (by joint name).
#include <array>
#include <span>

#include "robot/hal/joint_id.hpp"
#include "robot/model/link_poses.hpp"

namespace stride::model {

// model joint index of every LoLA joint (-1 if the model lacks it); built once per model.
struct NaoJointMap {
  std::array<int, hal::kNumJoints> model_index{};
  int rhip_yaw_pitch = -1;  // the mimic joint LoLA does not list
};

NaoJointMap make_nao_joint_map(const RobotModel& model);

// Writes the LoLA angles into q (sized to the model) and applies the mimic joints.
void joints_from_lola(const RobotModel& model, const NaoJointMap& map,
                      std::span<const double, hal::kNumJoints> lola, JointVector& q);

// Reads the LoLA angles back out of a model joint vector (absent joints read 0).
void joints_to_lola(const NaoJointMap& map, const JointVector& q,
                    std::span<double, hal::kNumJoints> lola);

}  // namespace stride::model
