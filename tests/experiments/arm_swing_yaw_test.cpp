// Sec. 4.4's purpose, measured: at the fastest of Fig. 4.18's speeds the arm swing of Eq. 4.20
// takes yaw moment off the support foot, which then turns less per stance (the arm-swing study's
// own sweep file, its walks with the swing on and off).
#include <string>

#include <gtest/gtest.h>

#include "tests/experiments/study_rows.hpp"

namespace stride::experiments {
namespace {

TEST(ArmSwingYaw, SwingCutsTheSupportFootTurnAtTheHighSpeed) {
  const auto rows = test::study_rows("arm-swing", "", {{"target_v", {"0.1940"}}});
  ASSERT_EQ(rows.size(), 2u);
  double turn[2] = {0, 0};  // per step: on, off
  for (const auto& r : rows) {
    ASSERT_EQ(r.at("status"), "ok") << r.at("reason");
    EXPECT_EQ(r.at("fell"), "0");
    const double steps = std::stod(r.at("steps"));
    EXPECT_GT(steps, 70);
    turn[r.at("swing") == "on" ? 0 : 1] = std::stod(r.at("foot_spin")) / steps;
  }
  RecordProperty("turn_per_step_on_mrad", std::to_string(1000 * turn[0]));
  RecordProperty("turn_per_step_off_mrad", std::to_string(1000 * turn[1]));
  EXPECT_LT(turn[0], 0.8 * turn[1]);  // 6 seeds: 29 against 48 mrad per step
}

}  // namespace
}  // namespace stride::experiments
