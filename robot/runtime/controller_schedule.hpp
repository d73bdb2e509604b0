#pragma once
// A controller's timed changes (<at time> in a <controller> section) applied to its Runtime at
// the first control frame at or after their time, in the order written.
#include <cstddef>
#include <vector>

#include "robot/hal/controller_config.hpp"
#include "robot/runtime/runtime.hpp"

namespace stride {

// A provider swap or a parameter value, now.
void apply_change(Runtime& rt, const ControllerChange& c);

// Tries every change in order on a scratch Runtime built like the real one, so that a bad change
// fails when the configuration is loaded (file:line: <at>: ...), not minutes into a run.
void check_changes(const ModuleRegistry& registry, const RuntimeConfig& config,
                   hal::HardwareLink& link, const std::vector<ControllerChange>& changes);

class ControllerSchedule {
 public:
  explicit ControllerSchedule(std::vector<ControllerChange> changes)
      : changes_(std::move(changes)) {}
  // Applies every change due at `time` (s since the controller started) not applied yet.
  void apply_due(Runtime& rt, double time);
  std::size_t applied() const { return next_; }

 private:
  std::vector<ControllerChange> changes_;
  std::size_t next_ = 0;
};

}  // namespace stride
