#pragma once
// ComStateEstimator (thesis Sec. 7.2): kinematic CoM + FSR centre of pressure, fused by the
// 3D-LIPM Kalman filter (Sec. 7.2), in the ground frame between the feet.
//   JointSensorData, FsrSensorData, InertialSensorData, FrameInfo -> ComState, BalanceModel
#include <array>
#include <vector>

#include <Eigen/Geometry>

#include "behaviours/balance/modules/balance_representations.hpp"
#include "robot/framework/module_registry.hpp"
#include "robot/hal/joint_id.hpp"
#include "robot/model/kinematics/nao_joint_map.hpp"
#include "robot/model/robot_model.hpp"

namespace stride::behaviours {

struct ComStateEstimatorParameters {
  STRIDE_FIELDS(ComStateEstimatorParameters);
  // process noise std-devs per step (Q)
  STRIDE_FIELD(double, sigma_position, "m", Range{0, 1}) = 1e-4;
  STRIDE_FIELD(double, sigma_velocity, "m/s", Range{0, 10}) = 5e-2;
  // the ZMP input (Eq. 7.4) is unknown: it is absorbed here
  STRIDE_FIELD(double, sigma_zmp, "m", Range{0, 1}) = 2e-2;
  STRIDE_FIELD(double, sigma_com, "m", Range{1e-9, 1}) = 1e-3;  // measurement noise std-devs (R)
  STRIDE_FIELD(double, sigma_cop, "m", Range{1e-9, 1}) = 5e-3;
  // accelerometer force measurement (N); 0 leaves it out
  STRIDE_FIELD(double, sigma_force, "N", Range{0, 1e3}) = 0;
  STRIDE_FIELD(double, g, "m/s^2", Range{0.1, 100}) = 9.81;
  // level the ground frame with the IMU instead of the left sole
  STRIDE_FIELD(bool, use_imu_tilt) = true;
  // Walking: the origin follows the stance sole (the foot whose FSRs carry more, by at least
  // support_hysteresis) instead of staying between the feet; the estimate moves with it.
  STRIDE_FIELD(bool, follow_support) = false;
  STRIDE_FIELD(double, support_hysteresis, "N", Range{0, 1000}) = 5;

  static constexpr std::string_view kTypeName = "ComStateEstimatorParameters";
};

// Ground frame (see ComState) in the torso frame, from the measured LoLA joint angles.
Eigen::Isometry3d ground_in_torso(const std::array<double, hal::kNumJoints>& lola,
                                  GroundOrigin origin = GroundOrigin::between_feet);

// Torso frame -> gravity-levelled ground frame (origin at `origin`, torso's heading) from the
// IMU's torso roll and pitch.
Eigen::Isometry3d level_ground_from_torso(const std::array<double, hal::kNumJoints>& lola,
                                          const Eigen::Vector2d& torso_roll_pitch,
                                          GroundOrigin origin = GroundOrigin::between_feet);

// The stance sole by the FSRs: the current one unless the other carries `hysteresis` N more.
GroundOrigin support_sole(GroundOrigin current, double left_load, double right_load,
                          double hysteresis);

// Whole-body CoM of a RobotModel (root = torso) at the LoLA angles, in the torso frame. Sized
// at construction: computing allocates nothing.
class KinematicCom {
 public:
  explicit KinematicCom(model::RobotModel model);
  const model::RobotModel& model() const { return model_; }
  Eigen::Vector3d in_torso(const std::array<double, hal::kNumJoints>& lola);
  // Mass-model numbers at the given (standing) angles; com_height from the ground frame.
  BalanceModel balance_model(const std::array<double, hal::kNumJoints>& lola);

 private:
  model::RobotModel model_;
  model::NaoJointMap map_;
  model::JointVector q_;
  std::vector<Eigen::Isometry3d> poses_;
};

void register_com_state_estimator(ModuleRegistry& registry);

}  // namespace stride::behaviours
