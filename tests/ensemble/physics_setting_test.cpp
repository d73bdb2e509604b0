// Solver settings set over a scene's <physics>: the other attributes stay, a spring replaces
// erp/cfm, and a bad setting is one error naming the setting and the attribute.
#include <string>

#include <gtest/gtest.h>

#include "robot/core/error.hpp"
#include "simulator/scene/contact_softness.hpp"
#include "simulator/scene/scene_parser.hpp"

namespace stride::sim {
namespace {

std::string scene(const std::string& rel) {
  return std::string(STRIDE_SOURCE_DIR) + "/" + rel;
}

TEST(PhysicsSetting, SetsOnlyTheNamedAttributes) {
  // The walk states its converged setting: the exact solver at 1 ms under the default law.
  const auto as_written = parse_scene_file(scene("scenes/walking/open_loop_medium.xml"));
  EXPECT_EQ(as_written.physics.solver, PhysicsSettings::Solver::Exact);
  EXPECT_DOUBLE_EQ(as_written.physics.sor, 1.3);
  ASSERT_TRUE(as_written.physics.contact_law);
  const auto s = parse_scene_file(scene("scenes/walking/open_loop_medium.xml"),
                                  parse_physics_setting("solver=iterative,iterations=40,sor=1.0"));
  EXPECT_EQ(s.physics.iterations, 40);
  EXPECT_DOUBLE_EQ(s.physics.sor, 1.0);
  EXPECT_DOUBLE_EQ(s.physics.step, 0.001);
  EXPECT_EQ(s.physics.solver, PhysicsSettings::Solver::Iterative);
  ASSERT_TRUE(s.physics.contact_law);  // the setting leaves the scene's law
  EXPECT_DOUBLE_EQ(s.physics.contact_law->stiffness, 1e5);
  const auto exact = parse_scene_file(scene("scenes/walking/open_loop_medium.xml"),
                                      parse_physics_setting("solver=exact,step=0.5ms"));
  EXPECT_EQ(exact.physics.solver, PhysicsSettings::Solver::Exact);
  EXPECT_DOUBLE_EQ(exact.physics.step, 0.0005);
  EXPECT_EQ(exact.robots.size(), 1u);
}

TEST(PhysicsSetting, IterationsNameTheIterativeSolverOverAnExactScene) {
  EXPECT_EQ(parse_physics_setting("iterations=40,sor=1.0"),
            (PhysicsAttributes{{"solver", "iterative"}, {"iterations", "40"}, {"sor", "1.0"}}));
  EXPECT_EQ(parse_physics_setting("sor=1.0"),
            (PhysicsAttributes{{"solver", "iterative"}, {"sor", "1.0"}}));
  EXPECT_EQ(parse_physics_setting("solver=exact,iterations=5"),
            (PhysicsAttributes{{"solver", "exact"}, {"iterations", "5"}}));
  EXPECT_EQ(parse_physics_setting("step=0.5ms"), (PhysicsAttributes{{"step", "0.5ms"}}));
  const auto s = parse_scene_file(scene("scenes/walking/open_loop_medium.xml"),
                                  parse_physics_setting("iterations=10"));
  EXPECT_EQ(s.physics.solver, PhysicsSettings::Solver::Iterative);
  EXPECT_EQ(s.physics.iterations, 10);
}

TEST(PhysicsSetting, AStepChangeRecomputesTheScenesContactSpring) {
  // soft_sole_exact states contact_stiffness / contact_damping: their ERP/CFM depend on the step.
  const std::string path = scene("scenes/experiments/soft_sole_exact/hip_medium.xml");
  const auto half = parse_scene_file(path, parse_physics_setting("step=0.5ms"));
  const ContactSoftness expected = contact_softness(4e4, 10, 0.0005);
  EXPECT_DOUBLE_EQ(half.physics.contact_erp, expected.erp);
  EXPECT_DOUBLE_EQ(half.physics.contact_cfm, expected.cfm);
  const auto soft =
      parse_scene_file(path, parse_physics_setting("contact_erp=0.3,contact_cfm=1e-4"));
  EXPECT_DOUBLE_EQ(soft.physics.contact_erp, 0.3);  // the scene's spring gave way
  EXPECT_DOUBLE_EQ(soft.physics.contact_cfm, 1e-4);
}

TEST(PhysicsSetting, AppliesToASceneWithoutPhysics) {
  const auto s =
      parse_scene_file(scene("scenes/nao_stand.xml"), parse_physics_setting("iterations=33"));
  EXPECT_EQ(s.physics.iterations, 33);
}

std::string error_of(const std::string& setting) {
  try {
    parse_physics_setting(setting);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(PhysicsSetting, BadSettingsNameTheSettingAndAttribute) {
  EXPECT_NE(error_of("iterations=0").find("physics setting 'iterations=0'"), std::string::npos);
  EXPECT_NE(error_of("iterations=0").find("'iterations'"), std::string::npos);
  EXPECT_NE(error_of("sor=2.5").find("expected a value in (0, 2)"), std::string::npos);
  EXPECT_NE(error_of("colour=red").find("'colour'"), std::string::npos);
  EXPECT_NE(error_of("iterations").find("expected attribute=value"), std::string::npos);
  EXPECT_NE(error_of("step=\"1\"").find("not a <physics> attribute and value"), std::string::npos);
  EXPECT_NE(error_of("").find("expected attribute=value"), std::string::npos);
}

}  // namespace
}  // namespace stride::sim
