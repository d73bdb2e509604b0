// The gains experiment's walk: the named strategy's medium-speed scene with the swept gains on
// that strategy's module, pitch and roll alike; an unknown strategy is a one-line error.
#include <gtest/gtest.h>

#include "console/experiments/gains_experiment.hpp"
#include "robot/core/error.hpp"

namespace stride::experiments {
namespace {

ExperimentOptions options() {
  ExperimentOptions o;
  o.scenes_dir = std::string(STRIDE_SOURCE_DIR) + "/scenes/experiments";
  return o;
}

TEST(GainsWalk, SetsBothAxesOnTheStrategysModule) {
  const WalkSetup w = gains_walk(options(), "ankle", 0.5, -0.08, 7);
  EXPECT_EQ(w.scene, options().scenes_dir + "/ankle_medium.xml");
  EXPECT_EQ(w.seed, 7u);
  ASSERT_EQ(w.parameters.size(), 1u);
  EXPECT_EQ(w.parameters[0].first, "AnkleStrategy");
  EXPECT_EQ(w.parameters[0].second, "kp_pitch=0.5 kd_pitch=-0.08 kp_roll=0.5 kd_roll=-0.08");
  EXPECT_EQ(gains_walk(options(), "hip", 0.4, -0.05, 1).parameters[0].first, "HipStrategy");
}

TEST(GainsWalk, UnknownStrategyIsNamed) {
  try {
    gains_walk(options(), "knee", 0.4, -0.05, 1);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("unknown strategy 'knee'"), std::string::npos);
  }
}

}  // namespace
}  // namespace stride::experiments
