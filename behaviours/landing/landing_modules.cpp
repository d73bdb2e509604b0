#include "behaviours/landing/landing_modules.hpp"

#include <array>
#include <cmath>

#include <Eigen/Geometry>

#include "behaviours/joint_state/joint_velocities.hpp"
#include "behaviours/landing/landing_law.hpp"
#include "robot/model/kinematics/nao_fk.hpp"
#include "robot/model/kinematics/nao_leg_ik.hpp"
#include "robot/model/link_poses.hpp"
#include "robot/representations/frame_info.hpp"
#include "robot/representations/inertial_sensor_data.hpp"
#include "robot/representations/joint_request.hpp"
#include "robot/representations/joint_sensor_data.hpp"

namespace stride::behaviours {
namespace {

using hal::JointId;

constexpr std::array<JointId, 6> kLeftLeg = {JointId::LHipYawPitch, JointId::LHipRoll,
                                             JointId::LHipPitch,    JointId::LKneePitch,
                                             JointId::LAnklePitch,  JointId::LAnkleRoll};

model::LegAngles left_leg(const std::array<double, hal::kNumJoints>& lola) {
  model::LegAngles q{};
  for (int i = 0; i < 6; ++i) q[i] = lola[hal::index(kLeftLeg[i])];
  return q;
}

// What both share: the first frame's angles (held) and sole pose (the plan's start).
class LandingFoot : public Module {
 protected:
  explicit LandingFoot(ModuleContext& c)
      : frame_(c.require<FrameInfo>()),
        joints_(c.require<JointSensorData>()),
        request_(c.provide<JointRequest>()) {}

  void update() final {
    if (!started_) {
      hold_ = joints_.position;
      start_ = model::leg_fk(model::Side::Left, left_leg(hold_));
      started_ = true;
    }
    for (int i = 0; i < hal::kNumJoints; ++i) {
      request_.mode[i] = hal::ServoMode::Position;
      request_.position[i] = hold_[i];
      request_.stiffness[i] = hold_stiffness();
      request_.torque[i] = 0;
    }
    land();
  }

  virtual double hold_stiffness() const = 0;
  virtual void land() = 0;

  landing::SoleTarget target(double speed, double descent) const {
    return landing::planned_sole(start_, speed, start_.translation().z() - descent, frame_.time);
  }

  const FrameInfo& frame_;
  const JointSensorData& joints_;
  JointRequest& request_;
  std::array<double, hal::kNumJoints> hold_{};

 private:
  bool started_ = false;
  Eigen::Isometry3d start_ = Eigen::Isometry3d::Identity();
};

class LandingPosition final : public LandingFoot {
 public:
  explicit LandingPosition(ModuleContext& c)
      : LandingFoot(c), params_(c.parameters<LandingPositionParameters>()) {}

 private:
  double hold_stiffness() const override { return params_.hold_stiffness; }
  void land() override {
    const model::LegIkResult ik =
        model::leg_ik(model::Side::Left, target(params_.speed, params_.descent).pose);
    for (int i = 0; i < 6; ++i) request_.position[hal::index(kLeftLeg[i])] = ik.q[i];
  }

  const LandingPositionParameters& params_;
};

class LandingImpedance final : public LandingFoot {
 public:
  explicit LandingImpedance(ModuleContext& c)
      : LandingFoot(c),
        velocities_(c.require<JointVelocities>()),
        inertial_(c.require<InertialSensorData>()),
        params_(c.parameters<LandingImpedanceParameters>()),
        model_(c.robot_model()) {
    if (!model_.links.empty()) leg_ = landing::left_leg_gravity_model(model_);
    for (std::size_t j = 0; j < model_.joints.size(); ++j)
      for (int l = 0; l < hal::kNumJoints; ++l)
        if (model_.joints[j].name == hal::kJointNames[l]) lola_of_joint_.emplace_back(j, l);
  }

 private:
  double hold_stiffness() const override { return params_.hold_stiffness; }
  void land() override {
    q_model_.setZero();  // joints LoLA does not name stay at zero
    for (const auto& [j, l] : lola_of_joint_)
      q_model_[static_cast<Eigen::Index>(j)] = joints_.position[l];
    model::apply_mimic(model_, q_model_);
    // Gravity in the torso frame from the IMU's roll and pitch.
    const Eigen::Matrix3d torso =
        (Eigen::AngleAxisd(inertial_.angles.y(), Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(inertial_.angles.x(), Eigen::Vector3d::UnitX()))
            .toRotationMatrix();
    const Eigen::Vector3d gravity = torso.transpose() * Eigen::Vector3d(0, 0, -9.81);
    const landing::ImpedanceGains gains{params_.stiffness, params_.damping, params_.rot_stiffness,
                                        params_.rot_damping};
    const model::LegAngles tau = landing::impedance_torques(
        gains, target(params_.speed, params_.descent), left_leg(joints_.position),
        left_leg(velocities_.velocity),
        landing::leg_gravity_torques(model_, leg_, q_model_, gravity, poses_));
    // HipYawPitch is shared with the right leg: it keeps its position; the other five push.
    for (int i = 1; i < 6; ++i) {
      const int k = hal::index(kLeftLeg[i]);
      request_.mode[k] = hal::ServoMode::Torque;
      request_.torque[k] = tau[i];
    }
  }

  const JointVelocities& velocities_;
  const InertialSensorData& inertial_;
  const LandingImpedanceParameters& params_;
  const model::RobotModel model_;  // a copy: the module outlives nothing it borrowed
  landing::LegGravityModel leg_;
  std::vector<std::pair<std::size_t, int>> lola_of_joint_;  // model joint, LoLA index
  // Work space sized here, so a control frame does not allocate.
  Eigen::VectorXd q_model_ = model::zero_joints(model_);
  std::vector<Eigen::Isometry3d> poses_ =
      std::vector<Eigen::Isometry3d>(model_.links.size(), Eigen::Isometry3d::Identity());
};

}  // namespace

void register_landing_modules(ModuleRegistry& registry) {
  registry.add<LandingPosition>("LandingPosition");
  registry.add<LandingImpedance>("LandingImpedance");
}

}  // namespace stride::behaviours
