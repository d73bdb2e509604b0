#pragma once
// How much one scene may hold (docs/scenes.md "Limits"): beyond these a scene is refused with a message
// naming the limit instead of exhausting memory or time.
#include <cstddef>

namespace stride::sim::scene_limits {

inline constexpr int kMaxRobots = 64;
inline constexpr int kMaxBodies = 10000;            // links over all robots
inline constexpr int kMaxRobotGeoms = 20000;        // collision shapes over all robots
inline constexpr long kMaxStaticGeoms = 500000;     // boxes, ramps and uneven-floor tiles
inline constexpr std::size_t kMaxContacts = 20000;  // contact points found in one step

}  // namespace stride::sim::scene_limits
