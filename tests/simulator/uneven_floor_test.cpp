// The uneven floor is the same surface on both engines, however each holds it: the height a
// vertical ray finds at sample points equals the tile model's (each tile a box at its seeded
// height and tilt, the ground plane beneath), and MuJoCo's blocks of static bodies place every
// tile exactly where the tile model says.
#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "simulator/world/ode/ode_world.hpp"
#ifdef STRIDE_HAVE_MUJOCO
#include "simulator/world/mujoco/mj_world.hpp"
#include "simulator/world/mujoco/tile_blocks.hpp"
#endif
#include "robot/model/urdf_loader.hpp"
#include "tests/simulator/sim_test_util.hpp"

namespace stride {
namespace {

// hip_medium.xml's floor and seed, a block above it.
const char* kScene = R"(<scene><physics seed="1"/>
  <uneven centre="2.1 0" size="4 1.2" cell="0.05" height="3mm" tilt="1deg" seed="7"/>
  <robot name="b" urdf="block.urdf" xyz="0 0 0.5"/></scene>)";

std::vector<sim::StaticBox> tiles_of(const sim::SceneDescription& scene) {
  return sim::uneven_tiles(scene.uneven.at(0), sim::uneven_patch_seed(scene, 0));
}

// Where a ray straight down from (x, y, 1) first meets the box, by slabs in the box's frame.
std::optional<double> ray_hit(const sim::StaticBox& b, double x, double y) {
  const Eigen::Matrix3d rt = b.pose.linear().transpose();
  const Eigen::Vector3d o = rt * (Eigen::Vector3d(x, y, 1) - b.pose.translation());
  const Eigen::Vector3d d = rt * Eigen::Vector3d(0, 0, -1);
  double t0 = -INFINITY, t1 = INFINITY;
  for (int k = 0; k < 3; ++k) {
    const double h = b.size[k] / 2;
    if (std::abs(d[k]) < 1e-15) {
      if (std::abs(o[k]) > h) return std::nullopt;
      continue;
    }
    const double a = (-h - o[k]) / d[k], c = (h - o[k]) / d[k];
    t0 = std::max(t0, std::min(a, c));
    t1 = std::min(t1, std::max(a, c));
  }
  if (t0 > t1 || t1 < 0) return std::nullopt;
  return 1 - t0;
}

// The tile model's surface height: the highest tile top over (x, y), or the ground's 0.
double model_height(const std::vector<sim::StaticBox>& tiles, double x, double y) {
  double z = 0;
  for (const auto& t : tiles)
    if (auto h = ray_hit(t, x, y)) z = std::max(z, *h);
  return z;
}

// Sample points over the patch and 5 cm beyond it, a few of them on tile edges and corners.
std::vector<Eigen::Vector2d> sample_points(const sim::UnevenPatch& u) {
  EXPECT_EQ(u.tiles_x() * u.tiles_y(), 80 * 24);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> ux(u.centre.x() - u.size.x() / 2 - 0.05,
                                            u.centre.x() + u.size.x() / 2 + 0.05);
  std::uniform_real_distribution<double> uy(u.centre.y() - u.size.y() / 2 - 0.05,
                                            u.centre.y() + u.size.y() / 2 + 0.05);
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < 400; ++i) points.emplace_back(ux(rng), uy(rng));
  for (int i = 0; i < 40; ++i)  // near tile corners, within a tilt's overhang
    points.emplace_back(u.centre.x() - u.size.x() / 2 + u.cell * (i % 20 + 1) + 1e-4 * (i % 3 - 1),
                        u.centre.y() - u.size.y() / 2 + u.cell * (i / 2 + 1) - 1e-4 * (i % 2));
  return points;
}

double ode_height(sim::OdeWorld& world, dGeomID ray, double x, double y) {
  dGeomRaySet(ray, x, y, 1, 0, 0, -1);
  double z = -INFINITY;
  for (int i = 0; i < dSpaceGetNumGeoms(world.static_space()); ++i) {
    dContactGeom c;
    if (dCollide(ray, dSpaceGetGeom(world.static_space(), i), 1, &c, sizeof c) > 0)
      z = std::max(z, double(c.pos[2]));
  }
  return z;
}

TEST(UnevenFloor, OdeSurfaceIsTheTileModels) {
  auto sim = test::scene_from_text(kScene);
  const auto tiles = tiles_of(sim->scene());
  auto& world = dynamic_cast<sim::OdeWorld&>(sim->world());
  ASSERT_EQ(world.static_geom_count(), 1 + 80 * 24);
  dGeomID ray = dCreateRay(nullptr, 2);
  int on_tiles = 0;
  for (const auto& p : sample_points(sim->scene().uneven[0])) {
    const double expected = model_height(tiles, p.x(), p.y());
    EXPECT_NEAR(ode_height(world, ray, p.x(), p.y()), expected, 1e-12) << p.transpose();
    on_tiles += expected > 0;
  }
  dGeomDestroy(ray);
  EXPECT_GT(on_tiles, 300);  // most samples meet a tile, not the ground
}

