#pragma once
// One contact of the last physics step with the force the solver applied (for force sensors).
#include <Eigen/Core>

#include "simulator/world/geom_info.hpp"

namespace stride::sim {

struct ContactRecord {
  const GeomInfo* a = nullptr;                         // first side
  const GeomInfo* b = nullptr;                         // second side (may be static)
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // world frame
  Eigen::Vector3d force_on_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_on_b = Eigen::Vector3d::Zero();
};

}  // namespace stride::sim
