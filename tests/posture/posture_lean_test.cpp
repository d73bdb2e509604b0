// The posture strategies' P term on a robot that leans: standing on flat feet, a hip-pitch
// calibration error of 3 deg leans the torso back by about 3 deg; the correction of Eqs. 4.8 and
// 4.10 (or 4.12 and 4.14) then turns the hips (or ankles) by K_p times the lean, which leans the
// torso back by as much again, so the lean settles at lean_0 / (1 - K_p): Sec. 4.3.4.2's torso
// that leans further back the larger K_p is.
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "console/session/sim_session.hpp"

namespace stride {
namespace {

// The standing phase (the walk starts at 2 s) of scenes/experiments/lean/<strategy>_medium.xml
// with K_p on both axes and K_d = 0: the torso's true pitch at 1.9 s.
double standing_pitch(const std::string& strategy, const std::string& module, double kp) {
  console::SimSession session(std::string(STRIDE_SOURCE_DIR) + "/scenes/experiments/lean/" +
                              strategy + "_medium.xml");
  const std::string k = std::to_string(kp);
  session.runtime(0)->set_parameters(module,
                                     "kp_pitch=" + k + " kp_roll=" + k + " kd_pitch=0 kd_roll=0");
  session.simulation().run_for(1.9);
  return session.simulation().robot(0).torso_pose().pitch;
}

void expect_lean_grows_as_one_over_one_minus_kp(const std::string& strategy,
                                                const std::string& module) {
  const double lean0 = standing_pitch(strategy, module, 0.0);
  EXPECT_NEAR(lean0, -3 * std::numbers::pi / 180, 0.006);  // back by the calibration error
  for (double kp : {0.25, 0.5}) {
    const double lean = standing_pitch(strategy, module, kp);
    EXPECT_NEAR(lean / lean0, 1 / (1 - kp), 0.03 / (1 - kp)) << strategy << " K_p " << kp;
  }
}

TEST(PostureLean, HipPTermMultipliesAStaticLeanByOneOverOneMinusKp) {
  expect_lean_grows_as_one_over_one_minus_kp("hip", "HipStrategy");
}

TEST(PostureLean, AnklePTermMultipliesAStaticLeanByOneOverOneMinusKp) {
  expect_lean_grows_as_one_over_one_minus_kp("ankle", "AnkleStrategy");
}

}  // namespace
}  // namespace stride
