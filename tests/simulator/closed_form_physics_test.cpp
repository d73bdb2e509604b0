// The physics engines against closed-form mechanics: free fall, a pendulum, friction on a ramp.
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "tests/simulator/sim_test_util.hpp"

namespace stride {
namespace {

constexpr double kG = 9.81;

// Free fall, the pendulum and the ramp on every engine built in; the contact spring is ODE's.
class ClosedFormPhysics : public ::testing::TestWithParam<std::string> {
 protected:
  std::unique_ptr<sim::Simulation> scene(const std::string& xml) const {
    return test::scene_from_text(test::on_engine(xml, GetParam()));
  }
};

TEST_P(ClosedFormPhysics, FreeFallFollowsHalfGTSquared) {
  auto sim = scene(R"(<scene><ground enabled="false"/>
    <robot name="ball" urdf="sphere.urdf" xyz="0 0 10"/></scene>)");
  const double t = 1.0;
  sim->run_for(t);
  const double z = sim->robot(0).torso_pose().z;
  // Semi-implicit Euler: z_n = z0 - g h^2 n (n + 1) / 2 exactly; closed form within g t h.
  const double h = sim->scene().physics.step;
  const double n = t / h;
  EXPECT_NEAR(z, 10 - kG * h * h * n * (n + 1) / 2, 1e-9);
  EXPECT_NEAR(z, 10 - kG * t * t / 2, kG * t * h);
}

double pendulum_energy(const sim::Simulation& s) {
  const auto& body = s.robot(0).body();
  const int bob = body.model().link_index("bob");
  const Eigen::Vector3d v = body.link_com_velocity(bob);
  const Eigen::Vector3d w = body.link_angular_velocity(bob);
  const double m = 0.5, i = 0.0002;
  const double ke = 0.5 * m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) +
                    0.5 * i * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  return ke + m * kG * body.link_com(bob).z();
}

TEST_P(ClosedFormPhysics, PendulumPeriodAndEnergyDrift) {
  auto sim = scene(R"(<scene><ground enabled="false"/>
    <physics solver="exact"/>
    <robot name="p" urdf="pendulum.urdf" xyz="0 0 1" fixed="true"><joints swing="0.05"/></robot></scene>)");
  const double m = 0.5, d = 0.4, i_pivot = 0.0002 + m * d * d;
  const double expected = 2 * std::numbers::pi * std::sqrt(i_pivot / (m * kG * d));
  const double e0 = pendulum_energy(*sim);
  const auto& body = sim->robot(0).body();
  double prev = body.joint_position(0), first = -1, last = -1;
  int crossings = 0;
  double max_drift = 0;
  while (sim->time() < 10.0) {
    sim->step();
    const double q = body.joint_position(0);
    if (prev > 0 && q <= 0) {  // downward zero crossing, interpolated
      const double tc = sim->time() - sim->scene().physics.step * q / (q - prev);
      if (first < 0) first = tc;
      last = tc;
      ++crossings;
    }
    prev = q;
    max_drift = std::max(max_drift, std::abs(pendulum_energy(*sim) - e0));
  }
  ASSERT_GE(crossings, 5);
  const double period = (last - first) / (crossings - 1);
  RecordProperty("period_s", std::to_string(period));
  RecordProperty("closed_form_period_s", std::to_string(expected));
  EXPECT_NEAR(period, expected, 0.005 * expected);
  const double swing_energy = m * kG * d * (1 - std::cos(0.05));
  RecordProperty("energy_drift_fraction_of_swing_energy", std::to_string(max_drift / swing_energy));
  EXPECT_LT(max_drift, 0.05 * swing_energy) << "energy drift over 10 s";
}

struct Slide {
  double v0 = 0;        // speed along the slope when measuring starts
  double distance = 0;  // travel down the slope in the following second
};

Slide slide_on_ramp(double mu, const std::string& engine) {
  const std::string xml = R"(<scene><ground enabled="false"/>
    <ramp name="r" xyz="-1 0 0" length="3" width="1" slope="10deg" friction=")" +
                          std::to_string(mu) + R"("/>
    <robot name="b" urdf="block.urdf" xyz="-0.0035 0 0.202" rpy="0 -10deg 0"/></scene>)";
  auto sim = test::scene_from_text(test::on_engine(xml, engine));
  sim->run_for(0.2);  // settle onto the ramp
  const auto p0 = sim->robot(0).torso_pose();
  const Eigen::Vector3d v = sim->robot(0).body().link_com_velocity(0);
  Slide s;
  s.v0 = std::hypot(v[0], v[2]);
  sim->run_for(1.0);
  const auto p1 = sim->robot(0).torso_pose();
  s.distance = std::hypot(p1.x - p0.x, p1.z - p0.z) * (p1.z < p0.z ? 1 : -1);
  return s;
}

