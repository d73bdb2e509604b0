// The Ch. 4 posture-control modules (see posture_modules.hpp for the data flow).
#include "behaviours/posture/posture_modules.hpp"

#include "behaviours/posture/gyro_calibration.hpp"
#include "behaviours/posture/posture_representations.hpp"
#include "behaviours/posture/torso_kalman_filter.hpp"
#include "behaviours/posture/walking_joint_request.hpp"
#include "robot/model/kinematics/nao_fk.hpp"
#include "robot/representations/frame_info.hpp"
#include "robot/representations/inertial_sensor_data.hpp"
#include "robot/representations/joint_request.hpp"

namespace stride::behaviours {

using hal::index;
using hal::JointId;

namespace {

class GyroCalibration final : public Module {
 public:
  explicit GyroCalibration(ModuleContext& c)
      : inertial_(c.require<InertialSensorData>()),
        params_(c.parameters<GyroCalibrationParameters>()),
        out_(c.provide<CalibratedGyro>()) {}

  void update() override {
    out_.rate = calibrator_.calibrate(inertial_.gyro.head<2>(), params_.alpha,
                                      params_.start_at_first_sample);
    out_.offset = calibrator_.offset;
  }

 private:
  const InertialSensorData& inertial_;
  const GyroCalibrationParameters& params_;
  CalibratedGyro& out_;
  GyroCalibrator calibrator_;
};

class TorsoStateEstimator final : public Module {
 public:
  explicit TorsoStateEstimator(ModuleContext& c)
      : frame_(c.require<FrameInfo>()),
        inertial_(c.require<InertialSensorData>()),
        gyro_(c.require<CalibratedGyro>()),
        params_(c.parameters<TorsoStateEstimatorParameters>()),
        out_(c.provide<TorsoState>()),
        debug_(c.debug_request("posture:kalman")) {}

  void update() override {
    const TorsoVector y = torso_measurement(inertial_.angles, gyro_.rate);
    estimator_.step(frame_.period, params_.q_diagonal, params_.r_diagonal, params_.initial_variance,
                    y);
    const TorsoKalmanFilter& f = estimator_.filter;
    out_.pitch = f.x[0];
    out_.roll = f.x[1];
    out_.pitch_rate = f.x[2];
    out_.roll_rate = f.x[3];
    out_.variance = f.p.diagonal();
    out_.gain = f.gain.diagonal();
    debug_.show({{"measured_pitch", y[0]},
                 {"pitch", out_.pitch},
                 {"measured_roll", y[1]},
                 {"roll", out_.roll},
                 {"measured_pitch_rate", y[2]},
                 {"pitch_rate", out_.pitch_rate},
                 {"measured_roll_rate", y[3]},
                 {"roll_rate", out_.roll_rate}});
  }

 private:
  const FrameInfo& frame_;
  const InertialSensorData& inertial_;
  const CalibratedGyro& gyro_;
  const TorsoStateEstimatorParameters& params_;
  TorsoState& out_;
  DebugRequest debug_;  // measurement beside estimate (Eq. 4.7's y_k and x_k|k)
  TorsoEstimator estimator_;
};

// Hip or ankle strategy (Sec. 4.3.3) on the walking joint targets.
template <PostureJoints Joints>
class PostureStrategy final : public Module {
 public:
  explicit PostureStrategy(ModuleContext& c)
      : reference_(c.require<WalkingJointRequest>()),
        torso_(c.require<TorsoState>()),
        params_(c.parameters<PostureStrategyParameters<Joints>>()),
        out_(c.provide<PostureCorrectedRequest>()),
        debug_(c.debug_request("posture:corrections")) {}

  void update() override {
    const Eigen::Vector4d desired(params_.desired_pitch, params_.desired_roll, 0, 0);
    const Eigen::Vector2d delta = posture_correction(params_.gains(), desired, torso_.state());
    out_.position = reference_.position;
    out_.stiffness = reference_.stiffness;
    apply_posture_correction(Joints, delta, out_.position);
    out_.pitch_correction = delta[0];
    out_.roll_correction = delta[1];
    debug_.show({{"pitch_correction", delta[0]},
                 {"roll_correction", delta[1]},
                 {"torso_pitch", torso_.pitch},
                 {"torso_roll", torso_.roll}});
  }

