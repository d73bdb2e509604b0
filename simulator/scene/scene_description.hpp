#pragma once
// A scene as plain data: everything the world is built from. Parsed and validated completely
// before any world exists, so a bad file never half-loads.
#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "robot/hal/controller_config.hpp"
#include "simulator/scene/device_description.hpp"

namespace stride::sim {

// <contact>: one compliant contact law that every engine realises alike (world/contact_law.hpp):
// a linear spring and damper in the normal direction, hard Coulomb friction within a cone.
struct ContactLaw {
  double stiffness =
      0;  // N/m: a body's whole spring against the static scene (per_body), or a point's
  double damping = 0;    // N s/m, likewise
  bool per_body = true;  // split over however many points the collider finds for the body that step
  double friction = 0.8;  // the robot's geoms, and every surface that states no friction of its own
  // elliptic: |f_t| <= mu f_n (on ODE a pyramid turned to the slip each step); pyramid:
  // |f_t1| <= mu f_n and |f_t2| <= mu f_n, t1 along world x in the contact plane
  enum class Cone { Pyramid, Elliptic } cone = Cone::Elliptic;
  std::string file;  // where <contact> was written, for what an engine cannot realise
  int line = 0;
};

struct PhysicsSettings {
  // ode (default) or mujoco, the optional second engine (STRIDE_MUJOCO).
  enum class Engine { Ode, Mujoco } engine = Engine::Ode;
  std::string file;  // where <physics> was written (empty: defaults), for engine errors
  int line = 0;
  double step = 0.001;  // s
  // exact: ODE's dWorldStep, MuJoCo's Newton; iterative: ODE's quickstep, MuJoCo's PGS;
  // cg: MuJoCo's conjugate gradient (MuJoCo only). Newton and CG run to convergence.
  enum class Solver { Exact, Iterative, Cg } solver = Solver::Iterative;
  // Iterative solver only. Walking studies state 20 (docs/solver-settings.md).
  int iterations = 10;
  double sor = 1.3;  // over-relaxation of the iterative solver
  double erp = 0.2;
  double cfm = 1e-5;
  double contact_erp = 0.2;
  double contact_cfm = 1e-4;
  // contact_spring_per="body": contact_erp/cfm stand for a body's whole contact with the static
  // scene, shared over however many points the collider finds for it in a step.
  bool contact_spring_per_body = false;
  int max_contacts = 8;  // per colliding geometry pair
  // MuJoCo only (mujoco_options.hpp): friction cone, no-slip pass, contact solref and solimp.
  enum class Cone { Elliptic, Pyramidal } cone = Cone::Elliptic;
  int noslip_iterations = 10;
  double contact_timeconst = 0.02;  // s, solref[0]
  double contact_dampratio = 1.0;   // solref[1]
  double contact_dmin = 0.9;        // solimp[0]
  double contact_dmax = 0.95;       // solimp[1]
  Eigen::Vector3d gravity{0, 0, -9.81};
  std::uint64_t seed = 1;
  std::optional<ContactLaw>
      contact_law;  // <contact>; replaces the engine-specific contact settings
};

struct GroundSettings {
  bool enabled = true;
  double friction = 0.8;
};

struct StaticBox {
  std::string name;
  Eigen::Vector3d size{1, 1, 1};
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  double friction = 0.8;
  int line = 0;
};

// A grid of thin tiles with seeded heights and tilts: a flat floor with local unevenness.
struct UnevenPatch {
  std::string name;
  Eigen::Vector2d centre{0, 0};
  Eigen::Vector2d size{2, 1};
  double cell = 0.05;         // tile edge, m
  double max_height = 0.003;  // tile tops uniformly in [0, max_height]
  double max_tilt = 0.02;     // rad, each tile tilted uniformly in [-max_tilt, max_tilt] per axis
  double friction = 0.8;
  std::uint64_t seed = 0;  // 0: derived from the scene seed

  // Tiles along x and y: the size in whole cells, at least one.
  int tiles_x() const { return std::max(1, static_cast<int>(size.x() / cell + 0.5)); }
  int tiles_y() const { return std::max(1, static_cast<int>(size.y() / cell + 0.5)); }
};

inline long uneven_tile_count(const UnevenPatch& u) {
  return static_cast<long>(u.tiles_x()) * u.tiles_y();
}

struct SensorSwitches {
  bool noise = true;
  bool delay = true;
  bool quantise = true;
};

struct RobotPlacement {
  std::string name;
  std::string urdf;     // resolved path
  std::string devices;  // resolved path
  Eigen::Vector3d xyz{0, 0, 0};
  bool auto_height = true;  // put the lowest collision point on z = 0
  Eigen::Vector3d rpy{0, 0, 0};
  std::map<std::string, double> joints;  // initial joint angles by name
  int joints_line = 0;
  bool fixed_base = false;  // weld the root link to the world (test rigs, swing-leg studies)
  double stiffness = 1.0;   // servo stiffness held until a controller commands otherwise
  double period = 0;        // s; control period overriding the device file's (0: keep it)
  std::vector<MotorOverride> motors;             // <motor> changes to the device file, in order
  std::vector<ServoOverride> servos;             // <servo> calibration errors, in order
  std::optional<CalibrationSpread> calibration;  // <calibration>: seeded zero errors
  std::optional<Eigen::Vector3d> gyro_bias;      // <imu gyro_bias>: rad/s, over the device file's
  bool has_controller = false;
  ControllerConfig controller;
  SensorSwitches sensors;
  double fall_tilt = 0.8;     // rad: |roll| or |pitch| of the torso beyond this = fallen
  double fall_height = 0.18;  // m: torso origin below this = fallen
  std::string file;           // where it was written, for errors found at build time
  int line = 0;
};

struct TimedPush {
  std::string robot;
  std::string body;
  Eigen::Vector3d force{0, 0, 0};  // N, world frame
  Eigen::Vector3d at{0, 0, 0};     // application point in the body frame
  double start = 0, duration = 0;  // s
  std::string file;                // where it was written, for errors found at build time
  int line = 0;
};

// A viewpoint for snapshots and videos, named so `snapshot <file> <name>` can pick it.
struct SceneCamera {
  std::string name;
  Eigen::Vector3d eye{1.0, -0.8, 0.5};
  Eigen::Vector3d look_at{0, 0, 0.25};
  double fov = 0.8;  // vertical field of view, rad
  int width = 640, height = 480;
  int line = 0;
};

// A directional light for snapshots (the renderer's default light is used when none is given).
struct SceneLight {
  Eigen::Vector3d direction{-0.4, 0.3, -1.0};  // the way the light travels
  double intensity = 0.8;
};

struct SceneDescription {
  std::string name;
  std::string file;  // top-level file
  PhysicsSettings physics;
  GroundSettings ground;
  std::vector<StaticBox> boxes;  // includes ramps
  std::vector<UnevenPatch> uneven;
  std::vector<RobotPlacement> robots;
  std::vector<TimedPush> pushes;
  std::vector<SceneCamera> cameras;
  std::vector<SceneLight> lights;
};

}  // namespace stride::sim
