#pragma once
// CoM state estimation with the 3D-LIPM Kalman filter (thesis Sec. 7.2).
#include <Eigen/Dense>

namespace stride::balance {

// State [x, xdot, x_zmp, y, ydot, y_zmp], input [xdot_zmp, ydot_zmp].
using ComFilterState = Eigen::Matrix<double, 6, 1>;
using ComFilterCovariance = Eigen::Matrix<double, 6, 6>;

struct ComFilterModel {
  Eigen::Matrix<double, 6, 6> A;  // of Eq. 7.3
  Eigen::Matrix<double, 6, 2> B;  // of Eq. 7.4
  Eigen::Matrix<double, 6, 6> Q;  // process noise covariance
};

// A and B (Eq. 7.3, Eq. 7.4) for CoM height z0, gravity g and time step T; Q = diag of the given
// std-devs^2.
ComFilterModel com_filter_model(double z0, double g, double T, double sigma_position,
                                double sigma_velocity, double sigma_zmp);

// Measurement matrices. Kinematic CoM + FSR CoP: y = [x, x_zmp, y, y_zmp].
Eigen::Matrix<double, 4, 6> com_cop_measurement();
// The printed C with total horizontal force f = m omega^2 (x - x_zmp): y = [x, x_zmp, fx, y, y_zmp,
// fy].
Eigen::Matrix<double, 6, 6> com_cop_force_measurement(double mass, double omega);

struct ComEstimate {
  ComFilterState x = ComFilterState::Zero();
  ComFilterCovariance P = ComFilterCovariance::Identity();
};

// Time update x <- A x + B u, P <- A P A^T + Q.
ComEstimate predict(const ComFilterModel& model, const ComEstimate& e, const Eigen::Vector2d& u);

// Measurement update with any linear measurement y = C x + v, v ~ N(0, R), of at most
// kMaxMeasurements values (more: stride::Error). Does not allocate (fixed-size arguments bind
// without a copy).
constexpr int kMaxMeasurements = 6;
ComEstimate update(const ComEstimate& e, const Eigen::Ref<const Eigen::VectorXd>& y,
                   const Eigen::Ref<const Eigen::MatrixXd>& C,
                   const Eigen::Ref<const Eigen::MatrixXd>& R);

}  // namespace stride::balance