 private:
  const WalkingJointRequest& reference_;
  const TorsoState& torso_;
  const PostureStrategyParameters<Joints>& params_;
  PostureCorrectedRequest& out_;
  DebugRequest debug_;  // the corrections (Eq. 4.8 and Eq. 4.9, or Eq. 4.12 and Eq. 4.13) and the
                        // torso they answer
};

// Passes the walking targets through: the "no posture control" runs of Sec. 4.3.4.
class NoPostureControl final : public Module {
 public:
  explicit NoPostureControl(ModuleContext& c)
      : reference_(c.require<WalkingJointRequest>()), out_(c.provide<PostureCorrectedRequest>()) {}

  void update() override {
    out_.position = reference_.position;
    out_.stiffness = reference_.stiffness;
    out_.pitch_correction = out_.roll_correction = 0;
  }

 private:
  const WalkingJointRequest& reference_;
  PostureCorrectedRequest& out_;
};

// Shoulder pitch around the walking request's arm posture, from the planned feet (Sec. 4.4).
class ArmSwing final : public Module {
 public:
  explicit ArmSwing(ModuleContext& c)
      : reference_(c.require<WalkingJointRequest>()),
        params_(c.parameters<ArmSwingParameters>()),
        out_(c.provide<ArmSwingRequest>()) {}

  void update() override {
    const double left_x = foot_x(model::Side::Left);
    const double right_x = foot_x(model::Side::Right);
    ArmSwingModel m = params_.model();
    m.swing_leg_mass *= params_.gain_scale;  // scales x_a of Eq. 4.20
    const ArmSwingOffsets o = arm_swing_offsets(m, left_x, right_x);
    out_.left_arm_displacement = o.left_displacement;
    out_.right_arm_displacement = o.right_displacement;
    out_.left_shoulder_pitch =
        reference_.position[index(JointId::LShoulderPitch)] + o.left_shoulder_pitch;
    out_.right_shoulder_pitch =
        reference_.position[index(JointId::RShoulderPitch)] + o.right_shoulder_pitch;
  }

 private:
  double foot_x(model::Side side) const {
    model::LegAngles q{};
    model::gather_chain(model::leg_chain(side), reference_.position, q);
    return model::leg_fk(side, q).translation().x();
  }

  const WalkingJointRequest& reference_;
  const ArmSwingParameters& params_;
  ArmSwingRequest& out_;
};

// Final joint targets: the corrected legs (and everything else) with the arm-swing shoulders.
class WalkingJointRequestAssembler final : public Module {
 public:
  explicit WalkingJointRequestAssembler(ModuleContext& c)
      : legs_(c.require<PostureCorrectedRequest>()),
        arms_(c.require<ArmSwingRequest>()),
        out_(c.provide<JointRequest>()) {}

  void update() override { assemble_walking_request(legs_.position, legs_.stiffness, arms_, out_); }

 private:
  const PostureCorrectedRequest& legs_;
  const ArmSwingRequest& arms_;
  JointRequest& out_;
};

}  // namespace

void assemble_walking_request(const std::array<double, hal::kNumJoints>& position,
                              const std::array<double, hal::kNumJoints>& stiffness,
                              const ArmSwingRequest& arms, JointRequest& out) {
  out.position = position;
  out.stiffness = stiffness;
  out.mode.fill(hal::ServoMode::Position);
  out.torque.fill(0);
  out.position[index(JointId::LShoulderPitch)] = arms.left_shoulder_pitch;
  out.position[index(JointId::RShoulderPitch)] = arms.right_shoulder_pitch;
}

void register_posture_modules(ModuleRegistry& registry) {
  registry.add<GyroCalibration>("GyroCalibration");
  registry.add<TorsoStateEstimator>("TorsoStateEstimator");
  registry.add<PostureStrategy<PostureJoints::Hip>>("HipStrategy");
  registry.add<PostureStrategy<PostureJoints::Ankle>>("AnkleStrategy");
  registry.add<NoPostureControl>("NoPostureControl");
  registry.add<ArmSwing>("ArmSwing");
  registry.add<WalkingJointRequestAssembler>("WalkingJointRequestAssembler");
}

}  // namespace stride::behaviours
