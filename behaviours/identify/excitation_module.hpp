#pragma once
// The Excitation module (provides JointRequest): plays an excitation motion for identification.
#include "robot/framework/module_registry.hpp"

namespace stride::behaviours {

void register_excitation(ModuleRegistry& registry);

}  // namespace stride::behaviours
