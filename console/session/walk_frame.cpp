#include "console/session/walk_frame.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "behaviours/posture/posture_representations.hpp"
#include "behaviours/posture/walking_joint_request.hpp"
#include "robot/representations/joint_request.hpp"
#include "robot/runtime/nao_io_modules.hpp"

namespace stride::console {
namespace {

using hal::JointId;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool on_blackboard(const Runtime& rt, const std::string& name) {
  const auto names = rt.representation_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

void fill_nan(WalkFrame& f) {
  for_each_field<WalkFrame>([&](const auto& field) { f.*(field.member) = kNaN; });
}

}  // namespace

std::optional<WalkPatternInfo> walk_pattern_info(SimSession& session) {
  Runtime* rt = session.simulation().robot_count() > 0 ? session.runtime(0) : nullptr;
  if (!rt) return std::nullopt;
  return behaviours::walk_pattern_info(*rt);
}

WalkFrameObserver::WalkFrameObserver(SimSession& session)
    : WalkFrameObserver(session, walk_pattern_info(session)) {}

WalkFrameObserver::WalkFrameObserver(SimSession& session, std::optional<WalkPatternInfo> pattern) {
  if (session.simulation().robot_count() == 0) return;
  rt_ = session.runtime(0);
  info_ = std::move(pattern);
  if (info_) pattern_.emplace(*info_);
  if (rt_) {
    has_torso_state_ = on_blackboard(*rt_, "TorsoState");
    has_walking_request_ = on_blackboard(*rt_, "WalkingJointRequest");
  }
  const auto& m = session.simulation().robot(0).model();
  lfoot_ = m.link_index("LFoot");
  rfoot_ = m.link_index("RFoot");
}

WalkFrameObserver::~WalkFrameObserver() = default;

void WalkFrameObserver::joints(WalkFrame& f) const {
  if (!rt_ || !has_walking_request_) return;
  const auto& ref = rt_->representation<WalkingJointRequest>().position;
  const auto& mod = rt_->representation<JointRequest>().position;
  auto pair = [&](double& r, double& m, JointId j) {
    r = ref[index(j)];
    m = mod[index(j)];
  };
  pair(f.hip_pitch_ref_l, f.hip_pitch_mod_l, JointId::LHipPitch);
  pair(f.hip_roll_ref_l, f.hip_roll_mod_l, JointId::LHipRoll);
  pair(f.hip_pitch_ref_r, f.hip_pitch_mod_r, JointId::RHipPitch);
  pair(f.hip_roll_ref_r, f.hip_roll_mod_r, JointId::RHipRoll);
  pair(f.ankle_pitch_ref_l, f.ankle_pitch_mod_l, JointId::LAnklePitch);
  pair(f.ankle_roll_ref_l, f.ankle_roll_mod_l, JointId::LAnkleRoll);
  pair(f.ankle_pitch_ref_r, f.ankle_pitch_mod_r, JointId::RAnklePitch);
  pair(f.ankle_roll_ref_r, f.ankle_roll_mod_r, JointId::RAnkleRoll);
  f.shoulder_pitch_l = mod[index(JointId::LShoulderPitch)];
  f.shoulder_pitch_r = mod[index(JointId::RShoulderPitch)];
}

void WalkFrameObserver::pattern_columns(WalkFrame& f, double t) {
  if (!pattern_) return;
  const behaviours::PlannedWalkSample plan = pattern_->at(t, *first_time_);
  f.pattern_t = plan.pattern_t;
  f.waist_v_ref = plan.waist_velocity_x;
  f.zmp_ref_x = origin_x_ + plan.zmp.x();
  f.zmp_ref_y = origin_y_ + plan.zmp.y();
}

void WalkFrameObserver::observe(const sim::SimulatedRobot& robot) {
  const hal::SensorFrame& s = robot.latest_sensors();
  const sim::TorsoPose torso = robot.torso_pose();
  const Eigen::Vector3d lf = robot.body().link_pose(lfoot_).translation();
  const Eigen::Vector3d rf = robot.body().link_pose(rfoot_).translation();
  WalkFrame& f = frame_;
  fill_nan(f);
  f.feet_x = 0.5 * (lf.x() + rf.x());
  f.feet_y = 0.5 * (lf.y() + rf.y());
  if (!first_time_) {
    first_time_ = s.time;
    origin_x_ = f.feet_x;
    origin_y_ = f.feet_y;
  }
  f.t = s.time;
  pattern_columns(f, s.time);
  joints(f);
  if (has_torso_state_) {
    const auto& e = rt_->representation<TorsoState>();
    f.est_pitch = e.pitch, f.est_roll = e.roll;
    f.est_pitch_rate = e.pitch_rate, f.est_roll_rate = e.roll_rate;
  }
  const double dt = previous_ ? s.time - previous_->t : 0;
  f.true_pitch = torso.pitch, f.true_roll = torso.roll;
  f.true_pitch_rate = dt > 0 ? (torso.pitch - previous_->pitch) / dt : 0;
  f.true_roll_rate = dt > 0 ? (torso.roll - previous_->roll) / dt : 0;
  f.imu_pitch = s.angles[1], f.imu_roll = s.angles[0];
  f.gyro_pitch = s.gyroscope[1], f.gyro_roll = s.gyroscope[0];
  f.waist_v = dt > 0 ? (torso.x - previous_->x) / dt : 0;
  f.torso_x = torso.x, f.torso_y = torso.y, f.torso_z = torso.z, f.torso_yaw = torso.yaw;
  const FsrSensorData fsr = fsr_sensor_data(s, 2.0);
  if (fsr.cop_torso_valid && fsr.total_left + fsr.total_right > 5.0) {
    const Eigen::Matrix3d r = (Eigen::AngleAxisd(torso.yaw, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(torso.pitch, Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(torso.roll, Eigen::Vector3d::UnitX()))
                                  .toRotationMatrix();
    const Eigen::Vector3d cop = Eigen::Vector3d(torso.x, torso.y, torso.z) + r * fsr.cop_torso;
    f.cop_x = cop.x(), f.cop_y = cop.y();
  }
  f.knee_current_l = s.current[index(JointId::LKneePitch)];
  f.knee_current_r = s.current[index(JointId::RKneePitch)];
  const Eigen::Vector3d com = robot.body().centre_of_mass();
  f.com_x = com.x(), f.com_y = com.y(), f.com_z = com.z();
  f.fell = robot.fallen() ? 1.0 : 0.0;
  previous_ = Previous{s.time, torso.x, torso.pitch, torso.roll};
}

}  // namespace stride::console
