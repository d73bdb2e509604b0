#include "behaviours/balance/com_kalman_filter.hpp"

#include <cmath>
#include <string>

#include "robot/core/error.hpp"

namespace stride::balance {

ComFilterModel com_filter_model(double z0, double g, double T, double sigma_position,
                                double sigma_velocity, double sigma_zmp) {
  if (!(z0 > 0) || !(g > 0) || !(T > 0)) throw Error("CoM filter: z0, g and T must be positive");
  const double w2T = g / z0 * T;  // omega^2 T
  ComFilterModel m;
  m.A.setZero();
  for (int axis = 0; axis < 2; ++axis) {  // Eq. 7.3: two identical decoupled blocks
    const int o = 3 * axis;
    m.A(o, o) = 1;
    m.A(o, o + 1) = T;
    m.A(o + 1, o) = w2T;
    m.A(o + 1, o + 1) = 1;
    m.A(o + 1, o + 2) = -w2T;
    m.A(o + 2, o + 2) = 1;
  }
  m.B.setZero();
  m.B(2, 0) = T;  // Eq. 7.4
  m.B(5, 1) = T;
  const Eigen::Vector3d s(sigma_position, sigma_velocity, sigma_zmp);
  m.Q.setZero();
  for (int i = 0; i < 6; ++i) m.Q(i, i) = s(i % 3) * s(i % 3);
  return m;
}

Eigen::Matrix<double, 4, 6> com_cop_measurement() {
  Eigen::Matrix<double, 4, 6> C = Eigen::Matrix<double, 4, 6>::Zero();
  C(0, 0) = 1;
  C(1, 2) = 1;
  C(2, 3) = 1;
  C(3, 5) = 1;
  return C;
}

Eigen::Matrix<double, 6, 6> com_cop_force_measurement(double mass, double omega) {
  const double mw2 = mass * omega * omega;
  Eigen::Matrix<double, 6, 6> C = Eigen::Matrix<double, 6, 6>::Zero();
  for (int axis = 0; axis < 2; ++axis) {
    const int o = 3 * axis;
    C(o, o) = 1;
    C(o + 1, o + 2) = 1;
    C(o + 2, o) = mw2;
    C(o + 2, o + 2) = -mw2;
  }
  return C;
}

ComEstimate predict(const ComFilterModel& model, const ComEstimate& e, const Eigen::Vector2d& u) {
  ComEstimate r;
  r.x = model.A * e.x + model.B * u;  // Eq. 7.2
  r.P = model.A * e.P * model.A.transpose() + model.Q;
  return r;
}

ComEstimate update(const ComEstimate& e, const Eigen::Ref<const Eigen::VectorXd>& y,
                   const Eigen::Ref<const Eigen::MatrixXd>& C,
                   const Eigen::Ref<const Eigen::MatrixXd>& R) {
  if (C.cols() != 6 || C.rows() != y.size() || R.rows() != y.size() || R.cols() != y.size())
    throw Error("CoM filter update: need C (k x 6), y (k) and R (k x k) of matching size k");
  if (y.size() > kMaxMeasurements)
    throw Error("CoM filter update: at most " + std::to_string(kMaxMeasurements) +
                " measurements, got " + std::to_string(y.size()));
  // Dynamic sizes held inside the matrices (at most 6), as the heap-sized ones computed them, so
  // an update in a control frame does not allocate.
  constexpr int kMax = kMaxMeasurements;
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMax, 6>;
  using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMax, 1>;
  const Matrix Cm = C, Rm = R;
  const Vector ym = y;
  const Matrix S = Cm * e.P * Cm.transpose() + Rm;
  const Matrix K = S.ldlt().solve(Cm * e.P).transpose();  // P C^T S^-1 (S symmetric)
  ComEstimate r;
  r.x = e.x + K * (ym - Cm * e.x);
  // Joseph form keeps P symmetric positive semi-definite under rounding.
  const ComFilterCovariance IKC = ComFilterCovariance::Identity() - K * Cm;
  r.P = IKC * e.P * IKC.transpose() + K * Rm * K.transpose();
  return r;
}

}  // namespace stride::balance
