#include "behaviours/walking/modules/walk_pattern_replay.hpp"

#include <algorithm>
#include <vector>

#include "behaviours/walking/modules/pattern_walk.hpp"
#include "robot/framework/text.hpp"

namespace stride::behaviours {
namespace {

bool on_blackboard(const Runtime& rt, const std::string& name) {
  const auto names = rt.representation_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::variant<walking::StretchedKneePattern, walking::ConventionalPattern> pattern_of(
    const WalkPatternInfo& info) {
  const walking::PatternParameters p = walk_pattern_parameters(info.parameters);
  if (info.module != "ConventionalWalk") return walking::StretchedKneePattern(p);
  return walking::ConventionalPattern(p);
}

}  // namespace

std::optional<WalkPatternInfo> walk_pattern_info(const Runtime& rt) {
  if (!on_blackboard(rt, "WalkingJointRequest")) return std::nullopt;
  WalkPatternInfo info;
  info.module = rt.provider_of("WalkingJointRequest");
  // PushRecoveryWalk plays PatternWalk's pattern (moved by its recovery steps) from `walk.*`.
  const bool recovery = info.module == "PushRecoveryWalk";
  if (info.module != "PatternWalk" && info.module != "ConventionalWalk" && !recovery)
    return std::nullopt;
  update_from_text(info.parameters, rt.get("module:" + info.module + (recovery ? ".walk" : "")));
  const walking::PatternParameters p = walk_pattern_parameters(info.parameters);
  info.duration = info.module != "ConventionalWalk" ? walking::StretchedKneePattern(p).duration()
                                                    : walking::ConventionalPattern(p).duration();
  info.start_delay = info.parameters.start_delay;
  return info;
}

WalkPatternReplay::WalkPatternReplay(const WalkPatternInfo& info)
    : pattern_(pattern_of(info)), start_delay_(info.start_delay) {}

PlannedWalkSample WalkPatternReplay::at(double frame_time, double first_frame_time) const {
  const double t = pattern_time(frame_time, first_frame_time, start_delay_);
  const walking::PatternSample plan =
      std::visit([&](const auto& p) { return p.sample(std::max(t, 0.0)); }, pattern_);
  PlannedWalkSample s;
  s.pattern_t = t;
  s.waist_velocity_x = t >= 0 ? plan.waist_velocity.x() : 0;
  s.zmp = plan.zmp;
  return s;
}

}  // namespace stride::behaviours
