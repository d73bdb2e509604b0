#pragma once
// The walking pattern a controller plays, replayed beside it: which walk module provides the
// WalkingJointRequest (PatternWalk, PushRecoveryWalk or ConventionalWalk) with its parameters,
// and the pattern's time, planned waist velocity and ZMP reference at any frame time, as the
// module computes them. Observers of a walk (the Ch. 4 traces, sweeps' `walk.*` keys) read the
// plan here instead of naming the modules and rebuilding their pattern themselves.
#include <optional>
#include <string>
#include <variant>

#include <Eigen/Core>

#include "behaviours/walking/modules/walk_parameters.hpp"
#include "behaviours/walking/pattern/walking_pattern.hpp"
#include "robot/runtime/runtime.hpp"

namespace stride::behaviours {

struct WalkPatternInfo {
  std::string module;      // PatternWalk, PushRecoveryWalk or ConventionalWalk
  double start_delay = 0;  // s after the first control frame
  double duration = 0;     // s
  WalkParameters parameters;
};

// nullopt when the runtime's WalkingJointRequest comes from no pattern walk.
std::optional<WalkPatternInfo> walk_pattern_info(const Runtime& runtime);

// What the pattern plans at one frame.
struct PlannedWalkSample {
  double pattern_t = 0;         // s since the pattern started (negative while standing)
  double waist_velocity_x = 0;  // m/s forward, 0 before the start
  Eigen::Vector2d zmp{0, 0};    // the pattern's ZMP in its walk frame (Eq. 3.16)
};

class WalkPatternReplay {
 public:
  explicit WalkPatternReplay(const WalkPatternInfo& info);
  // `first_frame_time`: the time of the controller's first frame (its pattern clock's zero).
  PlannedWalkSample at(double frame_time, double first_frame_time) const;

 private:
  std::variant<walking::StretchedKneePattern, walking::ConventionalPattern> pattern_;
  double start_delay_ = 0;
};

}  // namespace stride::behaviours
