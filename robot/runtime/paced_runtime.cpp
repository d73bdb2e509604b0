#include "robot/runtime/paced_runtime.hpp"

namespace stride {

bool PacedRuntime::control_frame(const hal::SensorFrame& sensors, hal::ActuatorFrame& commands) {
  schedule_.apply_due(runtime_, sensors.time);
  return step(sensors, commands);
}

bool PacedRuntime::step(const hal::SensorFrame& sensors, hal::ActuatorFrame& commands) {
  link_.hand(sensors);
  runtime_.step();
  return link_.take(commands);
}

}  // namespace stride
