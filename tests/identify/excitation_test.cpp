// The excitation motions (scenes/robots/nao/identify/): bounded in joint range and commanded
// speed, ending in the base posture, and the simulated scenes run the robot configs unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "behaviours/identify/excitation.hpp"
#include "console/session/sim_session.hpp"
#include "robot/app/robot_config.hpp"
#include "robot/framework/module_registry.hpp"
#include "robot/nao/joint_limits.hpp"
#include "simulator/scene/scene_parser.hpp"

namespace stride {
namespace {

using behaviours::ExcitationMotion;
using behaviours::ExcitationParameters;

const char* const kMotions[] = {"held_chirp", "held_steps", "squat", "weight_shift", "walk"};

TEST(Excitation, SceneRunsTheRobotConfigsController) {
  for (const char* m : kMotions) {
    const std::string name(m);
    const RobotConfig c =
        parse_robot_config_file(STRIDE_SOURCE_DIR "/scenes/robots/nao/identify/" + name + ".xml");
    const sim::SceneDescription s =
        sim::parse_scene_file(STRIDE_SOURCE_DIR "/scenes/identify/" + name + ".xml");
    EXPECT_EQ(c.controller, s.robots[0].controller) << name;
    EXPECT_EQ(s.robots[0].period, c.period) << name;
    EXPECT_EQ(s.robots[0].fixed_base, name.starts_with("held")) << name;
  }
}

TEST(Excitation, TargetsStayInsideTheLimitsAndEndInTheBase) {
  const auto base = behaviours::excitation_base();
  for (auto motion : {ExcitationMotion::chirp, ExcitationMotion::steps, ExcitationMotion::squat,
                      ExcitationMotion::weight_shift}) {
    ExcitationParameters p;
    p.motion = motion;
    p.amplitude = 0.4;  // the largest allowed: the clamp must hold it within the limits
    double moved = 0;
    for (double t = -1; t <= p.duration + 1; t += 0.004) {
      const auto q = behaviours::excitation_targets(p, t);
      for (int i = 0; i < hal::kNumJoints; ++i) {
        const bool leg = std::ranges::count(behaviours::kExcitedLegJoints, i) > 0;
        if (!leg) EXPECT_EQ(q[i], base[i]);
        if (!leg) continue;
        EXPECT_GE(q[i], nao::kJointLimits[i].lower + behaviours::kExcitationLimitMargin - 1e-12);
        EXPECT_LE(q[i], nao::kJointLimits[i].upper - behaviours::kExcitationLimitMargin + 1e-12);
        moved = std::max(moved, std::abs(q[i] - base[i]));
      }
    }
    EXPECT_GT(moved, 0.05) << static_cast<int>(motion);  // it does move something
    const auto end = behaviours::excitation_targets(p, p.duration);
    for (int i = 0; i < hal::kNumJoints; ++i) EXPECT_EQ(end[i], base[i]);
  }
}

TEST(Excitation, ChirpSpeedStaysWithinTheBoundBeforeTheRateLimit) {
  ExcitationParameters p;  // chirp; its amplitude shrinks with frequency to keep 2 pi f A
  const double dt = 1e-4;
  double fastest = 0;
  for (double t = 0; t < p.duration; t += dt) {
    const auto a = behaviours::excitation_targets(p, t);
    const auto b = behaviours::excitation_targets(p, t + dt);
    for (int i : behaviours::kExcitedLegJoints)
      fastest = std::max(fastest, std::abs(b[i] - a[i]) / dt);
  }
  // The envelope's own slope adds at most amplitude * pi / (2 ramp) to the bound.
  EXPECT_LE(fastest, p.max_speed + p.amplitude * M_PI / (2 * p.ramp));
  EXPECT_GT(fastest, 0.5 * p.max_speed);
}

TEST(Excitation, RateLimitMovesAtMostMaxSpeedPerFrame) {
  behaviours::JointTargets q{}, target{};
  target.fill(1.0);
  behaviours::limit_rate(q, target, 0.5, 0.012);
  for (double v : q) EXPECT_DOUBLE_EQ(v, 0.006);
}

// Each simulated motion runs to its end: commands within the bound at every frame, no fall, and
// the standing motions keep the robot upright; the last command is the base posture.
TEST(Excitation, SimulatedMotionsAreSafe) {
  const auto base = behaviours::excitation_base();
  for (const char* m : {"held_steps", "weight_shift", "squat"}) {
    const std::string path = STRIDE_SOURCE_DIR "/scenes/identify/" + std::string(m) + ".xml";
    const sim::SceneDescription scene = sim::parse_scene_file(path);
    const double speed =
        std::stod(scene.robots[0].controller.parameters.at("Excitation.max_speed"));
    console::SimSession session(path);
    auto& robot = session.simulation().robot(0);
    const double period = robot.period();
    hal::ActuatorFrame last{};
    double fastest = 0;
    int frames = 0;
    session.set_frame_observer(0, [&](sim::SimulatedRobot& r) {
      const auto& c = r.latest_commands();
      for (int i = 0; i < hal::kNumJoints; ++i)
        if (frames > 0)
          fastest = std::max(fastest, std::abs(c.position[i] - last.position[i]) / period);
      last = c;
      ++frames;
    });
    session.simulation().run_for(18.0);
    EXPECT_GT(frames, 1000) << m;
    EXPECT_LE(fastest, speed * (1 + 1e-9)) << m;
    EXPECT_GT(fastest, 0.1 * speed) << m;
    EXPECT_FALSE(robot.fallen()) << m;
    for (int i : behaviours::kExcitedLegJoints) EXPECT_NEAR(last.position[i], base[i], 1e-9) << m;
  }
}

}  // namespace
}  // namespace stride
