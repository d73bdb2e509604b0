#pragma once
// A walk request as the step planner takes it, and the limits that turn a request into what the
// walk grants: speeds within the step generator's reach and changed by at most so much a step.
#include <string>

namespace stride::walking {

struct StepVelocity {
  double forward = 0.0;   // m/s along the torso's x
  double sideways = 0.0;  // m/s, left positive
  double turn = 0.0;      // rad/s, counter-clockwise positive
  bool operator==(const StepVelocity&) const = default;
};

struct StepLimits {
  double max_forward = 0.22;        // m/s
  double max_backward = 0.08;       // m/s (a positive number)
  double max_sideways = 0.06;       // m/s either way
  double max_turn = 0.6;            // rad/s either way
  double forward_per_step = 0.06;   // m/s a step may add or take away
  double sideways_per_step = 0.03;  // m/s a step
  double turn_per_step = 0.25;      // rad/s a step
};

// The request within the limits' range (non-finite values count as 0).
StepVelocity within_range(const StepVelocity& wanted, const StepLimits& limits);

// The next step's velocity: `wanted` in range, reached from `previous` by at most one step's
// change of each component.
StepVelocity next_step_velocity(const StepVelocity& previous, const StepVelocity& wanted,
                                const StepLimits& limits);

// True when one step can bring `v` to rest.
bool can_stop_within_a_step(const StepVelocity& v, const StepLimits& limits);

// First problem with the limits as one line, or empty when they are usable.
std::string limits_error(const StepLimits& limits);

}  // namespace stride::walking
