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
  double sigma_position = 1e-4;  // process noise std-devs per step (Q)
  double sigma_velocity = 5e-2;
  double sigma_zmp = 2e-2;  // the ZMP input (Eq. 7.4) is unknown: it is absorbed here
  double sigma_com = 1e-3;  // measurement noise std-devs (R)
  double sigma_cop = 5e-3;
  double sigma_force = 0;  // accelerometer force measurement (N); 0 leaves it out
  double g = 9.81;
  bool use_imu_tilt = true;  // level the ground frame with the IMU instead of the left sole
  // Walking: the origin follows the stance sole (the foot whose FSRs carry more, by at least
  // support_hysteresis) instead of staying between the feet; the estimate moves with it.
  bool follow_support = false;
  double support_hysteresis = 5;  // N

  static constexpr std::string_view kTypeName = "ComStateEstimatorParameters";
  static constexpr auto fields() {
    using P = ComStateEstimatorParameters;
    return std::make_tuple(
        field("sigma_position", &P::sigma_position, "m", Range{0, 1}),
        field("sigma_velocity", &P::sigma_velocity, "m/s", Range{0, 10}),
        field("sigma_zmp", &P::sigma_zmp, "m", Range{0, 1}),
        field("sigma_com", &P::sigma_com, "m", Range{1e-9, 1}),
        field("sigma_cop", &P::sigma_cop, "m", Range{1e-9, 1}),
        field("sigma_force", &P::sigma_force, "N", Range{0, 1e3}),
        field("g", &P::g, "m/s^2", Range{0.1, 100}), field("use_imu_tilt", &P::use_imu_tilt),
        field("follow_support", &P::follow_support),
        field("support_hysteresis", &P::support_hysteresis, "N", Range{0, 1000}));
  }
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
