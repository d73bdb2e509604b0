// The scene's <contact> law against closed-form mechanics, on every engine built in and both
// friction cones, within 1 %:
// a box resting on the compliant floor sinks m g / k, a sliding block decelerates at mu g, a block
// on a ramp holds below atan mu and slides above it at g (sin - mu cos), and a box driven onto the
// floor leaves it as the damped spring that cannot pull lets it go.
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "robot/core/error.hpp"
#include "tests/simulator/sim_test_util.hpp"

namespace stride {
namespace {

constexpr double kG = 9.81;
constexpr double kBlockMass = 2, kBlockHalfHeight = 0.02;  // tests/data/block.urdf

// The scene on an engine, its <contact> law on a cone.
std::string law_scene(const std::string& xml, const std::string& engine, const std::string& cone) {
  std::string s = test::on_engine(xml, engine);
  const auto at = s.find("<contact ");
  return s.substr(0, at + 9) + "cone=\"" + cone + "\" " + s.substr(at + 9);
}

class ContactLaw : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {
 protected:
  const std::string& engine() const { return std::get<0>(GetParam()); }
  const std::string& cone() const { return std::get<1>(GetParam()); }
  std::unique_ptr<sim::Simulation> scene(const std::string& xml) const {
    return test::scene_from_text(law_scene(xml, engine(), cone()));
  }
  // Converged on both engines: ODE's exact solver, MuJoCo's Newton.
  static std::string physics(const std::string& extra = "") {
    return "<physics solver=\"exact\" " + extra + "/>";
  }
};

// A body's spring, split over however many points hold it: the same sink on the ground's four
// corner points as on a box's.
TEST_P(ContactLaw, BoxRestingOnTheFloorSinksMgOverK) {
  const double k = 2e4, sink = kBlockMass * kG / k;
  for (const bool on_box : {false, true}) {
    auto sim = scene("<scene>" + physics() + R"(<contact stiffness="2e4" damping="400"/>)" +
                     (on_box ? R"(<ground enabled="false"/>
      <box name="table" size="0.5 0.5 0.1" xyz="0 0 -0.05"/>)"
                             : "") +
                     R"(<robot name="b" urdf="block.urdf" xyz="0 0 0.02"/></scene>)");
    sim->run_for(2.0);
    const double measured = kBlockHalfHeight - sim->robot(0).torso_pose().z;
    RecordProperty(on_box ? "sink_on_box_m" : "sink_on_ground_m", std::to_string(measured));
    EXPECT_NEAR(measured, sink, 0.01 * sink) << (on_box ? "on a box" : "on the ground");
  }
}

// A per-point law puts the whole spring at each of the four corners: a quarter of the sink.
TEST_P(ContactLaw, PerPointSpringIsEachPointsSpring) {
  auto sim = scene("<scene>" + physics() + R"(<contact stiffness="2e4" damping="400" per="point"/>
    <robot name="b" urdf="block.urdf" xyz="0 0 0.02"/></scene>)");
  sim->run_for(2.0);
  const double sink = kBlockMass * kG / 2e4 / 4;
  EXPECT_NEAR(kBlockHalfHeight - sim->robot(0).torso_pose().z, sink, 0.01 * sink);
}

double forward_speed(const sim::Simulation& s) {
  return s.robot(0).body().link_com_velocity(0).x();
}

// Pushed along x for 0.1 s, then left to slide: v falls at mu g until it stops.
TEST_P(ContactLaw, SlidingBlockDeceleratesAtMuG) {
  const double mu = 0.5;
  auto sim =
      scene("<scene>" + physics() + R"(<contact stiffness="1e5" damping="1000" friction="0.5"/>
    <robot name="b" urdf="block.urdf" xyz="0 0 0.0198"/>
    <push robot="b" body="block" force="60 0 0" start="0.3" duration="0.1"/></scene>)");
  sim->run_for(0.5);
  const double v1 = forward_speed(*sim);
  sim->run_for(0.3);
  const double v2 = forward_speed(*sim);
  ASSERT_GT(v2, 0.1) << "still sliding at the end of the measurement";
  const double decel = (v1 - v2) / 0.3;
  RecordProperty("deceleration", std::to_string(decel));
  EXPECT_NEAR(decel, mu * kG, 0.01 * mu * kG);
  EXPECT_NEAR(sim->robot(0).body().link_com_velocity(0).y(), 0, 1e-6);  // straight on
}

#ifdef STRIDE_HAVE_MUJOCO
// MuJoCo's friction rows sit in its friction block, which every one of its solvers solves: the
// conjugate gradient and PGS (the speed settings) decelerate the sliding block at mu g too.
TEST(ContactLawMujoco, EverySolverRealisesTheSlidingFriction) {
  for (const std::string solver : {"solver=\"cg\"", "solver=\"iterative\" iterations=\"50\""}) {
    auto sim = test::scene_from_text("<scene><physics engine=\"mujoco\" " + solver +
                                     R"(/><contact stiffness="1e5" damping="1000" friction="0.5"/>
      <robot name="b" urdf="block.urdf" xyz="0 0 0.0198"/>
      <push robot="b" body="block" force="60 0 0" start="0.3" duration="0.1"/></scene>)");
    sim->run_for(0.5);
    const double v1 = forward_speed(*sim);
    sim->run_for(0.3);
    EXPECT_NEAR((v1 - forward_speed(*sim)) / 0.3, 0.5 * kG, 0.01 * 0.5 * kG) << solver;
  }
}
#endif

struct RampRun {
  double accel = 0;     // along the slope, downward, over the measured second
  double distance = 0;  // travelled down the slope in it
};

// A block set on a 10 degree ramp whose law friction is `mu`, settled for 0.2 s, then watched 1 s.
RampRun on_ramp(const std::string& engine, const std::string& cone, double mu) {
  const std::string xml = R"(<scene><physics solver="exact"/><ground enabled="false"/>
    <contact stiffness="1e5" damping="1000" friction=")" +
                          std::to_string(mu) + R"("/>
    <ramp name="r" xyz="-1 0 0" length="3" width="1" slope="10deg"/>
    <robot name="b" urdf="block.urdf" xyz="-0.0035 0 0.202" rpy="0 -10deg 0"/></scene>)";
  auto sim = test::scene_from_text(law_scene(xml, engine, cone));
  const auto speed = [&] {
    const Eigen::Vector3d v = sim->robot(0).body().link_com_velocity(0);
    return std::hypot(v.x(), v.z()) * (v.z() < 0 ? 1 : -1);
  };
  sim->run_for(0.2);
  const auto p0 = sim->robot(0).torso_pose();
  const double v0 = speed();
  sim->run_for(1.0);
  const auto p1 = sim->robot(0).torso_pose();
  RampRun r;
  r.accel = speed() - v0;
  r.distance = std::hypot(p1.x - p0.x, p1.z - p0.z) * (p1.z < p0.z ? 1 : -1);
  return r;
}

