#include "behaviours/walking/steps/step_velocity.hpp"

#include <algorithm>
#include <cmath>

#include "robot/core/number_text.hpp"

namespace stride::walking {

namespace {

double finite_or_zero(double v) {
  return std::isfinite(v) ? v : 0.0;
}

double toward(double from, double to, double max_change) {
  return from + std::clamp(to - from, -max_change, max_change);
}

}  // namespace

StepVelocity within_range(const StepVelocity& w, const StepLimits& l) {
  return {std::clamp(finite_or_zero(w.forward), -l.max_backward, l.max_forward),
          std::clamp(finite_or_zero(w.sideways), -l.max_sideways, l.max_sideways),
          std::clamp(finite_or_zero(w.turn), -l.max_turn, l.max_turn)};
}

StepVelocity next_step_velocity(const StepVelocity& previous, const StepVelocity& wanted,
                                const StepLimits& l) {
  const StepVelocity target = within_range(wanted, l);
  return {toward(previous.forward, target.forward, l.forward_per_step),
          toward(previous.sideways, target.sideways, l.sideways_per_step),
          toward(previous.turn, target.turn, l.turn_per_step)};
}

bool can_stop_within_a_step(const StepVelocity& v, const StepLimits& l) {
  return std::abs(v.forward) <= l.forward_per_step && std::abs(v.sideways) <= l.sideways_per_step &&
         std::abs(v.turn) <= l.turn_per_step;
}

std::string limits_error(const StepLimits& l) {
  const struct {
    const char* name;
    double value;
  } all[] = {{"max_forward", l.max_forward},           {"max_backward", l.max_backward},
             {"max_sideways", l.max_sideways},         {"max_turn", l.max_turn},
             {"forward_per_step", l.forward_per_step}, {"sideways_per_step", l.sideways_per_step},
             {"turn_per_step", l.turn_per_step}};
  for (const auto& f : all)
    if (!std::isfinite(f.value) || f.value < 0.0)
      return std::string(f.name) + " must be a finite value >= 0 (got " + short_number(f.value) +
             ")";
  for (const auto& f : {all[4], all[5], all[6]})
    if (!(f.value > 0.0)) return std::string(f.name) + " must be > 0 (a walk could never stop)";
  return "";
}

}  // namespace stride::walking
