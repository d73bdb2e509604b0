// `stride sweep|experiment --physics a=v,b=w`: a study run at another solver setting or on the
// other engine (issue 33's study settings) without editing its scenes. The option becomes
// scene:physics@ settings, checked as a scene's own attributes are.
#include <string>

#include <gtest/gtest.h>

#include "console/sweep/scene_edit.hpp"
#include "console/sweep/sweep_request.hpp"
#include "robot/core/error.hpp"

namespace stride::sweep {
namespace {

const std::string kScenes = std::string(STRIDE_SOURCE_DIR) + "/scenes/experiments/";

TEST(PhysicsOption, BecomesSceneSettingsOverThePhysicsElement) {
  const auto s = physics_settings("solver=exact,step=0.5ms");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].target, "scene:physics@solver");
  EXPECT_EQ(s[0].value, "exact");
  EXPECT_EQ(s[1].target, "scene:physics@step");
  EXPECT_EQ(s[1].value, "0.5ms");
}

TEST(PhysicsOption, SetsTheSolverOfAWalkingScene) {
  // hip_medium states the exact solver at 1 ms; the option replaces the solver and the step.
  const auto plain = load_edited_scene(kScenes + "hip_medium.xml", {});
  EXPECT_EQ(plain.physics.solver, sim::PhysicsSettings::Solver::Exact);
  EXPECT_DOUBLE_EQ(plain.physics.step, 0.001);
  const auto iterative = load_edited_scene(kScenes + "hip_medium.xml",
                                           physics_settings("solver=iterative,step=0.5ms"));
  EXPECT_EQ(iterative.physics.solver, sim::PhysicsSettings::Solver::Iterative);
  EXPECT_DOUBLE_EQ(iterative.physics.step, 0.0005);
}

TEST(PhysicsOption, BadSettingIsOneLineError) {
  for (const char* bad : {"solver=fast", "iterations", "colour=red", ""}) {
    SCOPED_TRACE(bad);
    try {
      physics_settings(bad);
      ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("--physics: ", 0), 0u) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
}

#ifdef STRIDE_HAVE_MUJOCO
TEST(PhysicsOption, SelectsMujocoAndRejectsOdeContactsAtFileLine) {
  const auto mj =
      load_edited_scene(kScenes + "hip_medium.xml", physics_settings("engine=mujoco,solver=exact"));
  EXPECT_EQ(mj.physics.engine, sim::PhysicsSettings::Engine::Mujoco);
  EXPECT_EQ(mj.physics.solver, sim::PhysicsSettings::Solver::Exact);
  // soft_sole_exact states ODE contact springs, which MuJoCo's contact model cannot take.
  try {
    load_edited_scene(kScenes + "soft_sole_exact/hip_medium.xml",
                      physics_settings("engine=mujoco"));
    ADD_FAILURE() << "accepted ODE contact springs on MuJoCo";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("soft_sole_exact/hip_medium.xml:"), std::string::npos) << what;
    EXPECT_NE(what.find("contact_stiffness"), std::string::npos) << what;
  }
}
#endif

}  // namespace
}  // namespace stride::sweep