TEST_P(ContactLaw, RampHoldsBelowAtanMuAndSlidesAbove) {
  const double slope = 10 * std::numbers::pi / 180, tan_slope = std::tan(slope);
  const RampRun holds = on_ramp(engine(), cone(), 1.05 * tan_slope);
  RecordProperty("creep_at_1.05_tan_m", std::to_string(holds.distance));
  EXPECT_LT(std::abs(holds.distance), 1e-4) << "static friction holds the block";
  const RampRun barely = on_ramp(engine(), cone(), 0.9 * tan_slope);
  const double a_barely = kG * (std::sin(slope) - 0.9 * tan_slope * std::cos(slope));
  EXPECT_NEAR(barely.accel, a_barely, 0.01 * a_barely);
  const RampRun slides = on_ramp(engine(), cone(), 0.5 * tan_slope);
  const double a = kG * (std::sin(slope) - 0.5 * tan_slope * std::cos(slope));
  RecordProperty("accel_at_half_tan", std::to_string(slides.accel));
  EXPECT_NEAR(slides.accel, a, 0.01 * a);
}

// The damped spring that cannot pull: m x'' = -k x - c x' from x = 0, x' = v0 until the force
// k x + c x' reaches zero, where the box leaves at x'(t_end) (without gravity, at that speed).
struct Bounce {
  double duration, restitution;
};
Bounce closed_form_bounce(double k, double c, double m) {
  const double s = c / (2 * m), wd = std::sqrt(k / m - s * s);
  const double t = (std::numbers::pi - std::atan(c * wd / (k - c * s))) / wd;
  const double v = std::exp(-s * t) * (std::cos(wd * t) - s / wd * std::sin(wd * t));
  return {t, -v};
}

