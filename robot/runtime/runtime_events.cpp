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

void RuntimeEvents::note(Kind kind, double time, double a, double b) {
  if (count_ < noted_.size())
    noted_[count_++] = {kind, time, a, b};
  else
    ++dropped_;
}

void RuntimeEvents::after_frame(double time, double tilt, double fall_tilt,
                                const CommandSafety& safety) {
  // Standing up again (well inside the threshold for 2 s: not a bounce) re-arms the fall line.
  if (!fallen_ && tilt > fall_tilt) {
    fallen_ = true;
    upright_since_ = -1;
    note(Kind::Fell, time, tilt, fall_tilt);
  } else if (fallen_) {
    if (tilt < 0 || tilt >= 0.5 * fall_tilt)
      upright_since_ = -1;
    else if (upright_since_ < 0)
      upright_since_ = time;
    else if (time - upright_since_ >= 2.0)
      fallen_ = false;
  }
  // Limits and NaN holds: a line when they start after a quiet second, not every frame.
  if (safety.clamped_positions > clamped_) {
    if (time - last_clamp_ > 1.0)
      note(Kind::Limited, time, static_cast<double>(safety.clamped_positions - clamped_));
    last_clamp_ = time;
  }
  if (safety.nonfinite_held > nonfinite_) {
    if (time - last_nonfinite_ > 1.0)
      note(Kind::Nonfinite, time, static_cast<double>(safety.nonfinite_held - nonfinite_));
    last_nonfinite_ = time;
  }
  clamped_ = safety.clamped_positions;
  nonfinite_ = safety.nonfinite_held;
}

void RuntimeEvents::link_lost(bool lost, double now) {
  // A late packet is a stall the link rides out; no frame for kLostAfter seconds is a lost link.
  if (!lost) lost_since_ = -1;
  if (lost && lost_since_ < 0) lost_since_ = now;
  if (lost && !link_lost_ && now - lost_since_ >= kLostAfter) {
    link_lost_ = true;
    note(Kind::LinkLost, now, now - lost_since_);
  } else if (!lost && link_lost_) {
    link_lost_ = false;
    note(Kind::LinkBack, now);
  }
}

void RuntimeEvents::take(std::vector<std::string>& lines) {
  for (std::size_t i = 0; i < count_; ++i) {
    const Noted& e = noted_[i];
    const std::string t = fixed(e.time, 2);
    switch (e.kind) {
      case Kind::Fell:
        lines.push_back("event: FELL at t=" + t + " s (IMU tilt " + fixed(e.a, 2) +
                        " rad past fall_tilt " + fixed(e.b, 2) + ")");
        break;
      case Kind::Limited:
        lines.push_back(
            "event: joint request limited at t=" + t + " s: " + fixed(e.a, 0) +
            " position(s) clamped onto joint limits (get representation:CommandSafety)");
        break;
      case Kind::Nonfinite:
        lines.push_back("event: NaN/inf joint command at t=" + t + " s: " + fixed(e.a, 0) +
                        " joint(s) held at their last valid position");
        break;
      case Kind::LinkLost:
        lines.push_back("event: hardware link lost: no sensor frame for " + fixed(e.a, 2) +
                        " s (holding the last command)");
        break;
      case Kind::LinkBack:
        lines.push_back("event: hardware link back");
        break;
    }
  }
  if (dropped_ > 0) lines.push_back("(" + std::to_string(dropped_) + " events dropped)");
  count_ = dropped_ = 0;
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
