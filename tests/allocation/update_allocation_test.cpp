// No shipped module allocates in update() once running (a robot's control loop must not stall in
// the allocator or throw std::bad_alloc; an opened file would show as its buffer's allocation):
// every allocation during Runtime::step() is counted while each registered module runs in a
// scene where it has work to do, providers swapped in as `mr` does. One test checks that the
// cases together run every module of the registry, so a new module must get a case here. This
// test binary replaces the allocator's entry points for that, so it is kept apart from the others.
#include <algorithm>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>

#include "console/session/sim_session.hpp"
#include "robot/app/robot_config.hpp"
#include "simulator/scene/scene_parser.hpp"
#include "tests/allocation/allocation_counter.hpp"
#include "tests/simulator/frame_hook.hpp"

namespace stride {
namespace {

using allocation_counter::allocations;
using allocation_counter::counting;

// A scene (from the source tree) whose robot runs the modules to check.
struct Case {
  std::string name;
  std::string scene;
  std::string config;  // a robot config whose <controller> replaces the scene's ("": the scene's)
  std::vector<std::pair<std::string, std::string>> swaps;  // representation -> module, as `mr`
  double warm_up = 0.1;  // s of first frames not counted (a module may size buffers on its first)
  double seconds = 1.0;  // s simulated in all
  double push_x = 0;     // N on the scene's first push, when the scene has one
  double push_at = 0;    // s: when that push starts (0: the scene's time)
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.name;
}

std::string cat(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : " ") + n;
  return s;
}

std::vector<Case> cases() {
  const std::string hip = "scenes/experiments/hip_medium.xml";
  const std::string push = "scenes/experiments/push_stand.xml";
  const std::string landing = "scenes/landing/landing_nao.xml";
  const std::string recovery = "scenes/experiments/push_recovery_walk.xml";
  // Walks run past the pattern's start at 2 s; the standing pushes past the push at 1.5 s.
  return {
      {"HipWalkRobotConfig", hip, "scenes/robots/nao/config/hip_walk.xml", {}, 0.1, 4.0},
      {"AnkleStrategyWalk", hip, "", {{"PostureCorrectedRequest", "AnkleStrategy"}}, 0.1, 3.0},
      {"UncontrolledWalk", hip, "", {{"PostureCorrectedRequest", "NoPostureControl"}}, 0.1, 3.0},
      {"ConventionalWalk", "scenes/experiments/energy_conventional_10.xml", "", {}, 0.1, 3.0},
      {"StandRobotConfig",
       "scenes/nao_stand_controlled.xml",
       "scenes/robots/nao/config/stand.xml",
       {},
       0.1,
       1.0},
      {"AnkleBalancePushed", push, "", {}, 0.1, 2.0, 20},
      {"HipBalancePushed", push, "", {{"JointRequest", "HipBalance"}}, 0.1, 2.0, 20},
      {"CombinedBalancePushed", push, "", {{"JointRequest", "CombinedBalance"}}, 0.1, 2.0, 20},
      {"LqrBalancePushed", push, "", {{"JointRequest", "LqrBalance"}}, 0.1, 2.0, 20},
      {"SwingLegTracking", "scenes/swing_leg/hanging_nao.xml", "", {}, 0.05, 0.5},
      {"LandingImpedance", landing, "", {}, 0.05, 0.5},
      {"LandingPosition", landing, "", {{"JointRequest", "LandingPosition"}}, 0.05, 0.5},
      {"LandingControlWalk", hip, "", {{"JointRequest", "LandingControl"}}, 0.1, 3.5},
      {"PositionBalancePushed", push, "", {{"JointRequest", "PositionBalance"}}, 0.1, 2.5, 25},
      // A push from behind 1.2 s into the walk that takes a recovery step.
      {"PushRecoveryWalkPushed", recovery, "", {}, 0.1, 4.0, 35, 3.2},
      // Walk requests: starting, forward, sideways, turning (its schedule's first 12 s).
      {"RequestWalkSteered", "scenes/walking/requests/steer.xml", "", {}, 0.1, 12.0},
      // The held chirp past the move to its base posture (1.5 s) into the excitation.
      {"ExcitationRobotConfig",
       "scenes/identify/held_chirp.xml",
       "scenes/robots/nao/identify/held_chirp.xml",
       {},
       0.1,
       3.0},
  };
}

sim::SceneDescription scene_of(const Case& c) {
  sim::SceneDescription scene = sim::parse_scene_file(STRIDE_SOURCE_DIR "/" + c.scene);
  if (!c.config.empty()) {
    // As `stride robot` runs that config: its controller at LoLA's period.
    scene.robots[0].controller =
        parse_robot_config_file(STRIDE_SOURCE_DIR "/" + c.config).controller;
    scene.robots[0].period = 0.012;
  }
  if (c.push_x != 0 && !scene.pushes.empty()) scene.pushes[0].force = {c.push_x, 0, 0};
  if (c.push_at > 0 && !scene.pushes.empty()) scene.pushes[0].start = c.push_at;
  return scene;
}

Runtime& runtime_with_swaps(console::SimSession& session, const Case& c) {
  Runtime* rt = session.runtime(0);
  for (const auto& [representation, module] : c.swaps) rt->swap_provider(representation, module);
  return *rt;
}

// Runs the case, counting allocations in step() after its warm-up.
long allocations_while_running(const Case& c) {
  console::SimSession session(scene_of(c));
  auto& sim = session.simulation();
  runtime_with_swaps(session, c);
  PacedRuntime& rt = *session.paced_runtime(0);
  test::FrameHook hook([&](const hal::SensorFrame& sensors, hal::ActuatorFrame& commands) {
    counting = sim.time() > c.warm_up;
    const bool written = rt.step(sensors, commands);
    counting = false;
    return written;
  });
  sim.set_controller(0, &hook);
  allocations = 0;
  sim.run_for(c.seconds);
  sim.set_controller(0, nullptr);
  return allocations;
}

class UpdateAllocation : public ::testing::TestWithParam<Case> {};

TEST_P(UpdateAllocation, ItsModulesAllocateNothingPerFrame) {
  const Case& c = GetParam();
  console::SimSession session(scene_of(c));
  const std::string modules = cat(runtime_with_swaps(session, c).module_order());
  EXPECT_EQ(allocations_while_running(c), 0) << c.name << " runs " << modules;
}

INSTANTIATE_TEST_SUITE_P(EveryShippedModule, UpdateAllocation, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

TEST(UpdateAllocationCoverage, TheCasesRunEveryRegisteredModule) {
  std::set<std::string> covered;
  std::vector<std::string> registered;
  for (const Case& c : cases()) {
    console::SimSession session(scene_of(c));
    const auto& order = runtime_with_swaps(session, c).module_order();
    covered.insert(order.begin(), order.end());
    registered = session.registry().names();
  }
  std::vector<std::string> missing;
  std::set_difference(registered.begin(), registered.end(), covered.begin(), covered.end(),
                      std::back_inserter(missing));
  EXPECT_EQ(missing, std::vector<std::string>{}) << "registered modules no case runs";
  EXPECT_EQ(std::vector<std::string>(covered.begin(), covered.end()), registered);
}

TEST(UpdateAllocationCoverage, TheCounterSeesOperatorNewAndMalloc) {
  allocations = 0;
  counting = true;
  void* p = ::operator new(16);  // a call, which unlike a new-expression is never elided
  counting = false;
  ::operator delete(p);
  EXPECT_EQ(allocations, 1);

  allocations = 0;
  counting = true;
  Eigen::VectorXd v = Eigen::VectorXd::Constant(64, 1.0);  // Eigen's heap goes through malloc
  counting = false;
  EXPECT_EQ(allocations, 1);
  EXPECT_EQ(v.sum(), 64.0);
}

}  // namespace
}  // namespace stride
