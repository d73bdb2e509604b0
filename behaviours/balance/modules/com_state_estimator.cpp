#include "behaviours/balance/modules/com_state_estimator.hpp"

#include <cmath>
#include <span>

#include "behaviours/balance/com_kalman_filter.hpp"
#include "robot/model/kinematics/nao_fk.hpp"
#include "robot/model/link_poses.hpp"
#include "robot/nao/nao_dimensions.hpp"
#include "robot/representations/frame_info.hpp"
#include "robot/representations/fsr_sensor_data.hpp"
#include "robot/representations/inertial_sensor_data.hpp"
#include "robot/representations/joint_sensor_data.hpp"

namespace stride {

balance::BalanceParams balance_params(const BalanceModel& m, double tau_forward,
                                      double tau_backward) {
  balance::BalanceParams p;
  p.z_cm = m.com_height;
  p.mass = m.mass;
  p.zmp_min = m.zmp_min;
  p.zmp_max = m.zmp_max;
  p.inertia = m.hat_inertia;
  p.tau_forward = tau_forward;
  p.tau_backward = tau_backward;
  p.theta_max_forward = m.theta_max_forward;
  p.theta_max_backward = m.theta_max_backward;
  return p;
}

}  // namespace stride

namespace stride::behaviours {

namespace {

model::LegAngles leg_angles(model::Side side, const std::array<double, hal::kNumJoints>& lola) {
  model::LegAngles q{};
  model::gather_chain(model::leg_chain(side), lola, std::span<double>(q));
  return q;
}

bool is_leg_link(const std::string& name) {
  for (const char* leg : {"Pelvis", "Hip", "Thigh", "Tibia", "Ankle", "Foot"})
    if (name == std::string("L") + leg || name == std::string("R") + leg) return true;
  return false;
}

}  // namespace

Eigen::Isometry3d ground_in_torso(const std::array<double, hal::kNumJoints>& lola,
                                  GroundOrigin origin) {
  const Eigen::Isometry3d left =
      model::leg_fk(model::Side::Left, leg_angles(model::Side::Left, lola));
  const Eigen::Isometry3d right =
      model::leg_fk(model::Side::Right, leg_angles(model::Side::Right, lola));
  if (origin == GroundOrigin::right_sole) return right;
  Eigen::Isometry3d g = left;  // standing feet are parallel: the left sole's axes serve both
  if (origin == GroundOrigin::between_feet)
    g.translation() = 0.5 * (left.translation() + right.translation());
  return g;
}

GroundOrigin support_sole(GroundOrigin current, double left_load, double right_load,
                          double hysteresis) {
  if (current != GroundOrigin::right_sole && right_load > left_load + hysteresis)
    return GroundOrigin::right_sole;
  if (current != GroundOrigin::left_sole && left_load > right_load + hysteresis)
    return GroundOrigin::left_sole;
  return current == GroundOrigin::between_feet ? GroundOrigin::left_sole : current;
}

Eigen::Isometry3d level_ground_from_torso(const std::array<double, hal::kNumJoints>& lola,
                                          const Eigen::Vector2d& torso_roll_pitch,
                                          GroundOrigin origin) {
  // The IMU's z-y-x angles without yaw: a sole that tips about its edge still reads level.
  const Eigen::Matrix3d level = (Eigen::AngleAxisd(torso_roll_pitch.y(), Eigen::Vector3d::UnitY()) *
                                 Eigen::AngleAxisd(torso_roll_pitch.x(), Eigen::Vector3d::UnitX()))
                                    .toRotationMatrix();
  Eigen::Isometry3d g = Eigen::Isometry3d::Identity();
  g.linear() = level;
  g.translation() = -level * ground_in_torso(lola, origin).translation();
  return g;
}

KinematicCom::KinematicCom(model::RobotModel model)
    : model_(std::move(model)),
      map_(model::make_nao_joint_map(model_)),
      q_(model::zero_joints(model_)),
      // Sized here so no frame allocates; computed per frame (the model may be the empty one a
      // Runtime hands out while it learns the modules' declarations).
      poses_(model_.links.size(), Eigen::Isometry3d::Identity()) {}

Eigen::Vector3d KinematicCom::in_torso(const std::array<double, hal::kNumJoints>& lola) {
  model::joints_from_lola(model_, map_, lola, q_);
  model::link_poses(model_, q_, poses_);
  return model::centre_of_mass(model_, poses_);
}

BalanceModel KinematicCom::balance_model(const std::array<double, hal::kNumJoints>& lola) {
  BalanceModel b;
  const Eigen::Isometry3d ground = ground_in_torso(lola);
  b.com_height = (ground.inverse() * in_torso(lola)).z();
  b.mass = model_.total_mass();
  // HAT = everything above the hips; its CoM distance to the hip pitch axis gives I (Sec. 7.5.1).
  double hat_mass = 0, feet_mass = 0;
  Eigen::Vector3d hat_moment = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < model_.links.size(); ++i) {
    const auto& link = model_.links[i];
    if (link.name == "LFoot" || link.name == "RFoot" || link.name == "LAnkle" ||
        link.name == "RAnkle")
      feet_mass += link.inertial.mass;
    if (is_leg_link(link.name)) continue;
    hat_mass += link.inertial.mass;
    hat_moment += link.inertial.mass * (poses_[i] * link.inertial.com);
  }
  b.mass_above_ankles = b.mass - feet_mass;
  const int lthigh = model_.link_index("LThigh"), rthigh = model_.link_index("RThigh");
  const Eigen::Vector3d hip_axis =
      0.5 * (poses_[lthigh].translation() + poses_[rthigh].translation());
  Eigen::Vector3d d = hat_moment / hat_mass - hip_axis;
  d.y() = 0;  // distance in the sagittal plane, perpendicular to the pitch axis
  b.hat_inertia = hat_mass * d.squaredNorm();
  b.hat_mass = hat_mass;
  b.zmp_min = nao::kSoleCentreX - nao::kSoleLength / 2;
  b.zmp_max = nao::kSoleCentreX + nao::kSoleLength / 2;
  // HAT angle theta = -(hip pitch - standing hip pitch): trunk forward is hip flexion (< 0).
  const auto& hip = model_.joints[model_.joint_index("LHipPitch")];
  const double stand = lola[hal::index(hal::JointId::LHipPitch)];
  b.theta_max_forward = stand - hip.lower;
  b.theta_max_backward = stand - hip.upper;
  b.valid = true;
  return b;
}

