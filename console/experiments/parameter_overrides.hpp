#pragma once
// `stride experiment ... --set Module.field=value`: module parameters changed in every walk an
// experiment runs, before the experiment's own settings (so the experiment's value still wins).
#include <string>
#include <utility>

#include "console/experiments/experiment_options.hpp"
#include "console/experiments/walk_recording.hpp"

namespace stride::experiments {

// "Module.field=value" -> {"Module", "field=value"}; throws stride::Error naming the text.
std::pair<std::string, std::string> parse_parameter_override(const std::string& text);

// The setup with o's overrides ahead of its own parameters.
WalkSetup with_overrides(const ExperimentOptions& o, WalkSetup setup);

}  // namespace stride::experiments
