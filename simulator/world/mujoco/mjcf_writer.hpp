#pragma once
// MJCF text for MuJoCo from Stride's own parsed scene and robot models: ground, static boxes,
// robots as body trees in their zero configuration (root at its placement), hinge/slide joints,
// inertials and collision primitives. Geoms are written in a fixed order that the world's
// GeomInfo table follows.
#include <string>
#include <vector>

#include <mujoco/mujoco.h>
#include <Eigen/Geometry>

#include "robot/model/robot_model.hpp"
#include "simulator/scene/scene_description.hpp"
#include "simulator/world/geom_info.hpp"

namespace stride::sim {

// A robot geom's friction without a contact law; a pair uses the smaller one, as in the ODE world.
constexpr double kRobotGeomFriction = 0.8;

struct MjcfRobot {
  const model::RobotModel* model = nullptr;
  int robot_index = 0;
  Eigen::Isometry3d root_pose = Eigen::Isometry3d::Identity();
  bool fixed = false;
  double friction = kRobotGeomFriction;  // its geoms' (write_mjcf sets the scene's)
};

// The MJCF document, and in `geoms` the GeomInfo of every geom in MuJoCo's geom order. Each
// of `tile_blocks` becomes one static body holding its boxes (tile_blocks.hpp); each of
// `tile_probes` (a patch's friction) a static body after the robots holding one box that collides
// with nothing (mj_tile_contacts.hpp).
std::string write_mjcf(const PhysicsSettings& physics, const GroundSettings& ground,
                       const std::vector<StaticBox>& boxes,
                       const std::vector<std::vector<StaticBox>>& tile_blocks,
                       const std::vector<MjcfRobot>& robots, std::vector<GeomInfo>& geoms,
                       const std::vector<double>& tile_probes = {});

// The compiled model of MJCF text, loaded through a one-file virtual file system (nothing touches
// the disk); throws stride::Error with MuJoCo's message if it does not compile.
mjModel* load_mjcf(const std::string& xml);

// MJCF names of robot `r`'s link `l` and joint `j` bodies/joints.
std::string mjcf_link_name(int r, int l);
std::string mjcf_joint_name(int r, int j);

}  // namespace stride::sim
