// CARE solver against closed-form solutions, and the LQR of Eq. 7.39.
#include "behaviours/balance/care_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "robot/core/error.hpp"

namespace stride::balance {
namespace {

using Eigen::MatrixXd;

MatrixXd m1(double v) {
  return MatrixXd::Constant(1, 1, v);
}

TEST(CareSolver, ScalarClosedForm) {
  // 2 a s - s^2 b^2 / r + q = 0  =>  s = r (a + sqrt(a^2 + q b^2 / r)) / b^2.
  for (const double a : {-2.0, 0.0, 1.5}) {
    const double b = 0.7, q = 3.0, r = 0.4;
    const MatrixXd S = solve_care(m1(a), m1(b), m1(q), m1(r));
    EXPECT_NEAR(S(0, 0), r * (a + std::sqrt(a * a + q * b * b / r)) / (b * b), 1e-10) << a;
  }
}

TEST(CareSolver, DoubleIntegratorClosedForm) {
  MatrixXd A(2, 2), B(2, 1);
  A << 0, 1, 0, 0;
  B << 0, 1;
  const LqrSolution sol = lqr(A, B, MatrixXd::Identity(2, 2), m1(1.0));
  const double r3 = std::sqrt(3.0);
  EXPECT_NEAR(sol.S(0, 0), r3, 1e-10);
  EXPECT_NEAR(sol.S(0, 1), 1.0, 1e-10);
  EXPECT_NEAR(sol.S(1, 0), 1.0, 1e-10);
  EXPECT_NEAR(sol.S(1, 1), r3, 1e-10);
  EXPECT_NEAR(sol.K(0, 0), 1.0, 1e-10);
  EXPECT_NEAR(sol.K(0, 1), r3, 1e-10);
  for (Eigen::Index i = 0; i < 2; ++i) {  // closed-loop poles -(sqrt 3)/2 +- i/2
    EXPECT_NEAR(sol.closed_loop_poles(i).real(), -r3 / 2, 1e-10);
    EXPECT_NEAR(std::abs(sol.closed_loop_poles(i).imag()), 0.5, 1e-10);
  }
}

TEST(CareSolver, RandomSystemsHaveSmallResidualAndStableClosedLoop) {
  std::srand(7);
  for (int trial = 0; trial < 5; ++trial) {
    const MatrixXd A = MatrixXd::Random(5, 5), B = MatrixXd::Random(5, 2);
    const MatrixXd Lq = MatrixXd::Random(5, 5);
    const MatrixXd Q = Lq * Lq.transpose() + 0.1 * MatrixXd::Identity(5, 5);
    const MatrixXd R = (Eigen::Vector2d(0.5, 2.0)).asDiagonal();
    const LqrSolution sol = lqr(A, B, Q, R);
    EXPECT_LT(care_residual(A, B, Q, R, sol.S).norm(), 1e-9 * (1 + sol.S.norm()));
    EXPECT_LT((sol.S - sol.S.transpose()).norm(), 1e-12 * (1 + sol.S.norm()));
    EXPECT_GT(sol.S.selfadjointView<Eigen::Lower>().eigenvalues().minCoeff(), 0.0);
    EXPECT_LT(sol.closed_loop_poles.real().maxCoeff(), 0.0);
  }
}

TEST(CareSolver, LyapunovSolution) {
  MatrixXd Ac(2, 2);
  Ac << -1, 2, 0, -3;
  const MatrixXd M = MatrixXd::Identity(2, 2);
  const MatrixXd X = solve_lyapunov(Ac, M);
  EXPECT_LT((Ac.transpose() * X + X * Ac + M).norm(), 1e-12);
}

TEST(CareSolver, BadInputIsAnError) {
  EXPECT_THROW(solve_care(MatrixXd::Zero(2, 3), MatrixXd::Zero(2, 1), MatrixXd::Zero(2, 2), m1(1)),
               Error);
  EXPECT_THROW(solve_care(m1(1), m1(1), m1(1), m1(-1)), Error);  // R not positive definite
  // Unstable mode with no input authority: not stabilisable.
  MatrixXd A(2, 2), B(2, 1);
  A << 1, 0, 0, -1;
  B << 0, 1;
  EXPECT_THROW(solve_care(A, B, MatrixXd::Identity(2, 2), m1(1)), Error);
}

}  // namespace
}  // namespace stride::balance
