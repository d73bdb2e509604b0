#pragma once
// SwingLegTracking: Sec. 5.4.2 as a module. The left leg in torque mode follows the Ch. 3
// pattern's joint angles under the adaptive law (Eq. 5.1, Eq. 5.6) or the PD law it is compared
// with (Eq. 5.14); every other joint holds the angle it had at the first frame.
//   FrameInfo, JointSensorData, JointVelocities -> JointRequest
// Choose it with `mr JointRequest SwingLegTracking` (scenes/swing_leg/hanging_nao.xml does);
// a sweep varies SwingLegTracking.lambda, .kd, .gamma, .controller, .preset.
#include <array>

#include <Eigen/Core>

#include "behaviours/swing_leg/adaptive_control.hpp"
#include "behaviours/swing_leg/tracking_simulation.hpp"
#include "behaviours/walking/modules/walk_parameters.hpp"
#include "robot/framework/module_registry.hpp"
#include "robot/framework/reflect.hpp"
#include "robot/hal/joint_id.hpp"

namespace stride::swing_leg {

using Leg5 = JointVector<5>;
using Leg17 = Eigen::Matrix<double, 17, 1>;

// The 3-D model's joints [hip roll, hip pitch, knee, ankle pitch, ankle roll] on the left leg
// (App. C's order; LHipYawPitch is shared with the right leg and stays in position mode).
inline constexpr std::array<hal::JointId, 5> kLeftLeg3d = {
    hal::JointId::LHipRoll, hal::JointId::LHipPitch, hal::JointId::LKneePitch,
    hal::JointId::LAnklePitch, hal::JointId::LAnkleRoll};

// The adaptation weights the thesis used in its ODE simulator (Sec. 5.4.2).
Leg17 thesis_ode_gamma();

// One control step of the 3-D leg: the torques and the estimates' rate a^' (zero for PD).
struct LegTrackingStep {
  Leg5 tau;
  Leg17 a_hat_rate;
};
LegTrackingStep leg3d_tracking_step(Controller controller, const Leg5& q, const Leg5& qd,
                                    const JointReference<5>& target, const Leg17& a_hat,
                                    double lambda, double kd, const Leg17& gamma);

}  // namespace stride::swing_leg

namespace stride::behaviours {

struct SwingLegTrackingParameters {
  STRIDE_FIELDS(SwingLegTrackingParameters);
  STRIDE_FIELD(swing_leg::Controller, controller) = swing_leg::Controller::Adaptive;
  // Lambda = lambda I, 1/s
  STRIDE_FIELD(double, lambda, "1/s", Range{1e-3, 1e4}) = 20;
  // K_D = kd I, N m s/rad
  STRIDE_FIELD(double, kd, "N*m*s/rad", Range{1e-6, 1e3}) = 0.1;
  // diagonal of Gamma
  STRIDE_FIELD(swing_leg::Leg17, gamma, "", Range{0, 1e6}) = swing_leg::thesis_ode_gamma();
  // the pattern the leg follows
  STRIDE_FIELD(WalkPreset, preset) = WalkPreset::medium;
  // the joints that keep their angle
  STRIDE_FIELD(double, hold_stiffness, "", Range{0, 1}) = 1;

  static constexpr std::string_view kTypeName = "SwingLegTrackingParameters";
};

void register_swing_leg_tracking(ModuleRegistry& registry);

}  // namespace stride::behaviours
