#include "behaviours/balance/modules/balance_modules.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "behaviours/balance/ankle_strategy.hpp"
#include "behaviours/balance/combined_strategy.hpp"
#include "behaviours/balance/hip_strategy.hpp"
#include "behaviours/balance/lqr_balance.hpp"
#include "behaviours/balance/modules/balance_actuation.hpp"
#include "behaviours/balance/modules/balance_outlook.hpp"
#include "behaviours/balance/modules/balance_representations.hpp"
#include "behaviours/balance/modules/com_state_estimator.hpp"
#include "behaviours/balance/modules/hat_excursion.hpp"
#include "behaviours/balance/modules/position_balance.hpp"
#include "behaviours/balance/modules/standing_balance.hpp"
#include "behaviours/stand/stand.hpp"
#include "robot/representations/frame_info.hpp"

namespace stride::behaviours {

namespace {

class AnkleBalance final : public StandingBalance {
 public:
  explicit AnkleBalance(ModuleContext& c)
      : StandingBalance(c), params_(c.parameters<AnkleBalanceParameters>()) {}

 private:
  double stiffness() const override { return params_.stiffness; }
  void balance() override { ankle_pd(params_.kp, params_.kd); }

  const AnkleBalanceParameters& params_;
};

class HipBalance final : public StandingBalance {
 public:
  explicit HipBalance(ModuleContext& c)
      : StandingBalance(c), params_(c.parameters<HipBalanceParameters>()) {}

 private:
  double stiffness() const override { return params_.stiffness; }
  void balance() override {
    const balance::BalanceParams p =
        balance_params(model_, params_.tau_forward, params_.tau_backward);
    if (!excursion_) {
      const balance::ComState s = relative_state();  // ZMP under the standing CoM (Alg. 2)
      if (std::abs(balance::capture_point(s, p.omega())) < params_.trigger) return;
      excursion_ = HatExcursion{p, s, balance::plan_hip(p, s), frame_.time};
    }
    const auto theta = excursion_->theta(frame_.time, params_.hold_time, params_.return_time);
    if (!theta) {
      excursion_.reset();
      return;
    }
    const double hat = clamp_theta(model_, *theta);
    command_hat_angle(request_, posture_, hat);
    if (params_.keep_com) command_body_tilt(request_, posture_, com_keeping_tilt(model_, hat));
  }

  const HipBalanceParameters& params_;
  std::optional<HatExcursion> excursion_;
};

class CombinedBalance final : public StandingBalance {
 public:
  explicit CombinedBalance(ModuleContext& c)
      : StandingBalance(c), params_(c.parameters<CombinedBalanceParameters>()) {}

 private:
  double stiffness() const override { return params_.stiffness; }
  void balance() override {
    ankle_pd(params_.kp, params_.kd);
    balance::BalanceParams p = balance_params(model_, params_.tau_forward, params_.tau_backward);
    p.zmp_min += params_.margin;  // the ZMP the ankle can really hold: the sole less a margin
    p.zmp_max -= params_.margin;
    if (!excursion_) {
      const balance::ComState s = absolute_state();
      const double xi = balance::capture_point(s, p.omega());
      if (xi > p.zmp_min && xi < p.zmp_max) return;
      // The ankle holds the border, the hip covers the rest of the capture point (Eq. 7.36).
      excursion_ = HatExcursion{p, s, balance::plan_combined(p, s), frame_.time};
    }
    const auto theta = excursion_->theta(frame_.time, params_.hold_time, params_.return_time);
    if (!theta) {
      excursion_.reset();
      return;
    }
    command_hat_angle(request_, posture_, clamp_theta(model_, *theta));
  }

  const CombinedBalanceParameters& params_;
  std::optional<HatExcursion> excursion_;
};

class LqrBalance final : public StandingBalance {
 public:
  explicit LqrBalance(ModuleContext& c)
      : StandingBalance(c), params_(c.parameters<LqrBalanceParameters>()) {}

 private:
  double stiffness() const override { return params_.stiffness; }
  void balance() override {
    const balance::BalanceParams p = balance_params(model_, params_.tau_max, -params_.tau_max);
    if (!gain_ || q_ != params_.q_diagonal || r_ != params_.r_diagonal) {
      q_ = params_.q_diagonal;
      r_ = params_.r_diagonal;
      const auto m = balance::lqr_balance_model(p);
      gain_ = balance::lqr(m.A, m.B, Eigen::Matrix4d(q_.asDiagonal()),
                           Eigen::Matrix2d(r_.asDiagonal()))
                  .K;  // Eq. 7.39
    }
    // theta, thetadot are the commanded HAT state: the hip position servos track it.
    const Eigen::Vector4d s(com_.x - *x_set_, theta_, com_.xdot, theta_dot_);
    const Eigen::Vector2d u = -*gain_ * s;
    const double zmp = std::clamp(*x_set_ + u(0), p.zmp_min, p.zmp_max);
    const double tau = std::clamp(u(1), -params_.tau_max, params_.tau_max);
    command_ankle_zmp(request_, zmp, model_.mass_above_ankles, p.g);
    // tau_h = I thetaddot, integrated to the HAT angle the hips are sent to.
    theta_dot_ += tau / p.inertia * frame_.period;
    theta_ += theta_dot_ * frame_.period;
    const double limited = clamp_theta(model_, theta_);
    if (limited != theta_) theta_dot_ = 0;
    theta_ = limited;
    command_hat_angle(request_, posture_, theta_);
  }

  const LqrBalanceParameters& params_;
  std::optional<Eigen::Matrix<double, 2, 4>> gain_;
  Eigen::Vector4d q_ = Eigen::Vector4d::Zero();
  Eigen::Vector2d r_ = Eigen::Vector2d::Zero();
  double theta_ = 0, theta_dot_ = 0;
};

}  // namespace

void register_balance_modules(ModuleRegistry& registry) {
  register_com_state_estimator(registry);
  register_position_balance(registry);
  register_balance_outlook(registry);
  registry.add<AnkleBalance>("AnkleBalance");
  registry.add<HipBalance>("HipBalance");
  registry.add<CombinedBalance>("CombinedBalance");
  registry.add<LqrBalance>("LqrBalance");
}

}  // namespace stride::behaviours