// Without gravity a box is pushed down onto the floor (0.5 m/s) and bounces off: its contact lasts
// and its rebound speed is the closed form's. A fine step (20 us) keeps the discretisation's own
// damping under 0.3 %.
TEST_P(ContactLaw, DroppedBoxBouncesAsTheDampedSpring) {
  const double k = 2e4, m = kBlockMass, zeta = 0.2, c = 2 * zeta * std::sqrt(k * m);
  auto sim = scene(R"(<scene><physics solver="exact" step="0.02ms" gravity="0 0 0"/>
    <contact stiffness="2e4" damping=")" +
                   std::to_string(c) + R"("/>
    <robot name="b" urdf="block.urdf" xyz="0 0 0.04"/>
    <push robot="b" body="block" force="0 0 -50" start="0" duration="0.02"/></scene>)");
  const auto vz = [&] { return sim->robot(0).body().link_com_velocity(0).z(); };
  sim->run_for(0.021);
  const double v_in = vz();
  double first = -1, last = -1, prev = v_in;
  while (sim->time() < 0.15) {
    sim->step();
    if (std::abs(vz() - prev) > 1e-9) {  // a contact force acts this step
      if (first < 0) first = sim->time() - sim->scene().physics.step;
      last = sim->time();
    }
    prev = vz();
  }
  ASSERT_GT(first, 0);
  const Bounce expected = closed_form_bounce(k, c, m);
  const double restitution = vz() / -v_in;
  RecordProperty("contact_duration_s", std::to_string(last - first));
  RecordProperty("closed_form_duration_s", std::to_string(expected.duration));
  RecordProperty("restitution", std::to_string(restitution));
  RecordProperty("closed_form_restitution", std::to_string(expected.restitution));
  // The textbook exp(-zeta pi / sqrt(1 - zeta^2)) lets the spring pull until x = 0: 0.526 here.
  RecordProperty("restitution_if_it_could_pull",
                 std::to_string(std::exp(-zeta * std::numbers::pi / std::sqrt(1 - zeta * zeta))));
  EXPECT_NEAR(v_in, -0.5, 1e-6);
  EXPECT_NEAR(last - first, expected.duration, 0.01 * expected.duration);
  EXPECT_NEAR(restitution, expected.restitution, 0.01 * expected.restitution);
}

// What the law states reaches the scene; what conflicts with it is one line at file:line.
std::string load_error(const std::string& xml) {
  try {
    sim::parse_scene_text(xml, "law.xml");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(ContactLawScene, SurfacesWithoutTheirOwnFrictionTakeTheLaws) {
  const sim::SceneDescription s = sim::parse_scene_text(R"(<scene>
    <contact friction="0.5"/><box name="a" size="1 1 1"/><box name="b" size="1 1 1" friction="0.3"/>
    <uneven size="1 1"/></scene>)",
                                                        "law.xml");
  ASSERT_TRUE(s.physics.contact_law.has_value());
  const sim::ContactLaw& law = *s.physics.contact_law;
  EXPECT_DOUBLE_EQ(law.stiffness, 1e5);  // the defaults
  EXPECT_DOUBLE_EQ(law.damping, 1000);
  EXPECT_TRUE(law.per_body);
  EXPECT_EQ(law.cone, sim::ContactLaw::Cone::Elliptic);
  EXPECT_EQ(law.line, 2);
  EXPECT_DOUBLE_EQ(s.ground.friction, 0.5);
  EXPECT_DOUBLE_EQ(s.boxes[0].friction, 0.5);
  EXPECT_DOUBLE_EQ(s.boxes[1].friction, 0.3);
  EXPECT_DOUBLE_EQ(s.uneven[0].friction, 0.5);
  EXPECT_DOUBLE_EQ(sim::parse_scene_text("<scene/>", "x.xml").ground.friction, 0.8);  // no law
}

TEST(ContactLawScene, ConflictsAndBadValuesAreOneLineAtTheirPlace) {
  EXPECT_EQ(load_error("<scene>\n<physics contact_stiffness=\"2e4\" contact_damping=\"10\"/>\n"
                       "<contact/></scene>"),
            "law.xml:2: <physics>: attribute 'contact_stiffness': replaced by the <contact> law at "
            "law.xml:3 (expected the contact stated once, there)");
  EXPECT_EQ(load_error("<scene><contact/>\n<contact/></scene>"),
            "law.xml:2: <contact>: given twice (first at law.xml:1; expected one per scene)");
  EXPECT_EQ(load_error("<scene><contact stiffness=\"0\"/></scene>"),
            "law.xml:1: <contact>: attribute 'stiffness': expected a stiffness > 0 (N/m)");
  EXPECT_NE(load_error("<scene><contact cone=\"box\"/></scene>")
                .find("law.xml:1: <contact>: "
                      "attribute 'cone'"),
            std::string::npos);
  EXPECT_NE(load_error("<scene><contact per=\"foot\"/></scene>").find("attribute 'per'"),
            std::string::npos);
#ifdef STRIDE_HAVE_MUJOCO
  EXPECT_EQ(load_error("<scene><physics engine=\"mujoco\" noslip_iterations=\"10\"/>\n"
                       "<contact cone=\"pyramid\"/></scene>"),
            "law.xml:1: <physics>: attribute 'noslip_iterations': replaced by the <contact> law "
            "at law.xml:2 (expected the contact stated once, there)");
#endif
}

INSTANTIATE_TEST_SUITE_P(
    EnginesAndCones, ContactLaw,
    ::testing::Combine(::testing::ValuesIn(test::engines()),
                       ::testing::Values(std::string("elliptic"), std::string("pyramid"))),
    [](const auto& info) { return std::get<0>(info.param) + "_" + std::get<1>(info.param); });

}  // namespace
}  // namespace stride
