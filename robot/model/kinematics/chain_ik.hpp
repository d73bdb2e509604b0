#pragma once
// Inverse kinematics of any of the five NAO chains: the legs in closed form (nao_leg_ik), the
// arms and the head by damped least squares on the URDF model, with the end effector chain_fk
// uses (the hand point kHandOffsetX ahead of the wrist, the head link's origin).
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "robot/model/kinematics/nao_chains.hpp"

namespace stride::model {

struct ChainIkResult {
  std::vector<double> q;   // chain order (chain_joints)
  bool reachable = false;  // the leg's pose within reach, or the iteration converged
  double residual = 0;     // m, the leg's position error or the iteration's final error
};

// `urdf`: the model file the arms and head are solved on (read only for them); throws
// stride::Error if it cannot be read.
ChainIkResult chain_ik(NaoChain chain, const Eigen::Isometry3d& target, const std::string& urdf);

}  // namespace stride::model
