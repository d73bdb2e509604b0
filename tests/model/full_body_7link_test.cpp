#include <gtest/gtest.h>

#include <random>

#include <Eigen/Eigenvalues>

#include "robot/model/dynamics/full_body_7link.hpp"
#include "robot/model/dynamics/integrator.hpp"

namespace stride::model {
namespace {

FullBodyVector random_state(std::mt19937& rng, double range) {
  FullBodyVector v;
  for (int i = 0; i < kFullBodyDof; ++i)
    v[i] = std::uniform_real_distribution<double>(-range, range)(rng);
  return v;
}

TEST(FullBody7Link, LagrangianStructure) {  // Eq. D.13
  const FullBodyParams p = nao_full_body_params();
  std::mt19937 rng(21);
  for (int trial = 0; trial < 20; ++trial) {
    const FullBodyVector q = random_state(rng, 1.0), qd = random_state(rng, 2.0);
    const FullBodyTerms t = full_body_terms(p, q, qd);
    EXPECT_LT((t.inertia - t.inertia.transpose()).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<FullBodyMatrix>(t.inertia).eigenvalues().minCoeff(),
              0.0);
    constexpr double h = 1e-6;
    const FullBodyMatrix hdot =
        (full_body_terms(p, q + h * qd, qd).inertia - full_body_terms(p, q - h * qd, qd).inertia) /
        (2 * h);
    const FullBodyMatrix n = hdot - 2 * t.coriolis;
    EXPECT_LT((n + n.transpose()).cwiseAbs().maxCoeff(), 1e-8);
    // G is the gradient of the potential, J the derivative of the swing sole point.
    for (int i = 0; i < kFullBodyDof; ++i) {
      FullBodyVector lo = q, hi = q;
      lo[i] -= h;
      hi[i] += h;
      const FullBodyVector zero = FullBodyVector::Zero();
      const double dp = (full_body_energy(p, hi, zero) - full_body_energy(p, lo, zero)) / (2 * h);
      EXPECT_NEAR(t.gravity[i], dp, 1e-7);
      const Eigen::Vector3d dx =
          (full_body_swing_foot(p, hi) - full_body_swing_foot(p, lo)) / (2 * h);
      EXPECT_LT((t.swing_jacobian.col(i) - dx).cwiseAbs().maxCoeff(), 1e-8);
    }
  }
}

TEST(FullBody7Link, ZeroPostureFoldsTheSwingLegOntoTheStanceLeg) {
  const FullBodyParams p = nao_full_body_params();
  const Eigen::Vector3d sole = full_body_swing_foot(p, FullBodyVector::Zero());
  EXPECT_LT(sole.norm(), 1e-15);  // the model has no hip width: legs fold onto each other
}

TEST(FullBody7Link, TorsoTorquesEnterBothHips) {
  const FullBodyTerms t =
      full_body_terms(nao_full_body_params(), FullBodyVector::Zero(), FullBodyVector::Zero());
  // Hip pitch torques act on the torso pitch coordinate, the ankles only on their own.
  EXPECT_EQ(t.input(10, 3), 1.0);
  EXPECT_EQ(t.input(10, 6), 1.0);
  EXPECT_EQ(t.input(11, 4), -1.0);
  EXPECT_EQ(t.input(11, 5), 1.0);
  EXPECT_EQ(t.input.col(0), (FullBodyVector() << 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0).finished());
}

TEST(FullBody7Link, Rk4ConservesEnergyUnforced) {
  const FullBodyParams p = nao_full_body_params();
  FullBodyVector q = FullBodyVector::Zero(), qd = FullBodyVector::Zero();
  q << 0.05, 0.1, 0.2, -0.3, 0.05, 0.1, -0.4, 0.5, -0.1, 0.05, 0.1, -0.05;
  const double e0 = full_body_energy(p, q, qd);
  double drift = 0;
  for (int i = 0; i < 200; ++i) {  // 0.2 s: the unactuated chain falls fast
    rk4_step<kFullBodyDof>(q, qd, 1e-3, [&](const FullBodyVector& x, const FullBodyVector& v) {
      const FullBodyTerms t = full_body_terms(p, x, v);
      return FullBodyVector(t.inertia.llt().solve(-t.coriolis * v - t.gravity));
    });
    drift = std::max(drift, std::abs(full_body_energy(p, q, qd) - e0));
  }
  EXPECT_LT(drift, 1e-6 * std::abs(e0));
}

}  // namespace
}  // namespace stride::model
