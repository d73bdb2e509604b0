#include "simulator/world/physics_world.hpp"

#include "simulator/devices/noise_source.hpp"

namespace stride::sim {

void PhysicsWorld::add_uneven_patch(const UnevenPatch& patch, std::uint64_t seed) {
  NoiseSource rng(seed);
  const int nx = patch.tiles_x();
  const int ny = patch.tiles_y();
  const double thickness = 0.02;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      StaticBox tile;
      tile.size = Eigen::Vector3d(patch.cell, patch.cell, thickness);
      tile.friction = patch.friction;
      const double top = rng.uniform(0, patch.max_height);
      const double roll = rng.uniform(-patch.max_tilt, patch.max_tilt);
      const double pitch = rng.uniform(-patch.max_tilt, patch.max_tilt);
      tile.pose = Eigen::Isometry3d::Identity();
      tile.pose.linear() = (Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                               .toRotationMatrix();
      const Eigen::Vector3d centre(patch.centre.x() - patch.size.x() / 2 + (i + 0.5) * patch.cell,
                                   patch.centre.y() - patch.size.y() / 2 + (j + 0.5) * patch.cell,
                                   top - thickness / 2);
      tile.pose.translation() = centre;
      add_static_box(tile);
    }
}

}  // namespace stride::sim
