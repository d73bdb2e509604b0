#include "behaviours/balance/lqr_balance.hpp"

#include <cmath>

#include "robot/core/error.hpp"

namespace stride::balance {

LqrBalanceModel lqr_balance_model(const BalanceParams& p) {
  const double w2 = p.omega() * p.omega();
  LqrBalanceModel m;
  m.A << 0, 0, 1, 0,                //
      0, 0, 0, 1,                   //
      w2, 0, 0, 0,                  //
      0, 0, 0, 0;                   // Eq. 7.38
  m.B << 0, 0,                      //
      0, 0,                         //
      -w2, -1 / (p.mass * p.z_cm),  // Eq. 7.33
      0, 1 / p.inertia;             // tau_h = I thetaddot
  return m;
}

Eigen::Matrix4d thesis_lqr_q() {
  return Eigen::Vector4d(2000, 500, 1, 10).asDiagonal();
}
Eigen::Matrix2d thesis_lqr_r() {
  return Eigen::Vector2d(4500000, 100).asDiagonal();
}

std::vector<LqrSample> simulate_lqr(const LqrBalanceModel& model, const Eigen::MatrixXd& K,
                                    const Eigen::Vector4d& x0, double duration, double dt) {
  if (K.rows() != 2 || K.cols() != 4) throw Error("LQR simulation: K must be 2 x 4");
  if (!(dt > 0) || !(duration > 0)) throw Error("LQR simulation: dt and duration must be > 0");
  const Eigen::Matrix4d Ac = model.A - model.B * K;
  auto f = [&](const Eigen::Vector4d& x) -> Eigen::Vector4d { return Ac * x; };
  std::vector<LqrSample> out;
  Eigen::Vector4d x = x0;
  const auto steps = static_cast<long>(std::ceil(duration / dt));
  for (long i = 0; i <= steps; ++i) {
    out.push_back({i * dt, x, -K * x});
    const Eigen::Vector4d k1 = f(x), k2 = f(x + dt / 2 * k1), k3 = f(x + dt / 2 * k2),
                          k4 = f(x + dt * k3);
    x += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return out;
}

}  // namespace stride::balance
