// The thesis' D-H forward kinematics (App. B) against the simulator's link poses, and the model's
// centre of mass against the simulator's mass-weighted bodies, for random configurations.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "robot/model/kinematics/nao_chains.hpp"
#include "robot/model/kinematics/nao_fk.hpp"
#include "robot/model/link_poses.hpp"
#include "robot/nao/nao_dimensions.hpp"
#include "simulator/scene/scene_parser.hpp"
#include "simulator/simulation.hpp"

namespace stride {
namespace {

using model::NaoChain;

TEST(FkAgainstSimulator, ThousandRandomConfigurationsAgreeToANanometre) {
  const std::string urdf = std::string(STRIDE_SOURCE_DIR) + "/scenes/robots/nao/nao.urdf";
  sim::SceneDescription base = sim::parse_scene_text(
      "<scene><ground enabled=\"false\"/><physics gravity=\"0 0 0\"/>"
      "<robot name=\"nao\" urdf=\"" +
          urdf + "\" xyz=\"0 0 0\" fixed=\"true\"/></scene>",
      "fk.xml");
  std::mt19937_64 rng(42);
  double worst_fk = 0, worst_com = 0;
  const sim::Simulation probe(base);
  for (int trial = 0; trial < 1000; ++trial) {
    // Random angles within every joint's limits, LoLA order (hands excluded).
    std::array<double, hal::kNumJoints> lola{};
    sim::SceneDescription scene = base;
    {
      const auto& m = probe.robot(0).model();
      for (int l = 0; l < hal::kNumJoints; ++l) {
        const int j = probe.robot(0).joint_of_lola(l);
        if (j < 0) continue;
        std::uniform_real_distribution<double> u(m.joints[j].lower, m.joints[j].upper);
        lola[l] = u(rng);
        scene.robots[0].joints[m.joints[j].name] = lola[l];
      }
      scene.robots[0].joints["RHipYawPitch"] = lola[hal::index(hal::JointId::LHipYawPitch)];
    }
    sim::Simulation s(scene);
    const auto& robot = s.robot(0);
    const auto& m = robot.model();
    auto link = [&](const char* name) { return robot.body().link_pose(m.link_index(name)); };
    auto check = [&](const Eigen::Isometry3d& fk, const Eigen::Isometry3d& sim_pose) {
      worst_fk = std::max(worst_fk, (fk.translation() - sim_pose.translation()).norm());
      worst_fk = std::max(worst_fk, (fk.linear() - sim_pose.linear()).norm());
    };
    for (auto [chain, foot] :
         {std::pair{NaoChain::LLeg, "LFoot"}, std::pair{NaoChain::RLeg, "RFoot"}}) {
      std::array<double, 6> q{};
      model::gather_chain(chain, lola, q);
      Eigen::Isometry3d sole = link(foot);
      sole.translate(Eigen::Vector3d(0, 0, -nao::kFootHeight));
      check(model::chain_fk(chain, q), sole);
    }
    for (auto [chain, hand] :
         {std::pair{NaoChain::LArm, "LHand"}, std::pair{NaoChain::RArm, "RHand"}}) {
      std::array<double, 5> q{};
      model::gather_chain(chain, lola, q);
      Eigen::Isometry3d point = link(hand);
      point.translate(Eigen::Vector3d(nao::kHandOffsetX, 0, 0));
      check(model::chain_fk(chain, q), point);
    }
    std::array<double, 2> qh{};
    model::gather_chain(NaoChain::Head, lola, qh);
    check(model::chain_fk(NaoChain::Head, qh), link("Head"));
    // Centre of mass: the model's (Eq. 3.17) against the simulator's bodies.
    model::JointVector qm = model::zero_joints(m);
    for (const auto& [name, v] : scene.robots[0].joints) qm[m.joint_index(name)] = v;
    std::vector<Eigen::Isometry3d> poses;
    model::link_poses(m, qm, poses);
    worst_com = std::max(worst_com,
                         (model::centre_of_mass(m, poses) - robot.body().centre_of_mass()).norm());
  }
  RecordProperty("worst_fk_error_m", std::to_string(worst_fk));
  EXPECT_LT(worst_fk, 1e-9);
  EXPECT_LT(worst_com, 1e-9);
}

}  // namespace
}  // namespace stride