TEST_P(ClosedFormPhysics, BoxSlidesOnTenDegreeRampWithLowFriction) {
  const double slope = 10 * std::numbers::pi / 180, mu = 0.1;
  const double a = kG * (std::sin(slope) - mu * std::cos(slope));  // 0.737 m/s^2
  const Slide s = slide_on_ramp(mu, GetParam());
  const double expected = s.v0 * 1.0 + 0.5 * a * 1.0 * 1.0;
  EXPECT_NEAR(s.distance, expected, 0.05 * expected);
}

TEST_P(ClosedFormPhysics, BoxHoldsOnTenDegreeRampWithHighFriction) {
  const Slide s =
      slide_on_ramp(0.3, GetParam());  // tan(10 deg) = 0.176 < 0.3: static friction holds
  EXPECT_LT(std::abs(s.distance), 0.002);
}

// A 1 kg ball set down on a contact spring k with damper c: a damped oscillator about the sink
// m g / k, period 2 pi / (w sqrt(1 - z^2)), w = sqrt(k / m), z = c / (2 sqrt(k m)). The spring
// acts below the world's 0.5 mm contact surface layer, where the ball starts at rest.
INSTANTIATE_TEST_SUITE_P(Engines, ClosedFormPhysics, ::testing::ValuesIn(test::engines()),
                         test::engine_name);

TEST(ClosedFormOdeContact, BallOnContactSpringSinksAndRingsAsAnOscillator) {
  const double k = 2e4, c = 20, m = 1;
  auto sim = test::scene_from_text(R"(<scene>
    <physics solver="exact" contact_stiffness="2e4" contact_damping="20"/>
    <robot name="ball" urdf="sphere.urdf" xyz="0 0 0.0495"/></scene>)");
  const double rest = 0.0495;  // radius less the surface layer: the spring's zero
  const double w = std::sqrt(k / m), zeta = c / (2 * std::sqrt(k * m));
  const double period = 2 * std::numbers::pi / (w * std::sqrt(1 - zeta * zeta));
  const double sink = m * kG / k;
  // Deepest points of the first rings: their spacing is the damped period.
  std::vector<double> troughs;
  double prev = rest, prev2 = rest, deepest = rest;
  while (sim->time() < 0.3) {
    sim->step();
    const double z = sim->robot(0).torso_pose().z;
    if (prev < prev2 && prev <= z) troughs.push_back(sim->time() - sim->scene().physics.step);
    deepest = std::min(deepest, z);
    prev2 = prev;
    prev = z;
  }
  ASSERT_GE(troughs.size(), 3u);
  const double measured = (troughs[2] - troughs[0]) / 2;
  RecordProperty("period_s", std::to_string(measured));
  RecordProperty("closed_form_period_s", std::to_string(period));
  EXPECT_NEAR(measured, period, 0.05 * period);
  // Lightly damped: the first swing goes well past the rest sink (closed form 1.80 x).
  RecordProperty("first_swing_over_sink", std::to_string((rest - deepest) / sink));
  EXPECT_GT(rest - deepest, 1.5 * sink);  // implicit Euler damps it a little: 1.64 at 1 ms
  EXPECT_LT(rest - deepest, 2.0 * sink);
  sim->run_for(3.0);
  EXPECT_NEAR(rest - sim->robot(0).torso_pose().z, sink, 0.01 * sink);
}

// The same spring per body: a 2 kg block sinks m g / k whether the collider holds it on the
// ground's 4 corner points or on a box's, and a per-point spring on 4 points sinks a quarter.
double block_sink(const std::string& spring_per, bool on_box) {
  const std::string xml = std::string(R"(<scene><physics solver="exact" contact_stiffness="2e4"
      contact_damping="200" contact_spring_per=")") +
                          spring_per + R"("/>)" +
                          (on_box ? R"(<ground enabled="false"/>
      <box name="table" size="0.5 0.5 0.1" xyz="0 0 -0.05"/>)"
                                  : "") +
                          R"(<robot name="b" urdf="block.urdf" xyz="0 0 0.0195"/></scene>)";
  auto sim = test::scene_from_text(xml);
  sim->run_for(2.0);
  return 0.0195 - sim->robot(0).torso_pose().z;  // half height less the surface layer
}

TEST(ClosedFormOdeContact, ContactSpringPerBodyIsTheBodysWholeSpring) {
  const double sink = 2 * kG / 2e4;
  EXPECT_NEAR(block_sink("body", false), sink, 0.02 * sink);
  EXPECT_NEAR(block_sink("body", true), sink, 0.02 * sink);
  EXPECT_NEAR(block_sink("point", false), sink / 4, 0.02 * sink / 4);
}

}  // namespace
}  // namespace stride
