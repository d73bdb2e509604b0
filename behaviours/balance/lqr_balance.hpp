#pragma once
// LQR balance control of the combined ankle + hip model (thesis Sec. 7.5.2, Eq. 7.38, Eq. 7.39).
#include <Eigen/Dense>
#include <vector>

#include "behaviours/balance/balance_params.hpp"
#include "behaviours/balance/care_solver.hpp"

namespace stride::balance {

// State [x_cm, theta, xdot_cm, thetadot], input [x_zmp, tau_h] (Eq. 7.38 with Eq. 7.33).
struct LqrBalanceModel {
  Eigen::Matrix4d A;
  Eigen::Matrix<double, 4, 2> B;
};
LqrBalanceModel lqr_balance_model(const BalanceParams& p);

// The weights printed with Figs. 7.13-7.14.
Eigen::Matrix4d thesis_lqr_q();
Eigen::Matrix2d thesis_lqr_r();

struct LqrSample {
  double t = 0.0;
  Eigen::Vector4d state = Eigen::Vector4d::Zero();
  Eigen::Vector2d input = Eigen::Vector2d::Zero();  // u = -K x: [x_zmp, tau_h]
};

// RK4 of xdot = (A - B K) x from x0, sampled every dt.
std::vector<LqrSample> simulate_lqr(const LqrBalanceModel& model, const Eigen::MatrixXd& K,
                                    const Eigen::Vector4d& x0, double duration, double dt);

}  // namespace stride::balance
