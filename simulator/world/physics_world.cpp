#include "simulator/world/physics_world.hpp"

#include "simulator/scene/noise_source.hpp"

namespace stride::sim {

std::vector<StaticBox> uneven_tiles(const UnevenPatch& patch, std::uint64_t seed) {
  std::vector<StaticBox> tiles;
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
      tiles.push_back(tile);
    }
  return tiles;
}

void PhysicsWorld::add_uneven_patch(const UnevenPatch& patch, std::uint64_t seed) {
  for (const StaticBox& tile : uneven_tiles(patch, seed)) add_static_box(tile);
}

std::uint64_t uneven_patch_seed(const SceneDescription& scene, std::size_t i) {
  const UnevenPatch& u = scene.uneven[i];
  return u.seed ? u.seed : scene.physics.seed * 7919 + i + 1;
}

}  // namespace stride::sim
