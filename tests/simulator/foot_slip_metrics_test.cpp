// The walk report's foot figures against closed form: a NAO sliding to rest on low friction
// covers v0^2 / (2 mu g), a standing NAO's feet neither slide, tilt nor turn, and turning the
// standing robot in place turns each loaded foot by that angle.
#include <cmath>

#include <gtest/gtest.h>

#include "simulator/teleport.hpp"
#include "simulator/world/ode/ode_robot_body.hpp"
#include "tests/simulator/sim_test_util.hpp"

namespace stride {
namespace {

// 20 solver iterations, as the walking studies whose feet the metric describes: at the default
// 10 a standing robot's feet creep about 1 mm/s, which would hide the metric's own error.
std::string stand_scene(double friction) {
  return R"(<scene><physics seed="5" iterations="20"/><ground friction=")" +
         std::to_string(friction) + R"("/>
    <robot name="nao" urdf="../../scenes/robots/nao/nao.urdf" devices="../../scenes/robots/nao/nao.devices.xml">
      <joints LHipPitch="-0.3" RHipPitch="-0.3" LKneePitch="0.6" RKneePitch="0.6"
              LAnklePitch="-0.3" RAnklePitch="-0.3" LShoulderPitch="1.5" RShoulderPitch="1.5"/>
      <sensors noise="off"/>
    </robot></scene>)";
}

TEST(FootSlipMetrics, StandingFeetNeitherSlideNorTilt) {
  auto sim = test::scene_from_text(stand_scene(0.8));
  sim->run_for(3.0);
  const auto r = sim->walk_metrics(0).result();
  EXPECT_LT(r.foot_slip, 1e-3);
  EXPECT_LT(r.foot_tilt_max, 0.01);
  EXPECT_EQ(r.foot_tilted_time, 0.0);
  EXPECT_LT(r.foot_spin, 1e-3);
  EXPECT_LT(r.yaw_max - r.yaw_min, 1e-3);
}

TEST(FootSlipMetrics, TurningTheStandingRobotTurnsEachLoadedFootByTheAngle) {
  auto sim = test::scene_from_text(stand_scene(0.8));
  sim->run_for(0.5);
  const auto before = sim->walk_metrics(0).result();
  const auto torso = sim->robot(0).torso_pose();
  sim::teleport_robot(*sim, 0, Eigen::Vector3d(torso.x, torso.y, torso.z),
                      0.3);  // within one stance
  sim->run_for(0.5);
  const auto r = sim->walk_metrics(0).result();
  EXPECT_NEAR(r.foot_spin - before.foot_spin, 2 * 0.3, 0.01);
  EXPECT_NEAR(r.foot_spin_max, 0.3, 0.005);
  EXPECT_NEAR(r.yaw_max, 0.3, 0.005);
  EXPECT_FALSE(sim->robot(0).fallen());
}

TEST(FootSlipMetrics, SlidingRobotCoversTheCoulombStoppingDistance) {
  const double mu = 0.1, v0 = 0.4, g = 9.81;
  auto sim = test::scene_from_text(stand_scene(mu));
  sim->run_for(0.5);  // settled, feet flat
  const double slip_before = sim->walk_metrics(0).result().foot_slip;
  const auto& body = dynamic_cast<const sim::OdeRobotBody&>(sim->robot(0).body());
  for (int l = 0; l < body.link_count(); ++l) {  // the whole robot moving forward at v0
    dBodySetLinearVel(body.body(l), v0, 0, 0);
    dBodySetAngularVel(body.body(l), 0, 0, 0);
  }
  sim->run_for(1.5);  // stops after v0 / (mu g) = 0.41 s
  const auto r = sim->walk_metrics(0).result();
  const double expected = v0 * v0 / (2 * mu * g);  // 81.5 mm per foot
  RecordProperty("slip_per_foot_m", std::to_string((r.foot_slip - slip_before) / 2));
  EXPECT_NEAR((r.foot_slip - slip_before) / 2, expected, 0.05 * expected);
  EXPECT_NEAR(r.foot_slip_net_x / 2, expected, 0.05 * expected);  // all of it forward
  EXPECT_FALSE(sim->robot(0).fallen());
}

}  // namespace
}  // namespace stride
