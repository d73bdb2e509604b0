#include "robot/core/error.hpp"
#include "simulator/world/ode/ode_world.hpp"
#include "simulator/world/physics_world.hpp"
#ifdef STRIDE_HAVE_MUJOCO
#include "simulator/world/mujoco/mj_world.hpp"
#endif

namespace stride::sim {

std::unique_ptr<PhysicsWorld> make_physics_world(const PhysicsSettings& physics,
                                                 const GroundSettings& ground) {
  if (physics.engine == PhysicsSettings::Engine::Mujoco) {
#ifdef STRIDE_HAVE_MUJOCO
    return std::make_unique<MjWorld>(physics, ground);
#else
    throw error_at(physics.file, physics.line,
                   "<physics>: attribute 'engine': mujoco is not built into this stride");
#endif
  }
  return std::make_unique<OdeWorld>(physics, ground);
}

}  // namespace stride::sim
