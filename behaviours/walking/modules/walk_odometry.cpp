#include "behaviours/walking/modules/walk_odometry.hpp"

#include <optional>

#include "behaviours/walking/odometry/leg_odometry.hpp"
#include "robot/model/kinematics/nao_chains.hpp"
#include "robot/model/kinematics/nao_fk.hpp"
#include "robot/representations/frame_info.hpp"
#include "robot/representations/fsr_sensor_data.hpp"
#include "robot/representations/inertial_sensor_data.hpp"
#include "robot/representations/joint_sensor_data.hpp"

namespace stride::behaviours {

namespace {

Eigen::Vector2d sole_in_torso(model::Side side, const JointSensorData& joints) {
  model::LegAngles q{};
  model::gather_chain(model::leg_chain(side), joints.position, std::span<double>(q));
  return model::leg_fk(side, q).translation().head<2>();
}

class WalkOdometryEstimator final : public Module {
 public:
  explicit WalkOdometryEstimator(ModuleContext& c)
      : frame_(c.require<FrameInfo>()),
        joints_(c.require<JointSensorData>()),
        inertial_(c.require<InertialSensorData>()),
        fsr_(c.require<FsrSensorData>()),
        params_(c.parameters<WalkOdometryParameters>()),
        out_(c.provide<WalkOdometry>()) {}

  void update() override {
    if (last_time_) gyro_yaw_ += inertial_.gyro.z() * (frame_.time - *last_time_);
    last_time_ = frame_.time;
    state_ = walking::advance_leg_odometry(
        state_, params_.gyro_scale * gyro_yaw_, sole_in_torso(model::Side::Left, joints_),
        sole_in_torso(model::Side::Right, joints_), fsr_.total_left, fsr_.total_right,
        params_.exchange_share);
    out_.x = state_.torso.x();
    out_.y = state_.torso.y();
    out_.yaw = state_.yaw;
    out_.gyro_yaw = gyro_yaw_;
    out_.support = static_cast<std::int64_t>(state_.support);
    out_.exchanges = state_.exchanges;
  }

 private:
  const FrameInfo& frame_;
  const JointSensorData& joints_;
  const InertialSensorData& inertial_;
  const FsrSensorData& fsr_;
  const WalkOdometryParameters& params_;
  WalkOdometry& out_;
  std::optional<double> last_time_;
  double gyro_yaw_ = 0.0;
  walking::LegOdometryState state_;
};

}  // namespace

void register_walk_odometry_modules(ModuleRegistry& registry) {
  registry.add<WalkOdometryEstimator>("WalkOdometryEstimator");
}

}  // namespace stride::behaviours
