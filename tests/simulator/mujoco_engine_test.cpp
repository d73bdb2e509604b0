// The MuJoCo engine (<physics engine="mujoco">) beyond the tests every engine runs (closed-form
// physics, standing, determinism): a push, and a one-line error at file:line for what it does not
// take, or for the engine itself in a build without MuJoCo.
#include <gtest/gtest.h>

#include "robot/core/error.hpp"
#include "robot/model/urdf_loader.hpp"
#ifdef STRIDE_HAVE_MUJOCO
#include "simulator/world/mujoco/mj_world.hpp"
#endif
#include "tests/simulator/sim_test_util.hpp"

namespace stride {
namespace {

#ifdef STRIDE_HAVE_MUJOCO

// The compiled MuJoCo model carries every NAO link's URDF mass, centre of mass and inertia tensor
// (the ones the ODE world takes): MuJoCo stores the tensor as principal moments in a rotated
// frame (its eigen-decomposition rounds at about 1e-8 of the tensor), and its compiler may
// "balance" an inertia; the tensor rebuilt from them is the URDF's.
TEST(MujocoEngine, EveryNaoLinkHasItsUrdfMassAndInertia) {
  const model::RobotModel nao = model::load_urdf(test::source_path("scenes/robots/nao/nao.urdf"));
  sim::MjWorld world(sim::PhysicsSettings{}, sim::GroundSettings{});
  world.add_robot(nao, 0, Eigen::Isometry3d::Identity(),
                  model::JointVector::Zero(static_cast<int>(nao.joints.size())));
  const mjModel* m = world.model();
  double total = 0;
  for (size_t l = 0; l < nao.links.size(); ++l) {
    const model::Inertial& in = nao.links[l].inertial;
    if (in.mass <= 1e-6) continue;  // a massless link gets the same floor on both engines
    const int b = world.layout(0).body[l];
    ASSERT_GE(b, 0) << nao.links[l].name;
    total += m->body_mass[b];
    EXPECT_NEAR(m->body_mass[b], in.mass, 1e-12) << nao.links[l].name;
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(m->body_ipos[3 * b + k], in.com[k], 1e-12) << nao.links[l].name;
    const mjtNum* q = m->body_iquat + 4 * b;
    const Eigen::Matrix3d r = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix();
    const Eigen::Vector3d principal(m->body_inertia[3 * b], m->body_inertia[3 * b + 1],
                                    m->body_inertia[3 * b + 2]);
    const Eigen::Matrix3d tensor = r * principal.asDiagonal() * r.transpose();
    EXPECT_LT((tensor - in.inertia).norm(), 1e-6 * in.inertia.norm())
        << nao.links[l].name << ": MuJoCo\n"
        << tensor << "\nURDF\n"
        << in.inertia;
  }
  EXPECT_NEAR(total, nao.total_mass(), 1e-9);
}

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

// The MuJoCo-only <physics> attributes (measuring a walk's dependence on MuJoCo's contact model)
// reach the compiled model; without them it is MuJoCo's own defaults with the elliptic cone and
// 10 no-slip iterations.
TEST(MujocoEngine, ContactOptionsReachTheCompiledModel) {
  const auto compiled = [](const std::string& attrs) {
    const auto sim =
        test::scene_from_text("<scene><physics engine=\"mujoco\" " + attrs + "/></scene>");
    auto world = std::make_unique<sim::MjWorld>(sim->scene().physics, sim->scene().ground);
    world->step();  // compiles the ground-only scene
    return world;
  };
  const auto plain = compiled("solver=\"exact\"");
  const mjModel* m = plain->model();
  EXPECT_EQ(m->opt.solver, mjSOL_NEWTON);
  EXPECT_EQ(m->opt.cone, mjCONE_ELLIPTIC);
  EXPECT_EQ(m->opt.noslip_iterations, 10);
  EXPECT_DOUBLE_EQ(m->geom_solref[0], 0.02);
  EXPECT_DOUBLE_EQ(m->geom_solref[1], 1.0);
  EXPECT_DOUBLE_EQ(m->geom_solimp[0], 0.9);
  EXPECT_DOUBLE_EQ(m->geom_solimp[1], 0.95);
  const auto varied = compiled(
      "solver=\"cg\" cone=\"pyramidal\" noslip_iterations=\"0\" contact_timeconst=\"5ms\" "
      "contact_dampratio=\"0.5\" contact_dmin=\"0.8\" contact_dmax=\"0.99\"");
  m = varied->model();
  EXPECT_EQ(m->opt.solver, mjSOL_CG);
  EXPECT_EQ(m->opt.cone, mjCONE_PYRAMIDAL);
  EXPECT_EQ(m->opt.noslip_iterations, 0);
  EXPECT_DOUBLE_EQ(m->geom_solref[0], 0.005);
  EXPECT_DOUBLE_EQ(m->geom_solref[1], 0.5);
  EXPECT_DOUBLE_EQ(m->geom_solimp[0], 0.8);
  EXPECT_DOUBLE_EQ(m->geom_solimp[1], 0.99);
}

TEST(MujocoEngine, ContactOptionsOutOfRangeAreErrorsAtTheirLine) {
  for (const std::string& bad :
       {"contact_timeconst=\"1ms\"", "contact_dampratio=\"0\"", "contact_dmin=\"1\"",
        "cone=\"round\"", "noslip_iterations=\"-1\""}) {
    try {
      test::scene_from_text("<scene>\n<physics engine=\"mujoco\" " + bad + "/></scene>");
      ADD_FAILURE() << "expected an error for " << bad;
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("inline.xml:2"), std::string::npos) << what;
      EXPECT_NE(what.find(bad.substr(0, bad.find('='))), std::string::npos) << what;
    }
  }
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
