// Ch. 6 in simulation: a sole set down on a floor 10 mm higher than planned. The position-
// controlled leg drives into it up to its motors' limits; under the impedance law (Eq. 6.17) the
// floor carries K_z times the shortfall, as a spring would.
#include <gtest/gtest.h>

#include "console/experiments/landing_impact_study.hpp"
#include "robot/core/error.hpp"

namespace stride::experiments {
namespace {

LandingOptions options(bool impedance) {
  LandingOptions o;
  o.scene = STRIDE_SOURCE_DIR "/scenes/landing/landing_nao.xml";
  o.impedance = impedance;
  o.depth = 0.01;
  return o;
}

TEST(LandingImpact, ImpedanceLawTurnsAnEarlyFloorIntoASpringForce) {
  const LandingResult position = run_landing(options(false));
  const LandingResult impedance = run_landing(options(true));
  ASSERT_GT(position.touchdown, 0.0);
  ASSERT_GT(impedance.touchdown, 0.0);
  const double kz = options(true).stiffness.z();
  EXPECT_NEAR(impedance.final_force, kz * 0.01, 0.25 * kz * 0.01);
  EXPECT_GT(position.final_force, 20 * impedance.final_force);
  EXPECT_LT(impedance.peak_force, position.peak_force / 5);
  // The figures `stride landing --depth 0.01` printed when both controllers ran as a lambda on
  // the simulator's ideal joint state; as the LandingPosition and LandingImpedance modules (joint
  // velocities from the encoders) they stay within 4 %. The position controller's, re-derived when
  // the rig took the default contact law and the exact solver (issue 47): it drives the sole 1 cm
  // into a floor that now yields (1e5 N/m) instead of a hard one, so it pushes longer and harder.
  // The impedance figures re-derived when the law's per-body split went by depth (0.251 -> 0.262
  // N s, 25.1 -> 26.2 N): the corners that touch first keep the sole's spring as the rest arrive.
  EXPECT_NEAR(position.touchdown, 0.105, 0.0011);
  EXPECT_NEAR(impedance.touchdown, 0.117, 0.0011);
  EXPECT_NEAR(position.impulse, 2.530, 0.04 * 2.530);
  EXPECT_NEAR(impedance.impulse, 0.262, 0.04 * 0.262);
  EXPECT_NEAR(position.peak_force, 550.4, 0.04 * 550.4);
  EXPECT_NEAR(impedance.peak_force, 26.2, 0.04 * 26.2);
  EXPECT_NEAR(position.final_force, 553.4, 0.04 * 553.4);
  EXPECT_NEAR(impedance.final_force, 3.0, 0.04 * 3.0);
}

TEST(LandingImpact, RefusesAFloatingRobotAndBadPlans) {
  LandingOptions o = options(true);
  o.scene = STRIDE_SOURCE_DIR "/scenes/nao_stand.xml";
  EXPECT_THROW(run_landing(o), Error);
  o = options(true);
  o.speed = -1;
  EXPECT_THROW(run_landing(o), Error);
}

}  // namespace
}  // namespace stride::experiments
