#pragma once
// What every standing-balance module shares (thesis Ch. 7 on the standing NAO): the inputs, the
// standing posture held in position mode, and the CoM set point (the CoM where the robot stood
// when balancing started). A strategy adds its corrections in balance().
#include <algorithm>
#include <optional>

#include "behaviours/balance/ankle_strategy.hpp"
#include "behaviours/balance/modules/balance_actuation.hpp"
#include "behaviours/balance/modules/balance_representations.hpp"
#include "behaviours/stand/stand.hpp"
#include "robot/framework/module.hpp"
#include "robot/representations/frame_info.hpp"
#include "robot/representations/joint_request.hpp"
#include "robot/representations/joint_sensor_data.hpp"

namespace stride::behaviours {

// The base of AnkleBalance .. LqrBalance and PositionBalance.
class StandingBalance : public Module {
 protected:
  explicit StandingBalance(ModuleContext& c)
      : frame_(c.require<FrameInfo>()),
        joints_(c.require<JointSensorData>()),
        com_(c.require<ComState>()),
        model_(c.require<BalanceModel>()),
        request_(c.provide<JointRequest>()),
        posture_(stand_posture(StandParameters{})) {}

  void update() final {
    hold_posture(request_, posture_, stiffness());
    if (!com_.valid || !model_.valid) return;
    if (!x_set_) x_set_ = com_.x;
    balance();
  }

  virtual double stiffness() const = 0;
  // Adds the strategy's corrections to the posture already in request_.
  virtual void balance() = 0;

  balance::ComState relative_state() const { return {com_.x - *x_set_, com_.xdot}; }
  balance::ComState absolute_state() const { return {com_.x, com_.xdot}; }

  // The PD ZMP (Eq. 7.18), clipped to the sole (Eq. 7.19), applied through the ankles.
  void ankle_pd(double kp, double kd) {
    const balance::BalanceParams p = balance_params(model_, 0, 0);
    const double zmp = balance::pd_demanded_zmp(p, {kp, kd}, absolute_state(), *x_set_);
    command_ankle_zmp(request_, std::clamp(zmp, p.zmp_min, p.zmp_max), model_.mass_above_ankles,
                      p.g);
  }

  const FrameInfo& frame_;
  const JointSensorData& joints_;
  const ComState& com_;
  const BalanceModel& model_;
  JointRequest& request_;
  JointAngles posture_;
  std::optional<double> x_set_;
};

}  // namespace stride::behaviours
