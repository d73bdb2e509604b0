#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>

#include "robot/model/dynamics/integrator.hpp"
#include "robot/model/dynamics/swing_leg_3d.hpp"
#include "robot/model/dynamics/swing_leg_planar.hpp"

namespace stride::model {
namespace {

// A printed value agrees when it is the computed one rounded to the printed decimals.
void expect_printed(double computed, double printed, int decimals, int index) {
  EXPECT_LE(std::abs(computed - printed), 0.5 * std::pow(10.0, -decimals) + 1e-15)
      << "a" << index + 1 << " = " << computed << ", thesis prints " << printed;
}

TEST(SwingLegPlanar, ParametersMatchTheThesis) {  // Sec. 5.4.1.1
  const double printed[9] = {0.00725,  0.0031, 0.00355, 0.000539, 0.000814,
                             0.000524, 0.650,  0.3044,  0.0514};
  const int decimals[9] = {5, 4, 5, 6, 6, 6, 3, 4, 4};
  const Vector9d a = planar_parameters(thesis_planar_leg());
  for (int i = 0; i < 9; ++i) expect_printed(a[i], printed[i], decimals[i], i);
}

TEST(SwingLeg3d, ParametersMatchTheThesis) {  // Sec. 5.4.1.2
  const double printed[17] = {0.0011,   0.000717, 0.0029, 0.000276, 0.0016,    0.0017,
                              0.000668, 0.000688, 0.0031, 0.0028,   0.0002694, 0.0016,
                              0.0011,   0.000644, 0.65,   0.305,    0.0656};
  const int decimals[17] = {4, 6, 4, 6, 4, 4, 6, 6, 4, 4, 7, 4, 4, 6, 2, 3, 4};
  const Vector17d a = leg3d_parameters(thesis_3d_leg());
  for (int i = 0; i < 17; ++i) expect_printed(a[i], printed[i], decimals[i], i);
}

template <int N>
Eigen::Matrix<double, N, 1> random_vector(std::mt19937& rng, double range) {
  Eigen::Matrix<double, N, 1> v;
  for (int i = 0; i < N; ++i) v[i] = std::uniform_real_distribution<double>(-range, range)(rng);
  return v;
}

// Checks the structure any Lagrangian model must have, H and C given as functions of (q, qd).
template <int N, typename Inertia, typename Coriolis>
void expect_lagrangian_structure(const Inertia& inertia, const Coriolis& coriolis,
                                 std::mt19937& rng) {
  using M = Eigen::Matrix<double, N, N>;
  for (int trial = 0; trial < 200; ++trial) {
    const auto q = random_vector<N>(rng, 1.5), qd = random_vector<N>(rng, 3.0);
    const M h = inertia(q);
    EXPECT_LT((h - h.transpose()).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<M>(h).eigenvalues().minCoeff(), 0.0);
    constexpr double step = 1e-6;  // H' along the motion by central differences
    const M hdot = (inertia(q + step * qd) - inertia(q - step * qd)) / (2 * step);
    const M n = hdot - 2 * coriolis(q, qd);
    EXPECT_LT((n + n.transpose()).cwiseAbs().maxCoeff(), 1e-8);
  }
}

TEST(SwingLegPlanar, InertiaPositiveDefiniteAndHdotMinus2CSkew) {
  std::mt19937 rng(11);
  const Vector9d a = planar_parameters(thesis_planar_leg());
  expect_lagrangian_structure<3>([&](const Eigen::Vector3d& q) { return planar_inertia(q, a); },
                                 [&](const Eigen::Vector3d& q, const Eigen::Vector3d& qd) {
                                   return planar_coriolis(q, qd, a);
                                 },
                                 rng);
}

TEST(SwingLeg3d, InertiaPositiveDefiniteAndHdotMinus2CSkew) {
  std::mt19937 rng(12);
  const Vector17d a = leg3d_parameters(thesis_3d_leg());
  expect_lagrangian_structure<5>(
      [&](const Vector5d& q) { return leg3d_terms(q, Vector5d::Zero(), a).inertia; },
      [&](const Vector5d& q, const Vector5d& qd) { return leg3d_terms(q, qd, a).coriolis; }, rng);
}

TEST(SwingLegPlanar, RegressorTimesParametersIsTheDynamics) {  // Eq. 5.4
  std::mt19937 rng(13);
  const Vector9d a = planar_parameters(thesis_planar_leg());
  for (int trial = 0; trial < 200; ++trial) {
    const auto q = random_vector<3>(rng, 1.5), qd = random_vector<3>(rng, 3),
               qdr = random_vector<3>(rng, 3), qddr = random_vector<3>(rng, 10);
    const Eigen::Vector3d expected =
        planar_inertia(q, a) * qddr + planar_coriolis(q, qd, a) * qdr + planar_gravity(q, a);
    EXPECT_LT((planar_regressor(q, qd, qdr, qddr) * a - expected).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(SwingLeg3d, RegressorTimesParametersIsTheDynamics) {
  std::mt19937 rng(14);
  const Vector17d a = leg3d_parameters(thesis_3d_leg());
  for (int trial = 0; trial < 200; ++trial) {
    const auto q = random_vector<5>(rng, 1.5), qd = random_vector<5>(rng, 3),
               qdr = random_vector<5>(rng, 3), qddr = random_vector<5>(rng, 10);
    const Leg3dTerms t = leg3d_terms(q, qd, a);
    const Vector5d expected = t.inertia * qddr + t.coriolis * qdr + t.gravity;
    EXPECT_LT((leg3d_regressor(q, qd, qdr, qddr) * a - expected).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(SwingLeg3d, CheapCoriolisVectorEqualsTheMatrixForm) {
  std::mt19937 rng(16);
  const Vector17d a = leg3d_parameters(thesis_3d_leg());
  for (int trial = 0; trial < 200; ++trial) {
    const auto q = random_vector<5>(rng, 1.5), qd = random_vector<5>(rng, 3);
    const Vector5d expected = leg3d_terms(q, qd, a).coriolis * qd;
    EXPECT_LT((leg3d_coriolis_times_velocity(q, qd, a) - expected).cwiseAbs().maxCoeff(), 1e-12);
  }
}

// With both rolls at zero the 3-D leg is the planar leg: J1 + J3 + J5 + J12 of the 3-D groups
// is the planar J1, and so on.
TEST(SwingLeg3d, ReducesToThePlanarModelWithoutRoll) {
  const PlanarLegData p = thesis_planar_leg();
  Leg3dData d{p.m1, p.m2, p.m3, 1e-3, 2e-3, 3e-4, p.i1, p.i2,
              p.i3, p.l1, p.l2, p.l3, p.b1, p.b2, p.b3};
  const Vector17d a3 = leg3d_parameters(d);
  const Vector9d a2 = planar_parameters(p);
  std::mt19937 rng(15);
  for (int trial = 0; trial < 50; ++trial) {
    const auto qp = random_vector<3>(rng, 1.5), qdp = random_vector<3>(rng, 3);
    Vector5d q = Vector5d::Zero(), qd = Vector5d::Zero();
    q.segment<3>(1) = qp;
    qd.segment<3>(1) = qdp;
    const Leg3dTerms t = leg3d_terms(q, qd, a3);
    EXPECT_LT((t.inertia.block<3, 3>(1, 1) - planar_inertia(qp, a2)).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_LT((t.coriolis.block<3, 3>(1, 1) - planar_coriolis(qp, qdp, a2)).cwiseAbs().maxCoeff(),
              1e-14);
    EXPECT_LT((t.gravity.segment<3>(1) - planar_gravity(qp, a2)).cwiseAbs().maxCoeff(), 1e-15);
  }
}

// Unforced swing from rest, 10 s with RK4 at 1 ms: energy stays within 1e-7 of its start.
TEST(SwingLegPlanar, Rk4ConservesEnergyOverTenSeconds) {
  const Vector9d a = planar_parameters(thesis_planar_leg());
  Eigen::Vector3d q(1.0, -0.8, 0.6), qd(0, 0, 0);
  const double e0 = planar_energy(q, qd, a);
  double drift = 0;
  for (int i = 0; i < 10000; ++i) {
    rk4_step<3>(q, qd, 1e-3, [&](const Eigen::Vector3d& x, const Eigen::Vector3d& v) {
      return planar_forward_dynamics(x, v, Eigen::Vector3d::Zero(), a);
    });
    drift = std::max(drift, std::abs(planar_energy(q, qd, a) - e0));
  }
  EXPECT_LT(drift, 1e-7 * std::abs(e0));  // measured: ~1e-9 relative
}

TEST(SwingLeg3d, Rk4ConservesEnergyOverTenSeconds) {
  const Vector17d a = leg3d_parameters(thesis_3d_leg());
  Vector5d q, qd = Vector5d::Zero();
  q << 0.3, 1.0, -0.8, 0.6, -0.2;
  const double e0 = leg3d_energy(q, qd, a);
  double drift = 0;
  for (int i = 0; i < 10000; ++i) {
    rk4_step<5>(q, qd, 1e-3, [&](const Vector5d& x, const Vector5d& v) {
      return leg3d_forward_dynamics(x, v, Vector5d::Zero(), a);
    });
    drift = std::max(drift, std::abs(leg3d_energy(q, qd, a) - e0));
  }
  EXPECT_LT(drift, 1e-7 * std::abs(e0));  // measured: ~1e-9 relative
}

}  // namespace
}  // namespace stride::model
