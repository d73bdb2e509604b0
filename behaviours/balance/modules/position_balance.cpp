#include "behaviours/balance/modules/position_balance.hpp"

#include <cmath>
#include <optional>

#include "behaviours/balance/combined_strategy.hpp"
#include "behaviours/balance/modules/hat_excursion.hpp"
#include "behaviours/balance/modules/standing_balance.hpp"
#include "behaviours/balance/strategy_classifier.hpp"
#include "behaviours/landing/admittance.hpp"

namespace stride::behaviours {

balance::Strategy chosen_strategy(BalanceChoice choice, balance::Strategy predicted) {
  switch (choice) {
    case BalanceChoice::ankle:
      return balance::Strategy::ankle;
    case BalanceChoice::hip:
      return balance::Strategy::hip;
    case BalanceChoice::combined:
      return balance::Strategy::combined;
    case BalanceChoice::automatic:
      break;
  }
  return predicted == balance::Strategy::none ? balance::Strategy::combined : predicted;
}

namespace {

using hal::index;
using hal::JointId;

class PositionBalance final : public StandingBalance {
 public:
  explicit PositionBalance(ModuleContext& c)
      : StandingBalance(c),
        params_(c.parameters<PositionBalanceParameters>()),
        state_(c.provide<PositionBalanceState>()) {}

 private:
  double stiffness() const override { return params_.stiffness; }

  void balance() override {
    balance::BalanceParams p = balance_params(model_, params_.tau_forward, params_.tau_backward);
    p.zmp_min += params_.margin;  // the ZMP the ankle can really hold: the sole less a margin
    p.zmp_max -= params_.margin;
    if (!excursion_) choose(p);
    double theta = 0;
    if (excursion_) {
      const auto t = excursion_->theta(frame_.time, params_.hold_time, params_.return_time);
      if (t)
        theta = clamp_theta(model_, *t);
      else
        excursion_.reset();
    }
    if (!excursion_) state_.strategy = balance::Strategy::ankle;
    const bool pure_hip = excursion_ && state_.strategy == balance::Strategy::hip;
    // The pure hip strategy of Sec. 7.4 leaves the ankles to hold the posture.
    const double ankle = pure_hip ? 0.0 : ankle_offset(p);
    for (JointId j : {JointId::LAnklePitch, JointId::RAnklePitch})
      request_.position[index(j)] = posture_[index(j)] + ankle;
    if (theta != 0) {
      command_hat_angle(request_, posture_, theta);
      if (pure_hip && params_.keep_com)
        command_body_tilt(request_, posture_, com_keeping_tilt(model_, theta));
    }
    state_.hat_angle = theta;
    state_.ankle_offset = ankle;
  }

  // A new disturbance: the strategy the parameters or the Ch. 7 boundaries name, with its plan.
  void choose(const balance::BalanceParams& p) {
    const balance::ComState s = absolute_state();
    const balance::Classification c = balance::classify(p, s);
    state_.capture_point = c.capture_point;
    state_.predicted = c.strategy;
    const balance::Strategy chosen = chosen_strategy(params_.strategy, c.strategy);
    if (chosen == balance::Strategy::hip) {
      const balance::ComState r = relative_state();  // ZMP under the standing CoM (Alg. 2)
      if (std::abs(balance::capture_point(r, p.omega())) < params_.trigger) return;
      excursion_ = HatExcursion{p, r, balance::plan_hip(p, r), frame_.time};
    } else if (chosen == balance::Strategy::combined) {
      const double xi = c.capture_point;
      if (xi > p.zmp_min && xi < p.zmp_max) return;  // the ankle alone suffices (Eq. 7.36)
      excursion_ = HatExcursion{p, s, balance::plan_combined(p, s), frame_.time};
    }
    if (excursion_) state_.strategy = chosen;
  }

  // The PD law (Eq. 7.16) demands a ZMP (Eq. 7.18, clipped by Eq. 7.19); Eq. 7.10 turns its
  // distance from the FSR CoP into an ankle torque error, which the admittance turns into the ankle
  // pitch offset (toes down > 0 moves the CoP forward).
  double ankle_offset(const balance::BalanceParams& p) {
    const double demanded =
        balance::pd_demanded_zmp(p, {params_.kp, params_.kd}, absolute_state(), *x_set_);
    const double zmp = std::clamp(demanded, p.zmp_min, p.zmp_max);
    const double torque_error =
        cop_torque_error(model_.mass_above_ankles, p.g, zmp, com_.measured_cop.x());
    const Admittance a{0, params_.ankle_damping, params_.ankle_stiffness};
    if (!(filter_.model().damping == a.damping && filter_.model().stiffness == a.stiffness &&
          filter_.model().mass == 0 && filter_.period() == frame_.period))
      filter_ = AdmittanceFilter(a, frame_.period);
    ankle_ = filter_.step(ankle_, torque_error);
    ankle_.offset = std::clamp(ankle_.offset, -params_.max_ankle_offset, params_.max_ankle_offset);
    state_.demanded_zmp = zmp;
    return ankle_.offset;
  }

  const PositionBalanceParameters& params_;
  PositionBalanceState& state_;
  std::optional<HatExcursion> excursion_;
  AdmittanceFilter filter_;
  AdmittanceState ankle_;
};

}  // namespace

void register_position_balance(ModuleRegistry& registry) {
  registry.add<PositionBalance>("PositionBalance");
}

}  // namespace stride::behaviours
