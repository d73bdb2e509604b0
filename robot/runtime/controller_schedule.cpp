#include "robot/runtime/controller_schedule.hpp"

namespace stride {

void apply_change(Runtime& rt, const ControllerChange& c) {
  if (c.kind == ControllerChange::Kind::Provider) {
    rt.swap_provider(c.first, c.second);
    return;
  }
  const auto dot = c.first.find('.');
  rt.set_parameters(c.first.substr(0, dot), c.first.substr(dot + 1) + "=" + c.second);
}

void check_changes(const ModuleRegistry& registry, const RuntimeConfig& config,
                   hal::HardwareLink& link, const std::vector<ControllerChange>& changes) {
  if (changes.empty()) return;
  Runtime scratch(registry, config, link);
  for (const auto& c : changes) {
    try {
      apply_change(scratch, c);
    } catch (const Error& e) {
      throw input_error_at(c.file, c.line, "<at>: " + std::string(e.what()));
    }
  }
}

void ControllerSchedule::apply_due(Runtime& rt, double time) {
  // 1e-9 s: a change written at a frame's time applies at that frame despite rounding.
  while (next_ < changes_.size() && changes_[next_].time <= time + 1e-9)
    apply_change(rt, changes_[next_++]);
}

}  // namespace stride
