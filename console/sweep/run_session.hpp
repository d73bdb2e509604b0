#pragma once
// A run's world: its scene file with the run's scene edits and seed, then its providers and
// module parameters applied to robot 0's controller, as `mr` and `set module:...` would.
#include <memory>

#include "console/session/sim_session.hpp"
#include "console/sweep/run_plan.hpp"

namespace stride::sweep {

// Throws stride::Error naming the scene and the setting that failed.
std::unique_ptr<console::SimSession> build_run_session(const SweepSpec& spec, const RunPlan& run);

// Checks a setting's target ("scene", "seed", "provider:X", "scene:...@attr", "Module.field");
// throws stride::Error saying what was expected.
void check_setting_target(const std::string& target);

}  // namespace stride::sweep
