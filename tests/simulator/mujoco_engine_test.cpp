// The MuJoCo engine (<physics engine="mujoco">) beyond the tests every engine runs (closed-form
// physics, standing, determinism): a push, and a one-line error at file:line for what it does not
// take, or for the engine itself in a build without MuJoCo.
#include <gtest/gtest.h>

#include "robot/core/error.hpp"
#include "tests/simulator/sim_test_util.hpp"

namespace stride {
namespace {

#ifdef STRIDE_HAVE_MUJOCO

// A push is a force at the link for its duration: on a free block the velocity gains the impulse
// over the mass, to rounding, while gravity adds g t downward.
TEST(MujocoEngine, PushGivesAFreeBlockTheImpulseOverItsMass) {
  auto sim = test::scene_from_text(R"(<scene><physics engine="mujoco"/>
    <robot name="b" urdf="block.urdf" xyz="0 0 0.5"/><ground enabled="false"/>
    <push robot="b" body="block" force="10 0 0" start="0" duration="0.1"/></scene>)");
  const double mass = sim->robot(0).model().total_mass();
  sim->run_for(0.1);
  const Eigen::Vector3d v = sim->robot(0).body().centre_of_mass_velocity();
  EXPECT_NEAR(v.x(), 10 * 0.1 / mass, 1e-9);  // free flight: the impulse over the mass
  EXPECT_NEAR(v.z(), -9.81 * 0.1, 1e-9);
}

TEST(MujocoEngine, OdeOnlySettingIsAnErrorAtItsLine) {
  try {
    test::scene_from_text("<scene>\n<physics engine=\"mujoco\" contact_erp=\"0.3\"/></scene>");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("inline.xml:2"), std::string::npos) << what;
    EXPECT_NE(what.find("contact_erp"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

#else

TEST(MujocoEngine, WithoutMujocoTheEngineIsAnErrorAtItsLine) {
  try {
    test::scene_from_text("<scene>\n<physics engine=\"mujoco\"/></scene>");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("inline.xml:2"), std::string::npos) << e.what();
  }
}

#endif

}  // namespace
}  // namespace stride
