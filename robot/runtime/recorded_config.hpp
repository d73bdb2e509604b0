#pragma once
// The controller configuration a log is recorded with (providers and parameters), kept in its
// metadata as "provider:<Representation>" and "parameter:<Module>.<field>", so that a log
// recorded after `mr` or `set module:` replays with what actually ran; and `log info`.
#include <string>
#include <vector>

#include "robot/runtime/log.hpp"
#include "robot/runtime/runtime_config.hpp"

namespace stride {

LogMetadata config_metadata(const RuntimeConfig& config);
// Whether the log says what it was recorded with (logs written before they did do not).
bool has_recorded_config(const LogMetadata& metadata);
// The recorded providers and parameters, keeping the rest of `fallback` (robot model, error
// policy); `fallback` itself for
// a log that does not carry them.
RuntimeConfig recorded_config(const LogMetadata& metadata, RuntimeConfig fallback);

// `log info`: frames, representations and the recorded configuration, one fact a line.
std::vector<std::string> log_info_lines(const LogReader& log);

}  // namespace stride
