// Under the contact law MuJoCo's world holds the uneven floor's tiles outside its model and finds
// the robot's contacts with them itself (mj_tile_contacts.hpp). They must be the contacts MuJoCo
// found with the tiles in its model, bit for bit and in the same order: a NAO dropped onto the
// hip walk's floor with weak motors, so that it lands on its soles and then falls on the tiles,
// gives the same contact list every step and the same state at the end in both worlds.
#include <cstring>
#include <iostream>

#include <gtest/gtest.h>

#include "robot/model/urdf_loader.hpp"
#ifdef STRIDE_HAVE_MUJOCO
#include "simulator/world/mujoco/mj_world.hpp"
#include "simulator/world/robot_body.hpp"
#endif
#include "tests/simulator/sim_test_util.hpp"

namespace stride {
namespace {
#ifdef STRIDE_HAVE_MUJOCO

struct Dropped {
  std::unique_ptr<sim::MjWorld> world;
  std::unique_ptr<sim::RobotBody> robot;
};

Dropped drop_nao(const sim::SceneDescription& scene, const model::RobotModel& nao, bool in_model) {
  Dropped r{std::make_unique<sim::MjWorld>(scene.physics, scene.ground), nullptr};
  if (in_model) r.world->hold_tiles_in_model();
  r.world->add_uneven_patch(scene.uneven.at(0), sim::uneven_patch_seed(scene, 0));
  Eigen::Isometry3d root = Eigen::Isometry3d::Identity();
  root.translation() = Eigen::Vector3d(1.02, 0.03, 0.36);  // soles 2-3 cm above the tiles
  r.robot = r.world->add_robot(nao, 0, root,
                               model::JointVector::Zero(static_cast<int>(nao.joints.size())));
  for (int j = 0; j < static_cast<int>(nao.joints.size()); ++j)
    if (r.robot->is_hinge(j)) r.robot->set_motor_max_torque(j, 0.4);  // too weak to stand
  return r;
}

bool same_bits(const double* a, const double* b, int n) {
  return std::memcmp(a, b, sizeof(double) * static_cast<std::size_t>(n)) == 0;
}

TEST(MujocoTileContacts, SameContactsAsWithTheTilesInTheModel) {
  const auto scene =
      sim::parse_scene_file(test::source_path("scenes/experiments/hip_medium.xml"),
                            sim::parse_physics_setting("engine=mujoco,solver=exact"));
  ASSERT_TRUE(scene.physics.contact_law);
  const model::RobotModel nao = model::load_urdf(test::source_path("scenes/robots/nao/nao.urdf"));
  Dropped out = drop_nao(scene, nao, false), in = drop_nao(scene, nao, true);
  ASSERT_FALSE(out.world->tiles_in_model());
  ASSERT_TRUE(in.world->tiles_in_model());
  // The tiles left the model: the robot, the ground and one probe geom.
  EXPECT_EQ(in.world->model()->ngeom - out.world->model()->ngeom, 80 * 24 - 1);
  const int first_probe = out.world->model()->ngeom - 1;
  int box_tile = 0, other_tile = 0, steps_on_tiles = 0;
  for (int step = 0; step < 1500; ++step) {
    out.world->step();
    in.world->step();
    const mjData* a = out.world->data();
    const mjData* b = in.world->data();
    ASSERT_EQ(a->ncon, b->ncon) << "step " << step;
    bool on_tiles = false;
    for (int i = 0; i < a->ncon; ++i) {
      const mjContact& p = a->contact[i];
      const mjContact& q = b->contact[i];
      ASSERT_EQ(p.geom1, q.geom1) << "step " << step << " contact " << i;
      const bool tile = p.geom2 >= first_probe;
      if (!tile) ASSERT_EQ(p.geom2, q.geom2) << "step " << step << " contact " << i;
      // The tangents of a contact the law leaves out are any two (the law writes its own).
      const int frame = p.efc_address >= 0 ? 9 : 3;
      ASSERT_TRUE(same_bits(&p.dist, &q.dist, 1) && same_bits(p.pos, q.pos, 3) &&
                  same_bits(p.frame, q.frame, frame) && same_bits(p.friction, q.friction, 5) &&
                  same_bits(p.solref, q.solref, mjNREF) && same_bits(p.solimp, q.solimp, mjNIMP))
          << "step " << step << " contact " << i << " dist " << p.dist << " " << q.dist << " pos "
          << p.pos[0] << " " << q.pos[0] << " n " << p.frame[0] << " " << q.frame[0] << " t "
          << p.frame[3] << " " << q.frame[3] << " fr " << p.friction[0] << " " << q.friction[0]
          << " efc " << p.efc_address << " " << q.efc_address << " geoms " << p.geom1 << " "
          << p.geom2 << " " << q.geom2 << " type " << out.world->model()->geom_type[p.geom1]
          << " ncon " << a->ncon;
      ASSERT_EQ(p.efc_address, q.efc_address) << "step " << step << " contact " << i;
      if (tile) {
        on_tiles = true;
        ++(out.world->model()->geom_type[p.geom1] == mjGEOM_BOX ? box_tile : other_tile);
      }
    }
    steps_on_tiles += on_tiles;
    ASSERT_TRUE(same_bits(a->qpos, b->qpos, out.world->model()->nq)) << "step " << step;
    ASSERT_TRUE(same_bits(a->qvel, b->qvel, out.world->model()->nv)) << "step " << step;
  }
  EXPECT_GT(steps_on_tiles, 1000);
  EXPECT_GT(box_tile, 1000);  // the soles
  EXPECT_GT(other_tile, 0);   // its head's sphere and its limbs' cylinders as it falls
  std::cout << "tile contacts: " << box_tile << " of soles, " << other_tile
            << " of other geoms over " << steps_on_tiles << " steps\n";
}

#endif
}  // namespace
}  // namespace stride
