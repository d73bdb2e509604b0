#include "simulator/world/ode/ode_context.hpp"

#include <ode/ode.h>

namespace stride::sim {

void ensure_ode_initialised() {
  // ODE keeps library state; a function-local static makes the one-time call thread-safe.
  static const bool initialised = [] {
    dInitODE2(0);
    dAllocateODEDataForThread(dAllocateMaskAll);
    return true;
  }();
  (void)initialised;
}

}  // namespace stride::sim
