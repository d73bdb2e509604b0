#include "robot/runtime/runtime_events.hpp"

#include <cstdio>

namespace stride {

namespace {
std::string fixed(double x, int digits) {
  char b[32];
  std::snprintf(b, sizeof b, "%.*f", digits, x);
  return b;
}
}  // namespace

void RuntimeEvents::after_frame(double time, double tilt, double fall_tilt,
                                const CommandSafety& safety, std::vector<std::string>& lines) {
  // Standing up again (well inside the threshold for 2 s: not a bounce) re-arms the fall line.
  if (!fallen_ && tilt > fall_tilt) {
    fallen_ = true;
    upright_since_ = -1;
    lines.push_back("event: FELL at t=" + fixed(time, 2) + " s (IMU tilt " + fixed(tilt, 2) +
                    " rad past fall_tilt " + fixed(fall_tilt, 2) + ")");
  } else if (fallen_) {
    if (tilt < 0 || tilt >= 0.5 * fall_tilt)
      upright_since_ = -1;
    else if (upright_since_ < 0)
      upright_since_ = time;
    else if (time - upright_since_ >= 2.0)
      fallen_ = false;
  }
  // Limits and NaN holds: a line when they start after a quiet second, not every frame.
  if (safety.clamped_positions > last_.clamped_positions && time - last_clamp_ > 1.0)
    lines.push_back("event: joint request limited at t=" + fixed(time, 2) +
                    " s: " + std::to_string(safety.clamped_positions - last_.clamped_positions) +
                    " position(s) clamped onto joint limits (get representation:CommandSafety)");
  if (safety.clamped_positions > last_.clamped_positions) last_clamp_ = time;
  if (safety.nonfinite_held > last_.nonfinite_held && time - last_nonfinite_ > 1.0)
    lines.push_back("event: NaN/inf joint command at t=" + fixed(time, 2) +
                    " s: " + std::to_string(safety.nonfinite_held - last_.nonfinite_held) +
                    " joint(s) held at their last valid position");
  if (safety.nonfinite_held > last_.nonfinite_held) last_nonfinite_ = time;
  last_ = safety;
}

void RuntimeEvents::link_lost(bool lost, double now, std::vector<std::string>& lines) {
  // A late packet is a stall the link rides out; no frame for kLostAfter seconds is a lost link.
  if (!lost) lost_since_ = -1;
  if (lost && lost_since_ < 0) lost_since_ = now;
  if (lost && !link_lost_ && now - lost_since_ >= kLostAfter) {
    link_lost_ = true;
    lines.push_back("event: hardware link lost: no sensor frame for " +
                    fixed(now - lost_since_, 2) + " s (holding the last command)");
  } else if (!lost && link_lost_) {
    link_lost_ = false;
    lines.push_back("event: hardware link back");
  }
}

std::string RuntimeEvents::fault_line(const std::string& module, const std::string& what) {
  return "event: module " + module + " failed: " + what + " (the last safe command is held)";
}

std::string RuntimeEvents::swapped_override_line(const std::string& representation,
                                                 const std::string& from, const std::string& to) {
  return "event: provider of " + representation + " swapped " +
         (from.empty() ? std::string("(none)") : from) + " -> " + to +
         ", but a held override still sets it every frame (set representation:" + representation +
         " unchanged releases it)";
}

}  // namespace stride
