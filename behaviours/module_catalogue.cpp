#include "behaviours/module_catalogue.hpp"

#include "behaviours/stand/stand.hpp"
#include "robot/runtime/nao_io_modules.hpp"

namespace stride::behaviours {

void register_all_modules(ModuleRegistry& registry) {
  register_nao_io_modules(registry);
  register_stand(registry);
}

}  // namespace stride::behaviours
