// Kinematics hot paths: analytic leg IK (target < 1 us) and full-body FK + CoM (target < 2 us).
#include <benchmark/benchmark.h>

#include "robot/model/kinematics/jacobians.hpp"
#include "robot/model/kinematics/nao_fk.hpp"
#include "robot/model/kinematics/nao_joint_map.hpp"
#include "robot/model/kinematics/nao_leg_ik.hpp"
#include "robot/model/urdf_loader.hpp"

namespace {

using namespace stride::model;

const RobotModel& nao() {
  static const RobotModel m = load_urdf(STRIDE_SOURCE_DIR "/scenes/robots/nao/nao.urdf");
  return m;
}

void BM_LegIk(benchmark::State& state) {
  const LegAngles q{0.1, 0.05, -0.4, 0.8, -0.4, -0.05};
  Eigen::Isometry3d target = leg_fk(Side::Left, q);
  for (auto _ : state) {
    target.translation().x() += 1e-9;  // a new target each call
    benchmark::DoNotOptimize(leg_ik(Side::Left, target));
  }
}
BENCHMARK(BM_LegIk);

void BM_BothLegsIk(benchmark::State& state) {
  const Eigen::Isometry3d l = leg_fk(Side::Left, {0.1, 0.05, -0.4, 0.8, -0.4, -0.05});
  const Eigen::Isometry3d r = leg_fk(Side::Right, {0.1, -0.05, -0.4, 0.8, -0.4, 0.05});
  for (auto _ : state) benchmark::DoNotOptimize(legs_ik(l, r));
}
BENCHMARK(BM_BothLegsIk);

void BM_LegFkAnalytic(benchmark::State& state) {
  LegAngles q{0.1, 0.05, -0.4, 0.8, -0.4, -0.05};
  for (auto _ : state) {
    q[2] += 1e-9;
    benchmark::DoNotOptimize(leg_fk(Side::Left, q));
  }
}
BENCHMARK(BM_LegFkAnalytic);

// All 26 link frames from the URDF tree plus the whole-body CoM; buffers reused (no allocation).
void BM_FullBodyFkAndCom(benchmark::State& state) {
  const RobotModel& m = nao();
  JointVector q = zero_joints(m);
  for (Eigen::Index i = 0; i < q.size(); ++i) q[i] = 0.01 * static_cast<double>(i);
  apply_mimic(m, q);
  std::vector<Eigen::Isometry3d> poses;
  link_poses(m, q, poses);
  for (auto _ : state) {
    q[0] += 1e-9;
    link_poses(m, q, poses);
    benchmark::DoNotOptimize(centre_of_mass(m, poses));
  }
}
BENCHMARK(BM_FullBodyFkAndCom);

void BM_ComJacobian(benchmark::State& state) {
  const RobotModel& m = nao();
  const JointVector q = zero_joints(m);
  std::vector<Eigen::Isometry3d> poses;
  link_poses(m, q, poses);
  Eigen::Matrix3Xd j(3, m.joints.size());
  for (auto _ : state) {
    com_jacobian(m, poses, j);
    benchmark::DoNotOptimize(j.data());
  }
}
BENCHMARK(BM_ComJacobian);

}  // namespace

BENCHMARK_MAIN();