namespace {

class ComStateEstimator final : public Module {
 public:
  // Torso frame -> the ground frame with its origin at `origin`.
  Eigen::Isometry3d ground_from_torso(GroundOrigin origin) const {
    return params_.use_imu_tilt
               ? level_ground_from_torso(joints_.position, inertial_.angles, origin)
               : ground_in_torso(joints_.position, origin).inverse();
  }

  explicit ComStateEstimator(ModuleContext& c)
      : frame_(c.require<FrameInfo>()),
        joints_(c.require<JointSensorData>()),
        fsr_(c.require<FsrSensorData>()),
        inertial_(c.require<InertialSensorData>()),
        params_(c.parameters<ComStateEstimatorParameters>()),
        state_(c.provide<ComState>()),
        model_out_(c.provide<BalanceModel>()),
        debug_(c.debug_request("balance:kalman")),
        com_(c.robot_model()) {}

  void update() override {
    if (!stand_measured_) {
      model_out_ = com_.balance_model(joints_.position);  // first frame: the standing posture
      stand_measured_ = true;
    }
    const GroundOrigin origin = params_.follow_support
                                    ? support_sole(state_.origin, fsr_.total_left, fsr_.total_right,
                                                   params_.support_hysteresis)
                                    : GroundOrigin::between_feet;
    const Eigen::Isometry3d torso_to_ground = ground_from_torso(origin);
    if (origin != state_.origin && state_.valid) {
      // The estimate moves with the origin: the old origin seen from the new one, this frame.
      const Eigen::Vector3d shift =
          torso_to_ground * ground_from_torso(state_.origin).inverse() * Eigen::Vector3d::Zero();
      for (int axis : {0, 3}) {
        estimate_.x(axis) += shift(axis / 3);
        estimate_.x(axis + 2) += shift(axis / 3);
      }
    }
    state_.origin = origin;
    const Eigen::Vector3d com = torso_to_ground * com_.in_torso(joints_.position);
    state_.measured_com = com;
    state_.com_height = com.z();
    if (!fsr_.cop_torso_valid || !(frame_.period > 0) || !(com.z() > 0)) return;
    const Eigen::Vector3d cop = torso_to_ground * fsr_.cop_torso;
    state_.measured_cop = cop.head<2>();
    if (!state_.valid) {
      estimate_.x << com.x(), 0, cop.x(), com.y(), 0, cop.y();
      estimate_.P = balance::ComFilterCovariance::Identity() * 1e-4;
    }
    const auto filter =
        balance::com_filter_model(com.z(), params_.g, frame_.period, params_.sigma_position,
                                  params_.sigma_velocity, params_.sigma_zmp);  // A, B of Sec. 7.2
    const auto predicted = balance::predict(filter, estimate_, Eigen::Vector2d::Zero());
    if (params_.sigma_force > 0) {
      // The printed C: the accelerometer's levelled horizontal specific force times m is the
      // total horizontal force f = m omega^2 (x - x_zmp); it sees a push as it happens.
      const Eigen::Vector3d acc = torso_to_ground.linear() * inertial_.acc;
      const double mass = model_out_.mass;
      const double omega = std::sqrt(params_.g / com.z());
      Eigen::Matrix<double, 6, 1> y, r;
      y << com.x(), cop.x(), mass * acc.x(), com.y(), cop.y(), mass * acc.y();
      r << params_.sigma_com, params_.sigma_cop, params_.sigma_force, params_.sigma_com,
          params_.sigma_cop, params_.sigma_force;
      estimate_ = balance::update(predicted, y, balance::com_cop_force_measurement(mass, omega),
                                  Eigen::Matrix<double, 6, 6>(r.cwiseAbs2().asDiagonal()));
    } else {
      const Eigen::Vector4d y(com.x(), cop.x(), com.y(), cop.y());
      const Eigen::Vector4d r(params_.sigma_com, params_.sigma_cop, params_.sigma_com,
                              params_.sigma_cop);
      estimate_ = balance::update(predicted, y, balance::com_cop_measurement(),
                                  Eigen::Matrix4d(r.cwiseAbs2().asDiagonal()));
    }
    state_.valid = true;
    state_.x = estimate_.x(0);
    state_.xdot = estimate_.x(1);
    state_.zmp_x = estimate_.x(2);
    state_.y = estimate_.x(3);
    state_.ydot = estimate_.x(4);
    state_.zmp_y = estimate_.x(5);
    debug_.show({{"measured_com_x", com.x()},
                 {"com_x", state_.x},
                 {"measured_cop_x", cop.x()},
                 {"zmp_x", state_.zmp_x},
                 {"measured_com_y", com.y()},
                 {"com_y", state_.y},
                 {"measured_cop_y", cop.y()},
                 {"zmp_y", state_.zmp_y}});
  }

 private:
  const FrameInfo& frame_;
  const JointSensorData& joints_;
  const FsrSensorData& fsr_;
  const InertialSensorData& inertial_;
  const ComStateEstimatorParameters& params_;
  ComState& state_;
  BalanceModel& model_out_;
  DebugRequest debug_;  // measured CoM and CoP beside the filter's CoM and ZMP (Sec. 7.2)
  KinematicCom com_;
  bool stand_measured_ = false;
  balance::ComEstimate estimate_;
};

}  // namespace

void register_com_state_estimator(ModuleRegistry& registry) {
  registry.add<ComStateEstimator>("ComStateEstimator");
}

}  // namespace stride::behaviours