#ifdef STRIDE_HAVE_MUJOCO

// Every tile in exactly one block, each block's tiles within one block edge of each other, in
// the 5 x 5 blocks the edge gives the 5 cm floor (the last row of blocks 4 tiles deep).
TEST(UnevenFloor, TilesGroupIntoBlocksOfNearbyTiles) {
  const auto tiles = tiles_of(sim::parse_scene_text(kScene, test::source_path("tests/data/x.xml")));
  const auto blocks = sim::group_tiles(tiles, sim::kTileBlockEdge);
  ASSERT_EQ(blocks.size(), 16u * 5u);
  std::size_t total = 0;
  std::set<std::pair<double, double>> seen;
  for (const auto& b : blocks) {
    EXPECT_TRUE(b.size() == 25 || b.size() == 20) << b.size();
    total += b.size();
    for (const auto& t : b) {
      seen.insert({t.pose.translation().x(), t.pose.translation().y()});
      EXPECT_LT((t.pose.translation() - b.front().pose.translation()).head<2>().norm(),
                sim::kTileBlockEdge * std::sqrt(2.0));
    }
  }
  EXPECT_EQ(total, tiles.size());
  EXPECT_EQ(seen.size(), tiles.size());
  EXPECT_TRUE(sim::group_tiles({}, 0.25).empty());
}

// MuJoCo's tiles in blocks sit exactly where they sat as world geoms (the representation before
// the blocks), in static bodies (welded to the world, not the world body itself), within
// rounding of the tile model's poses; its rays find the tile model's surface.
TEST(UnevenFloor, MujocoSurfaceIsTheTileModels) {
  auto sim = test::scene_from_text(test::on_engine(kScene, "mujoco"));
  const auto tiles = tiles_of(sim->scene());
  const auto& world = dynamic_cast<const sim::MjWorld&>(sim->world());
  const mjModel* m = world.model();
  const mjData* d = world.data();
  ASSERT_EQ(world.static_geom_count(), 1 + 80 * 24);
  sim::MjWorld as_boxes(sim->scene().physics, sim->scene().ground);
  for (const auto& t : tiles) as_boxes.add_static_box(t);
  const model::RobotModel block = model::load_urdf(test::source_path("tests/data/block.urdf"));
  as_boxes.add_robot(block, 0, Eigen::Isometry3d::Identity(),
                     model::JointVector::Zero(static_cast<int>(block.joints.size())));
  const mjModel* m0 = as_boxes.model();
  const mjData* d0 = as_boxes.data();
  ASSERT_EQ(m->ngeom, m0->ngeom);
  // Blocks follow the robot, in group_tiles' order; as world geoms the tiles followed the plane.
  const auto blocks = sim::group_tiles(tiles, sim::kTileBlockEdge);
  int g = m->ngeom - static_cast<int>(tiles.size());
  for (const auto& blk : blocks)
    for (const auto& t : blk) {
      const auto k0 = std::find_if(tiles.begin(), tiles.end(), [&](const sim::StaticBox& o) {
        return o.pose.translation() == t.pose.translation();
      });
      const int g0 = 1 + static_cast<int>(k0 - tiles.begin());
      const int b = m->geom_bodyid[g];
      ASSERT_NE(b, 0);
      ASSERT_EQ(m->body_weldid[b], 0);
      ASSERT_EQ(m0->geom_bodyid[g0], 0);
      for (int k = 0; k < 3; ++k) {
        ASSERT_EQ(d->geom_xpos[3 * g + k], d0->geom_xpos[3 * g0 + k]) << g;
        ASSERT_EQ(d->geom_xpos[3 * g + k], t.pose.translation()[k]) << g;
        ASSERT_EQ(m->geom_size[3 * g + k], m0->geom_size[3 * g0 + k]) << g;
        for (int j = 0; j < 3; ++j) {
          ASSERT_EQ(d->geom_xmat[9 * g + 3 * k + j], d0->geom_xmat[9 * g0 + 3 * k + j]) << g;
          ASSERT_NEAR(d->geom_xmat[9 * g + 3 * k + j], t.pose.linear()(k, j), 1e-15) << g;
        }
      }
      ++g;
    }
  for (const auto& p : sample_points(sim->scene().uneven[0])) {
    const mjtNum from[3] = {p.x(), p.y(), 1}, down[3] = {0, 0, -1};
    int hit = -1;
    const double dist = mj_ray(m, d, from, down, nullptr, 1, -1, &hit);
    ASSERT_GE(hit, 0);
    EXPECT_NEAR(1 - dist, model_height(tiles, p.x(), p.y()), 1e-12) << p.transpose();
  }
}

#endif

}  // namespace
}  // namespace stride
