#pragma once
// One contact of the last physics step with the force the solver applied (for force sensors).
#include <ode/ode.h>

#include "simulator/world/geom_info.hpp"

namespace stride::sim {

struct ContactRecord {
  const GeomInfo* a = nullptr;  // ODE body1 side
  const GeomInfo* b = nullptr;  // ODE body2 side (may be static)
  dVector3 position{};
  dJointFeedback* feedback = nullptr;  // forces on body1 (f1, t1) and body2 (f2, t2)
};

}  // namespace stride::sim
