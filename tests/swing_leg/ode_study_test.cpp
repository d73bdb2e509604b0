// Sec. 5.4.2 on the simulated NAO: the left leg in torque mode follows the pattern under PD and
// (slowly adapting) adaptive control; scenes that do not fit the study are refused.
#include <gtest/gtest.h>

#include "console/experiments/swing_leg_ode_study.hpp"
#include "robot/core/error.hpp"

namespace stride::experiments {
namespace {

OdeSwingLegOptions options(swing_leg::Controller c) {
  OdeSwingLegOptions o;
  o.scene = STRIDE_SOURCE_DIR "/scenes/swing_leg/hanging_nao.xml";
  o.controller = c;
  o.lambda = 20;
  o.kd = 0.1;
  o.duration = 2.5;
  o.gamma = thesis_ode_gamma() * 0.01;
  return o;
}

TEST(OdeSwingLeg, BothLawsTrackThePatternWithinTheMotorsLimits) {
  const OdeSwingLegResult pd = run_ode_swing_leg(options(swing_leg::Controller::Pd));
  const OdeSwingLegResult adaptive = run_ode_swing_leg(options(swing_leg::Controller::Adaptive));
  for (const auto* r : {&pd, &adaptive}) {
    ASSERT_EQ(r->rms_error.size(), 5);
    EXPECT_LT(r->rms_error.maxCoeff(), 0.2);  // the pattern's hip pitch swings ~0.5 rad
    EXPECT_GT(r->rms_error.minCoeff(), 0.0);
    EXPECT_EQ(r->saturated, 0.0);
  }
  // The feed-forward the estimates build lowers the hip pitch error (PD: K_P = lambda K_D).
  EXPECT_LT(adaptive.rms_error[1], pd.rms_error[1]);
  // The figures `stride swing-leg ode-track --seconds 2.5 --gamma-scale 0.01` printed when the
  // laws ran as a lambda on the simulator's ideal joint velocities; the SwingLegTracking module
  // differentiates the encoder angles instead and stays within 1.5 % of them.
  const double lambda_era_pd[] = {9.85e-03, 1.37e-01, 8.25e-02, 2.58e-02, 2.88e-03};
  const double lambda_era_adaptive[] = {6.74e-03, 6.88e-02, 5.88e-02, 2.14e-02, 2.60e-03};
  for (int i = 0; i < 5; ++i) {
    EXPECT_NEAR(pd.rms_error[i], lambda_era_pd[i], 0.015 * lambda_era_pd[i]) << i;
    EXPECT_NEAR(adaptive.rms_error[i], lambda_era_adaptive[i], 0.015 * lambda_era_adaptive[i]) << i;
  }
  EXPECT_NEAR(pd.max_torque, 1.25, 0.02);
  // Re-derived when the hanging NAO took the exact solver (issue 47): 3.88 at iterative 20.
  EXPECT_NEAR(adaptive.max_torque, 3.81, 0.06);
}

TEST(OdeSwingLeg, RefusesScenesWithoutAOneMillisecondLoop) {
  OdeSwingLegOptions o = options(swing_leg::Controller::Pd);
  o.scene = STRIDE_SOURCE_DIR "/scenes/nao_stand.xml";  // 10 ms period
  try {
    run_ode_swing_leg(o);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("needs a 1 ms control period"), std::string::npos);
  }
  o = options(swing_leg::Controller::Adaptive);
  o.gamma.resize(3);
  EXPECT_THROW(run_ode_swing_leg(o), Error);
}

}  // namespace
}  // namespace stride::experiments
