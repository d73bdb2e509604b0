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
