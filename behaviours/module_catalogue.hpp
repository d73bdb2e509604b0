#pragma once
// Every module Stride ships, registered by name: the NAO I/O conversions and the thesis'
// behaviours.
#include "robot/framework/module_registry.hpp"

namespace stride::behaviours {

void register_all_modules(ModuleRegistry& registry);

}  // namespace stride::behaviours
