#include "simulator/world/ode/ode_world.hpp"
#include "simulator/world/physics_world.hpp"

namespace stride::sim {

std::unique_ptr<PhysicsWorld> make_physics_world(const PhysicsSettings& physics,
                                                 const GroundSettings& ground) {
  return std::make_unique<OdeWorld>(physics, ground);
}

}  // namespace stride::sim
