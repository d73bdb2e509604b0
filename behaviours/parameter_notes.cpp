#include "behaviours/parameter_notes.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "behaviours/balance/modules/balance_modules.hpp"
#include "behaviours/posture/posture_modules.hpp"
#include "behaviours/swing_leg/swing_leg_tracking.hpp"
#include "behaviours/walking/modules/walk_parameters.hpp"
#include "behaviours/walking/pattern/pattern_plausibility.hpp"
#include "robot/core/error.hpp"
#include "robot/nao/nao_dimensions.hpp"

namespace stride::behaviours {
namespace {

// The control period the bounds below assume: the NAO's DCM (LoLA's 12 ms is no faster).
constexpr double kPeriod = 0.01;  // s

std::string g(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

// The walk the pattern modules would run: the preset with the overrides applied. An invalid set
// is refused by the module itself when it starts, so it gets no note here.
void walk_notes(const WalkParameters& w, std::vector<std::string>& notes) {
  try {
    for (const std::string& n : walking::plausibility_notes(walk_pattern_parameters(w)))
      notes.push_back(n);
  } catch (const Error&) {
  }
}

// tau = -K_D (e' + lambda e) (Eq. 5.14). A tracking error of 0.1 rad and 1 rad/s, which a swing
// leg sees at its start, must not ask for more torque than a motor has, with the same 2x margin
// the swing-leg study flags measured torques with.
void swing_leg_notes(const SwingLegTrackingParameters& p, std::vector<std::string>& notes) {
  const double torque = p.kd * (1.0 + p.lambda * 0.1);
  if (torque <= 2 * nao::kLargestStallTorque) return;
  std::ostringstream s;
  s << "lambda = " << p.lambda << " 1/s, kd = " << p.kd << " N m s/rad: an error of 0.1 rad and "
    << "1 rad/s asks for " << g(torque) << " N m, " << std::setprecision(3)
    << torque / nao::kLargestStallTorque << " x the largest NAO joint's stall torque ("
    << nao::kLargestStallTorque << " N m; the thesis' Sec. 5.4.2 gains ask for 0.1 to 0.6 N m)";
  notes.push_back(s.str());
}

// The CoM feedback of Fig. 7.5 (kp 72 1/s^2, kd 12 1/s): gains whose closed loop is faster than
// half the control rate are sampled, not followed.
void balance_gain_notes(double kp, double kd, std::vector<std::string>& notes) {
  constexpr double kMaxKp = 0.25 / (kPeriod * kPeriod), kMaxKd = 0.5 / kPeriod;
  if (kp > kMaxKp)
    notes.push_back("kp = " + g(kp) + " 1/s^2: a closed-loop frequency of " + g(std::sqrt(kp)) +
                    " rad/s, faster than a 10 ms control loop follows (plausible up to " +
                    g(kMaxKp) + "; Fig. 7.5 uses 72)");
  if (kd > kMaxKd)
    notes.push_back("kd = " + g(kd) + " 1/s: faster than a 10 ms control loop follows " +
                    "(plausible up to " + g(kMaxKd) + "; Fig. 7.5 uses 12)");
}

// The posture laws (Eq. 4.10, Eq. 4.11, Eq. 4.14, Eq. 4.15) add kp x the torso's tilt (and kd x
// its rate) to the leg joints: the thesis tuned 0.28-0.40 and -0.05 to -0.06 s; more than twice the
// tilt overturns the correction.
void posture_gain_notes(const PostureGains& k, std::vector<std::string>& notes) {
  const std::pair<const char*, double> kp[] = {{"kp_pitch", k.kp_pitch}, {"kp_roll", k.kp_roll}};
  const std::pair<const char*, double> kd[] = {{"kd_pitch", k.kd_pitch}, {"kd_roll", k.kd_roll}};
  for (const auto& [name, v] : kp)
    if (std::abs(v) > 2)
      notes.push_back(std::string(name) + " = " + g(v) + ": corrects by more than twice the " +
                      "measured tilt (plausible |kp| up to 2; the thesis tuned 0.28 to 0.40)");
  for (const auto& [name, v] : kd)
    if (std::abs(v) > 0.3)
      notes.push_back(std::string(name) + " = " + g(v) + " s: plausible |kd| up to 0.3 s (the " +
                      "thesis tuned -0.05 to -0.06 s)");
}

}  // namespace

std::vector<std::string> parameter_notes(const std::string& module, const Slot& parameters) {
  std::vector<std::string> notes;
  const std::type_index t = parameters.type();
  if (t == typeid(WalkParameters)) {
    walk_notes(slot_value<WalkParameters>(parameters), notes);
  } else if (t == typeid(SwingLegTrackingParameters)) {
    swing_leg_notes(slot_value<SwingLegTrackingParameters>(parameters), notes);
  } else if (t == typeid(AnkleBalanceParameters)) {
    const auto& p = slot_value<AnkleBalanceParameters>(parameters);
    balance_gain_notes(p.kp, p.kd, notes);
  } else if (t == typeid(CombinedBalanceParameters)) {
    const auto& p = slot_value<CombinedBalanceParameters>(parameters);
    balance_gain_notes(p.kp, p.kd, notes);
  } else if (t == typeid(HipStrategyParameters)) {
    posture_gain_notes(slot_value<HipStrategyParameters>(parameters).gains(), notes);
  } else if (t == typeid(AnkleStrategyParameters)) {
    posture_gain_notes(slot_value<AnkleStrategyParameters>(parameters).gains(), notes);
  }
  for (std::string& n : notes) n = module + ": " + n;
  return notes;
}

}  // namespace stride::behaviours
