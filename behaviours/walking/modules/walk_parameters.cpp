#include "behaviours/walking/modules/walk_parameters.hpp"

#include <cmath>
#include <string>

#include "robot/core/error.hpp"

namespace stride::behaviours {
namespace {

void override_with(double& target, double value) {
  if (!std::isnan(value)) target = value;
}

}  // namespace

walking::PatternParameters walk_pattern_parameters(const WalkParameters& w) {
  walking::PatternParameters p =
      walking::preset(std::string(EnumNames<WalkPreset>::names[static_cast<int>(w.preset)]));
  override_with(p.T_stride, w.T_stride);
  override_with(p.tau_dsp, w.tau_dsp);
  override_with(p.A_l, w.A_l);
  override_with(p.z_min, w.z_min);
  override_with(p.z_max, w.z_max);
  override_with(p.d_0, w.d_0);
  override_with(p.H_foot, w.H_foot);
  override_with(p.z_conventional, w.z_conventional);
  const int development = w.development_steps > 0 ? w.development_steps : p.development_steps();
  const int decay = w.decay_steps > 0 ? w.decay_steps : p.decay_steps();
  override_with(p.rhythmic.V_min, w.V_min);
  override_with(p.rhythmic.V_max, w.V_max);
  // The intermediate levels ramp to the (possibly new) rhythmic speed (Fig. 3.7).
  p.development = walking::linear_levels(p.rhythmic, development);
  p.decay = walking::linear_levels(p.rhythmic, decay);
  if (w.steps > 0) p.steps = w.steps;
  if (auto e = walking::validation_error(p)) throw Error("WalkParameters: " + *e);
  return p;
}

bool same_walk_parameters(const WalkParameters& a, const WalkParameters& b) {
  bool same = true;
  for_each_field<WalkParameters>([&](const auto& f) {
    const auto& x = a.*(f.member);
    const auto& y = b.*(f.member);
    if constexpr (std::is_floating_point_v<std::decay_t<decltype(x)>>)
      same = same && (x == y || (std::isnan(x) && std::isnan(y)));
    else
      same = same && x == y;
  });
  return same;
}

}  // namespace stride::behaviours
