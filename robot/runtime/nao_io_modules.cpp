#include "robot/runtime/nao_io_modules.hpp"

#include "robot/model/kinematics/nao_fk.hpp"
#include "robot/nao/nao_dimensions.hpp"

namespace stride {

Eigen::Vector2d foot_cop(const double* forces, const Eigen::Vector2d* positions) {
  double total = 0;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int i = 0; i < 4; ++i) {
    total += forces[i];
    sum += forces[i] * positions[i];
  }
  return total > 0 ? Eigen::Vector2d(sum / total) : Eigen::Vector2d::Zero();
}

FsrSensorData fsr_sensor_data(const hal::SensorFrame& s, double contact_force) {
  FsrSensorData f;
  f.force = s.fsr;
  for (int i = 0; i < 4; ++i) {
    f.total_left += s.fsr[i];
    f.total_right += s.fsr[i + 4];
  }
  f.contact_left = f.total_left > contact_force;
  f.contact_right = f.total_right > contact_force;
  f.cop_left = foot_cop(s.fsr.data(), nao::kFsrPositions.data());
  f.cop_right = foot_cop(s.fsr.data() + 4, nao::kFsrPositions.data() + 4);
  const double total = f.total_left + f.total_right;
  f.cop_torso_valid = total > 0;
  if (!f.cop_torso_valid) return f;
  // FSR positions lie in the sole plane, which is z = 0 of leg_fk's sole frame.
  auto in_torso = [&](model::Side side, const Eigen::Vector2d& cop) {
    model::LegAngles q{};
    model::gather_chain(model::leg_chain(side), s.position, std::span<double>(q));
    return model::leg_fk(side, q) * Eigen::Vector3d(cop.x(), cop.y(), 0);
  };
  f.cop_torso = (f.total_left * in_torso(model::Side::Left, f.cop_left) +
                 f.total_right * in_torso(model::Side::Right, f.cop_right)) /
                total;
  return f;
}

namespace {

class SensorConversion final : public Module {
 public:
  explicit SensorConversion(ModuleContext& c)
      : sensor_(c.require<hal::SensorFrame>()),
        params_(c.parameters<SensorConversionParameters>()),
        joints_(c.provide<JointSensorData>()),
        inertial_(c.provide<InertialSensorData>()),
        fsr_(c.provide<FsrSensorData>()),
        stop_on_fall_(c.debug_request("robot:stop_on_fall")) {}

  void update() override {
    joints_.position = sensor_.position;
    joints_.current = sensor_.current;
    joints_.temperature = sensor_.temperature;
    joints_.stiffness = sensor_.stiffness;
    inertial_.acc = Eigen::Vector3d(sensor_.accelerometer.data());
    inertial_.gyro = Eigen::Vector3d(sensor_.gyroscope.data());
    inertial_.angles = Eigen::Vector2d(sensor_.angles.data());
    fsr_ = fsr_sensor_data(sensor_, params_.contact_force);
    const double tilt = imu_tilt(inertial_);
    if (stop_on_fall_.on() && tilt > params_.fall_tilt)
      stop_on_fall_.stop("fell: IMU tilt " + std::to_string(tilt) + " rad (roll " +
                         std::to_string(inertial_.angles.x()) + ", pitch " +
                         std::to_string(inertial_.angles.y()) + ") past fall_tilt " +
                         std::to_string(params_.fall_tilt));
  }

 private:
  const hal::SensorFrame& sensor_;
  const SensorConversionParameters& params_;
  JointSensorData& joints_;
  InertialSensorData& inertial_;
  FsrSensorData& fsr_;
  DebugRequest stop_on_fall_;
};

class ActuatorConversion final : public Module {
 public:
  explicit ActuatorConversion(ModuleContext& c)
      : request_(c.require<JointRequest>()), out_(c.provide<hal::ActuatorFrame>()) {}

  // Limits, stiffness range and NaN are the Runtime's CommandGuard's (robot/runtime/
  // command_guard.hpp): it sees every command, whichever module provides the ActuatorFrame.
  void update() override {
    out_.mode = request_.mode;
    out_.position = request_.position;
    out_.stiffness = request_.stiffness;
    out_.torque = request_.torque;
  }

 private:
  const JointRequest& request_;
  hal::ActuatorFrame& out_;
};

}  // namespace

void register_nao_io_modules(ModuleRegistry& registry) {
  registry.add<SensorConversion>("SensorConversion");
  registry.add<ActuatorConversion>("ActuatorConversion");
}

}  // namespace stride
