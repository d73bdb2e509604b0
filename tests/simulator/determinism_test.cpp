// Same binary + scene + seed = the same bits; another seed with noise = other bits.
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "robot/core/error.hpp"
#include "tests/simulator/sim_test_util.hpp"

namespace stride {
namespace {

std::string scene(int seed) {
  return R"(<scene><physics seed=")" + std::to_string(seed) + R"("/>
    <uneven centre="0.3 0" size="1 0.6" cell="0.05" height="3mm" tilt="1deg"/>
    <robot name="nao" urdf="../../scenes/robots/nao/nao.urdf" devices="../../scenes/robots/nao/nao.devices.xml">
      <joints LKneePitch="0.6" RKneePitch="0.6" LHipPitch="-0.3" RHipPitch="-0.3"
              LAnklePitch="-0.3" RAnklePitch="-0.3" LShoulderPitch="1.5" RShoulderPitch="1.5"/>
    </robot>
    <push robot="nao" body="torso" force="4 2 0" start="0.3" duration="0.1"/></scene>)";
}

// On every engine built in (ODE, MuJoCo).
class Determinism : public ::testing::TestWithParam<std::string> {
 protected:
  std::unique_ptr<sim::Simulation> make(int seed) const {
    return test::scene_from_text(test::on_engine(scene(seed), GetParam()));
  }
  std::uint64_t run_hash(int seed, double seconds) const {
    auto sim = make(seed);
    sim->run_for(seconds);
    return sim->state_hash();
  }
};

TEST_P(Determinism, TwoRunsGiveIdenticalHashes) {
  EXPECT_EQ(run_hash(5, 1.0), run_hash(5, 1.0));
}

TEST_P(Determinism, ResetInsideOneProcessReproducesTheRun) {
  auto sim = make(5);
  EXPECT_EQ(sim->world().engine_name(), GetParam());
  sim->run_for(1.0);
  const auto first = sim->state_hash();
  sim->reset();
  EXPECT_EQ(sim->time(), 0.0);
  sim->run_for(1.0);
  EXPECT_EQ(sim->state_hash(), first);
}

TEST_P(Determinism, AnotherSeedWithNoiseGivesAnotherHash) {
  EXPECT_NE(run_hash(5, 0.5), run_hash(6, 0.5));
}

INSTANTIATE_TEST_SUITE_P(Engines, Determinism, ::testing::ValuesIn(test::engines()),
                         test::engine_name);

TEST(DeterminismOde, DivergingPhysicsStopsWithTheBodyNamed) {
  // The largest push a scene may give (1e7 N) on a light link makes the state explode; the run
  // must stop and say where.
  auto sim = test::scene_from_text(R"(<scene>
    <robot name="nao" urdf="../../scenes/robots/nao/nao.urdf"/>
    <push robot="nao" body="LHand" force="1e7 0 0" start="0" duration="1"/></scene>)");
  try {
    sim->run_for(1.0);
    FAIL() << "expected the divergence to be detected";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("robot 'nao' link '"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("physics diverged"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace stride
