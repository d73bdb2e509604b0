// The WalkPlan placed in the drawn world: the walk frame anchored on the planned support foot
// (both feet: their midpoint), ZMP reference and footsteps mapped with it, and the plan read
// from the console's printed values (a plan never written, or none at all, draws nothing).
#include <gtest/gtest.h>

#include <cmath>

#include "console/view/walk_plan_overlay.hpp"
#include "robot/core/data_dir.hpp"
#include "robot/model/urdf_loader.hpp"

namespace stride::view {
namespace {

const model::RobotModel& nao() {
  static const model::RobotModel m = model::load_urdf(data_file("scenes/robots/nao/nao.urdf"));
  return m;
}

Eigen::Isometry3d pose(double x, double y, double yaw) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.translate(Eigen::Vector3d(x, y, 0.045));
  p.rotate(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  return p;
}

// A frame whose feet are drawn at the given poses (x, y, yaw), every other link at the origin.
RobotFrame drawn_feet(const Eigen::Vector3d& left, const Eigen::Vector3d& right) {
  RobotFrame f;
  f.links.assign(nao().links.size(), Eigen::Isometry3d::Identity());
  for (std::size_t i = 0; i < nao().links.size(); ++i) {
    if (nao().links[i].name == "LFoot") f.links[i] = pose(left.x(), left.y(), left.z());
    if (nao().links[i].name == "RFoot") f.links[i] = pose(right.x(), right.y(), right.z());
  }
  return f;
}

WalkPlanValues plan(int support) {
  WalkPlanValues p;
  p.zmp = {0.12, -0.01};
  p.support = support;
  p.left = {0.10, 0.05, 0};
  p.right = {0.14, -0.05, 0};
  p.steps = {{0.18, 0.05, 0, 1}, {0.22, -0.05, 0, 2}};
  return p;
}

TEST(WalkPlanOverlay, AnchoredOnTheSupportFootTurnedAndMoved) {
  // The right foot carries the robot, drawn at (1, 2) turned by 90 degrees.
  RobotFrame f = drawn_feet({0.9, 2.1, M_PI / 2}, {1.0, 2.0, M_PI / 2});
  place_walk_plan(f, nao(), plan(2));
  ASSERT_TRUE(f.walk_frame && f.zmp_ref);
  // Planned right foot (0.14, -0.05) -> (1, 2); +x in the walk frame is +y in the world.
  // The ZMP is (-0.02, +0.04) from the planned right foot: turned, (-0.04, -0.02) from (1, 2).
  EXPECT_NEAR(f.zmp_ref->x(), 0.96, 1e-9);
  EXPECT_NEAR(f.zmp_ref->y(), 1.98, 1e-9);
  EXPECT_NEAR(f.walk_frame->z(), M_PI / 2, 1e-9);
  EXPECT_NEAR(f.walk_frame->x(), 1.0 - 0.05, 1e-9);
  EXPECT_NEAR(f.walk_frame->y(), 2.0 - 0.14, 1e-9);
  ASSERT_EQ(f.footsteps.size(), 2u);
  EXPECT_TRUE(f.footsteps[0].left);
  EXPECT_FALSE(f.footsteps[1].left);
  EXPECT_NEAR(f.footsteps[1].pose.x(), 1.0, 1e-9);  // the right foot again, 0.08 ahead
  EXPECT_NEAR(f.footsteps[1].pose.y(), 2.08, 1e-9);
  EXPECT_NEAR(f.footsteps[1].pose.z(), M_PI / 2, 1e-9);
}

TEST(WalkPlanOverlay, BothFeetAnchorTheirMidpoint) {
  RobotFrame f = drawn_feet({0.3, 0.05, 0}, {0.34, -0.05, 0});
  place_walk_plan(f, nao(), plan(0));
  ASSERT_TRUE(f.zmp_ref);
  EXPECT_NEAR(f.zmp_ref->x(), 0.32, 1e-9);  // plan midpoint (0.12, 0) -> (0.32, 0)
  EXPECT_NEAR(f.zmp_ref->y(), -0.01, 1e-9);
  EXPECT_NEAR(f.walk_frame->x(), 0.2, 1e-9);
}

TEST(WalkPlanOverlay, ReadsThePrintedPlanAndNothingElse) {
  const std::string printed =
      "{t=0.99, zmp=[0.12, -0.01], support=1, left_foot=[0.1, 0.05, 0], right_foot=[0.14, -0.05, "
      "0], steps=2, step_x=[0.18, 0.22, 0, 0], step_y=[0.05, -0.05, 0, 0], step_yaw=[0, 0, 0, 0], "
      "step_foot=[1, 2, 0, 0]}";
  auto p = read_walk_plan(printed);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->support, 1);
  EXPECT_EQ(p->zmp[1], -0.01);
  EXPECT_EQ(p->right[0], 0.14);
  ASSERT_EQ(p->steps.size(), 2u);  // only `steps` of the four slots
  EXPECT_EQ(p->steps[1][0], 0.22);
  EXPECT_EQ(p->steps[1][3], 2);
  auto with = [&](const std::string& from, const std::string& to) {
    std::string s = printed;
    return s.replace(s.find(from), from.size(), to);
  };
  // Never written (a log from before WalkPlan): both feet at the origin.
  EXPECT_FALSE(read_walk_plan(with("left_foot=[0.1, 0.05, 0]", "left_foot=[0.14, -0.05, 0]")));
  EXPECT_FALSE(read_walk_plan(with("zmp=[0.12, -0.01]", "zmp=[0.12]")));
  EXPECT_FALSE(read_walk_plan(with("support=1", "support=x")));
  EXPECT_FALSE(read_walk_plan(with("steps=2, ", "")));
  EXPECT_FALSE(read_walk_plan(""));
  EXPECT_FALSE(read_walk_plan("{"));
  EXPECT_FALSE(read_walk_plan("[0.1, 0.2]"));
}

// A robot seen through its sensors alone stands where its plan puts it: the drawn support foot
// moves onto the planned one, turned to its heading, and every link, the CoM and the support
// polygon move with it (the body keeps its shape); the walk frame is then the world's.
TEST(WalkPlanOverlay, ARobotWithoutAWorldPoseStandsOnItsPlan) {
  RobotFrame f = drawn_feet({0.9, 2.1, M_PI / 2}, {1.0, 2.0, M_PI / 2});
  f.com = Eigen::Vector3d(0.95, 2.05, 0.3);
  f.support = {{1.0, 2.0}, {1.1, 2.0}, {1.1, 2.05}};
  const RobotFrame before = f;
  stand_on_plan(f, nao(), plan(2));
  int right = -1, left = -1;
  for (std::size_t i = 0; i < nao().links.size(); ++i) {
    if (nao().links[i].name == "RFoot") right = static_cast<int>(i);
    if (nao().links[i].name == "LFoot") left = static_cast<int>(i);
  }
  ASSERT_GE(right, 0);
  ASSERT_GE(left, 0);
  const Eigen::Isometry3d& r = f.links[static_cast<std::size_t>(right)];
  EXPECT_NEAR(r.translation().x(), 0.14, 1e-12);
  EXPECT_NEAR(r.translation().y(), -0.05, 1e-12);
  EXPECT_NEAR(r.translation().z(), 0.045, 1e-12);  // still on the ground
  EXPECT_NEAR(std::atan2(r.linear()(1, 0), r.linear()(0, 0)), 0.0, 1e-12);
  // The left foot was drawn 0.1 m to the robot's left (-x, facing +y) and 0.1 m ahead (+y).
  const Eigen::Vector3d l = f.links[static_cast<std::size_t>(left)].translation();
  EXPECT_NEAR(l.x(), 0.14 + 0.1, 1e-12);
  EXPECT_NEAR(l.y(), -0.05 + 0.1, 1e-12);
  EXPECT_NEAR((*f.com - r.translation()).norm(),
              (*before.com - before.links[static_cast<std::size_t>(right)].translation()).norm(),
              1e-12);
  ASSERT_EQ(f.support.size(), 3u);
  EXPECT_NEAR(f.support[0].x(), 0.14, 1e-12);
  EXPECT_NEAR(f.support[0].y(), -0.05, 1e-12);
  EXPECT_NEAR(f.support[1].x(), 0.14, 1e-12);  // +x in the drawn frame is the robot's right
  EXPECT_NEAR(f.support[1].y(), -0.05 - 0.1, 1e-12);
  // Placed afterwards, the walk frame is the world's own.
  place_walk_plan(f, nao(), plan(2));
  ASSERT_TRUE(f.walk_frame && f.zmp_ref);
  EXPECT_NEAR(f.walk_frame->norm(), 0.0, 1e-12);
  EXPECT_NEAR(f.zmp_ref->x(), 0.12, 1e-12);
  EXPECT_NEAR(f.zmp_ref->y(), -0.01, 1e-12);
}

}  // namespace
}  // namespace stride::view
