#pragma once
// The boundary between the robot runtime and a body: the in-process simulator, LoLA, or a replay.
#include <string>

#include "robot/hal/actuator_frame.hpp"
#include "robot/hal/sensor_frame.hpp"

namespace stride::hal {

class HardwareLink {
 public:
  virtual ~HardwareLink() = default;
  // Blocks until the next control frame's sensor data is ready; false when the link is lost.
  virtual bool read(SensorFrame& out) = 0;
  // Sends the commands for the frame whose sensors were last read.
  virtual void write(const ActuatorFrame& in) = 0;
  // Control period of this link in seconds (10 ms DCM, 12 ms LoLA).
  virtual double period() const = 0;
  virtual std::string name() const = 0;
};

}  // namespace stride::hal
