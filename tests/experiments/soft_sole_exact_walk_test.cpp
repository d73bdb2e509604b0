// On scenes/experiments/soft_sole_exact (rubber soles, 100/s leg servos, exact solver, Q rate
// 3e-5) posture control decides the medium walk of Sec. 4.3.4.2: without it the torso passes
// 0.4 rad or the robot falls; with either strategy it walks the 15 s upright and forward. The
// walks and the lost criterion are the posture study's own (posture.sweep.xml).
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "tests/experiments/study_rows.hpp"

namespace stride::experiments {
namespace {

test::Row walk(const std::string& c) {
  const auto rows = test::study_rows("posture", "soft_sole_exact", {{"case", {c}}});
  EXPECT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows.at(0).at("status"), "ok") << rows.at(0).at("reason");
  return rows.at(0);
}

double number(const test::Row& r, const std::string& column) {
  return std::stod(r.at(column));
}

TEST(SoftSoleExactWalk, WithoutPostureControlTheMediumWalkIsLost) {
  EXPECT_EQ(walk("none_medium").at("lost"), "1");
}

void expect_kept(const test::Row& s) {
  EXPECT_EQ(s.at("lost"), "0");
  EXPECT_GT(number(s, "fk_distance"), 2.0);  // thesis Figs. 4.7, 4.11: 2.88 m, 2.61 m
  EXPECT_LT(std::max(-number(s, "pitch_min"), number(s, "pitch_max")), 0.2);
}

TEST(SoftSoleExactWalk, HipStrategyKeepsTheMediumWalk) {
  expect_kept(walk("hip_medium"));
}

TEST(SoftSoleExactWalk, AnkleStrategyKeepsTheMediumWalk) {
  expect_kept(walk("ankle_medium"));
}

}  // namespace
}  // namespace stride::experiments
