// The loaded NAO model against the published numbers it was written from (nao-facts.md).
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "robot/model/link_poses.hpp"
#include "robot/model/urdf_loader.hpp"
#include "tests/simulator/sim_test_util.hpp"

namespace stride {
namespace {

// nao-facts.md, URDF-V5 masses (kg) and CoMs (m, link frame), left side.
struct Row {
  const char* link;
  double m, x, y, z;
};
constexpr Row kFacts[] = {
    {"torso", 1.04956, -0.00413, 0, 0.04342},
    {"Neck", 0.07842, -1e-5, 0, -0.02742},
    {"Head", 0.60533, -0.00112, 0, 0.05258},
    {"LShoulder", 0.09304, -0.00165, -0.02663, 0.00014},
    {"LBicep", 0.15777, 0.02455, 0.00563, 0.0033},
    {"LElbow", 0.06483, -0.02744, 0, -0.00014},
    {"LForeArm", 0.07761, 0.02556, 0.00281, 0.00076},
    {"LHand", 0.18533, 0.03434, -0.00088, 0.00308},
    {"LPelvis", 0.06981, -0.00781, -0.01114, 0.02661},
    {"LHip", 0.14053, -0.01549, 0.00029, -0.00515},
    {"LThigh", 0.38968, 0.00138, 0.00221, -0.05373},
    {"LTibia", 0.30142, 0.00453, 0.00225, -0.04936},
    {"LAnkle", 0.13416, 0.00045, 0.00029, 0.00685},
    {"LFoot", 0.17184, 0.02542, 0.0033, -0.03239},
};

// Link origins at the zero pose in the torso frame, from the link lengths (thesis Appendix A).
Eigen::Vector3d origin_of(const std::string& link, double s) {
  const double y_sh = 0.098 * s, y_hip = 0.05 * s;
  if (link == "torso") return {0, 0, 0};
  if (link == "Neck" || link == "Head") return {0, 0, 0.1265};
  if (link == "Shoulder" || link == "Bicep") return {0, y_sh, 0.1};
  if (link == "Elbow" || link == "ForeArm") return {0.105, y_sh + 0.015 * s, 0.1};
  if (link == "Hand") return {0.105 + 0.05595, y_sh + 0.015 * s, 0.1};
  if (link == "Pelvis" || link == "Hip" || link == "Thigh") return {0, y_hip, -0.085};
  if (link == "Tibia") return {0, y_hip, -0.185};
  return {0, y_hip, -0.2879};  // Ankle, Foot
}

TEST(NaoModel, TotalMassAndCentreOfMassMatchPublishedNumbers) {
  const auto model = model::load_urdf(test::source_path("scenes/robots/nao/nao.urdf"));
  double mass = 0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (const Row& r : kFacts) {
    const std::string name = r.link;
    const bool sided = name[0] == 'L';  // left links; the right mirrors them
    const std::vector<double> sides = sided ? std::vector<double>{1, -1} : std::vector<double>{1};
    for (double s : sides) {
      const std::string base = sided ? name.substr(1) : name;
      mass += r.m;
      moment += r.m * (origin_of(base, s) + Eigen::Vector3d(r.x, s * r.y, r.z));
    }
  }
  EXPECT_NEAR(mass, 5.305, 0.0005);  // nao-facts: total 5.305 kg
  EXPECT_NEAR(model.total_mass(), mass, 1e-9);
  std::vector<Eigen::Isometry3d> poses;
  model::link_poses(model, model::zero_joints(model), poses);
  const Eigen::Vector3d com = model::centre_of_mass(model, poses);
  EXPECT_LT((com - moment / mass).norm(), 1e-9);
}

TEST(NaoModel, SimulatorBodiesCarryTheModelsCentreOfMass) {
  auto sim = test::scene_from_text(R"(<scene><ground enabled="false"/><physics gravity="0 0 0"/>
    <robot name="nao" urdf="../../scenes/robots/nao/nao.urdf" xyz="0 0 1" fixed="true">
      <joints LKneePitch="0.6" RKneePitch="0.6" LHipPitch="-0.3" RHipPitch="-0.3"
              LShoulderPitch="1.5" RShoulderPitch="1.2" HeadYaw="0.3" LHipYawPitch="-0.2"/>
    </robot></scene>)");
  const auto& robot = sim->robot(0);
  model::JointVector q = model::zero_joints(robot.model());
  for (const auto& [name, v] : robot.placement().joints) q[robot.model().joint_index(name)] = v;
  model::apply_mimic(robot.model(), q);
  std::vector<Eigen::Isometry3d> poses;
  model::link_poses(robot.model(), q, poses);
  const Eigen::Vector3d com_model = model::centre_of_mass(robot.model(), poses);
  const Eigen::Vector3d com_sim = robot.body().centre_of_mass() - Eigen::Vector3d(0, 0, 1);
  EXPECT_LT((com_model - com_sim).norm(), 1e-9);
  // Every link frame where the model puts it, and every joint reads back its value.
  for (int l = 0; l < robot.body().link_count(); ++l) {
    const Eigen::Vector3d p = robot.body().link_pose(l).translation() - Eigen::Vector3d(0, 0, 1);
    EXPECT_LT((p - poses[l].translation()).norm(), 1e-9) << robot.model().links[l].name;
  }
  for (size_t j = 0; j < robot.model().joints.size(); ++j)
    EXPECT_NEAR(robot.body().joint_position(static_cast<int>(j)), q[j], 1e-9)
        << robot.model().joints[j].name;
}

}  // namespace
}  // namespace stride
