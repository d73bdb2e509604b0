#pragma once
// The NAO's sensor and actuator conversions: raw link data <-> representations.
//   SensorConversion:   SensorFrame -> JointSensorData, InertialSensorData, FsrSensorData
//   ActuatorConversion: JointRequest -> ActuatorFrame
#include <Eigen/Core>

#include "robot/framework/module_registry.hpp"
#include "robot/representations/fsr_sensor_data.hpp"
#include "robot/representations/inertial_sensor_data.hpp"
#include "robot/representations/joint_request.hpp"
#include "robot/representations/joint_sensor_data.hpp"

namespace stride {

struct SensorConversionParameters {
  STRIDE_FIELDS(SensorConversionParameters);
  // a foot is in contact when its FSRs sum to more than this
  STRIDE_FIELD(double, contact_force, "N", Range{0, 200}) = 2.0;
  // IMU |roll| or |pitch| beyond this is a fall (robot:stop_on_fall)
  STRIDE_FIELD(double, fall_tilt, "rad", Range{0.05, 3.2}) = 0.8;

  static constexpr std::string_view kTypeName = "SensorConversionParameters";
};

// Centre of pressure of one foot: force-weighted mean of its 4 FSR positions (ankle frame);
// zero when the total force is not positive.
Eigen::Vector2d foot_cop(const double* forces, const Eigen::Vector2d* positions);
FsrSensorData fsr_sensor_data(const hal::SensorFrame& s, double contact_force);
// The IMU's largest |roll| or |pitch|: past SensorConversionParameters::fall_tilt it is a fall.
inline double imu_tilt(const InertialSensorData& imu) {
  return imu.angles.cwiseAbs().maxCoeff();
}

void register_nao_io_modules(ModuleRegistry& registry);

}  // namespace stride
