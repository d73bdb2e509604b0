#include "behaviours/module_catalogue.hpp"

#include "behaviours/balance/modules/balance_modules.hpp"
#include "behaviours/identify/excitation_module.hpp"
#include "behaviours/joint_state/joint_velocities.hpp"
#include "behaviours/landing/landing_control.hpp"
#include "behaviours/landing/landing_modules.hpp"
#include "behaviours/posture/posture_modules.hpp"
#include "behaviours/push_recovery/push_recovery_walk.hpp"
#include "behaviours/stand/stand.hpp"
#include "behaviours/swing_leg/swing_leg_tracking.hpp"
#include "behaviours/walking/modules/pattern_walk.hpp"
#include "robot/runtime/nao_io_modules.hpp"

namespace stride::behaviours {

void register_all_modules(ModuleRegistry& registry) {
  register_nao_io_modules(registry);
  register_stand(registry);
  register_excitation(registry);
  register_walking_modules(registry);
  register_posture_modules(registry);
  register_balance_modules(registry);
  register_joint_state_modules(registry);
  register_swing_leg_tracking(registry);
  register_landing_modules(registry);
  register_landing_control(registry);
  register_push_recovery_modules(registry);
}

}  // namespace stride::behaviours
