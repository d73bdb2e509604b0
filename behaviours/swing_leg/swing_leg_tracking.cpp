#include "behaviours/swing_leg/swing_leg_tracking.hpp"

#include "behaviours/joint_state/joint_velocities.hpp"
#include "behaviours/swing_leg/thesis_runs.hpp"
#include "robot/model/dynamics/swing_leg_3d.hpp"
#include "robot/representations/frame_info.hpp"
#include "robot/representations/joint_request.hpp"
#include "robot/representations/joint_sensor_data.hpp"

namespace stride::swing_leg {

Leg17 thesis_ode_gamma() {
  Leg17 g;
  g << 0.002, 0.008, 0.005, 0.001, 0.002, 0.006, 0.001, 0.005, 0.007, 0.003, 0.001, 0.004, 0.005,
      0.005, 0.09, 0.015, 0.06;
  return g;
}

LegTrackingStep leg3d_tracking_step(Controller controller, const Leg5& q, const Leg5& qd,
                                    const JointReference<5>& target, const Leg17& a_hat,
                                    double lambda, double kd, const Leg17& gamma) {
  if (controller == Controller::Pd)
    return {pd_torque<5>(q, qd, target, lambda, kd), Leg17::Zero()};  // the law of Eq. 5.14
  const auto st = sliding_terms<5>(q, qd, target, lambda);
  const model::Leg3dRegressor y = model::leg3d_regressor(q, qd, st.qd_r, st.qdd_r);
  return {adaptive_torque<5, 17>(y, a_hat, st, kd),  // the law of Eq. 5.1
          adaptation_rate<5, 17>(y, st, gamma)};     // and of Eq. 5.6
}

}  // namespace stride::swing_leg

namespace stride::behaviours {
namespace {

using hal::index;

class SwingLegTracking final : public Module {
 public:
  explicit SwingLegTracking(ModuleContext& c)
      : frame_(c.require<FrameInfo>()),
        joints_(c.require<JointSensorData>()),
        velocities_(c.require<JointVelocities>()),
        params_(c.parameters<SwingLegTrackingParameters>()),
        request_(c.provide<JointRequest>()) {}

  void update() override {
    if (!started_) hold_ = joints_.position, started_ = true;
    if (!reference_ || preset_ != params_.preset) {
      preset_ = params_.preset;
      reference_ = swing_leg::walking_pattern_reference(
          std::string(EnumNames<WalkPreset>::names[static_cast<int>(preset_)]));
    }
    swing_leg::Leg5 q, qd;
    for (int i = 0; i < 5; ++i) {
      q[i] = joints_.position[index(swing_leg::kLeftLeg3d[i])];
      qd[i] = velocities_.velocity[index(swing_leg::kLeftLeg3d[i])];
    }
    reference_(frame_.time, rq_, rqd_, rqdd_);
    const swing_leg::LegTrackingStep step =
        swing_leg::leg3d_tracking_step(params_.controller, q, qd, {rq_, rqd_, rqdd_}, a_hat_,
                                       params_.lambda, params_.kd, params_.gamma);
    a_hat_ += frame_.period * step.a_hat_rate;
    for (int i = 0; i < hal::kNumJoints; ++i) {
      request_.mode[i] = hal::ServoMode::Position;
      request_.position[i] = hold_[i];
      request_.stiffness[i] = params_.hold_stiffness;
      request_.torque[i] = 0;
    }
    for (int i = 0; i < 5; ++i) {
      const int k = index(swing_leg::kLeftLeg3d[i]);
      request_.mode[k] = hal::ServoMode::Torque;
      request_.torque[k] = step.tau[i];
    }
  }

 private:
  const FrameInfo& frame_;
  const JointSensorData& joints_;
  const JointVelocities& velocities_;
  const SwingLegTrackingParameters& params_;
  JointRequest& request_;
  bool started_ = false;
  std::array<double, hal::kNumJoints> hold_{};
  WalkPreset preset_ = WalkPreset::medium;
  swing_leg::ReferenceFunction reference_;
  swing_leg::Leg17 a_hat_ = swing_leg::Leg17::Zero();  // the estimates start at zero
  // The reference's values, sized here so a control frame does not allocate.
  Eigen::VectorXd rq_ = Eigen::VectorXd::Zero(5), rqd_ = rq_, rqdd_ = rq_;
};

}  // namespace

void register_swing_leg_tracking(ModuleRegistry& registry) {
  registry.add<SwingLegTracking>("SwingLegTracking");
}

}  // namespace stride::behaviours
