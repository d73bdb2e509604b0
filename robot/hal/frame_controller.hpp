#pragma once
// The boundary from the body's side, for a body that sets the pace (the simulator): it hands its
// controller each control frame's sensors and takes the frame's commands back. A runtime on a NAO
// paces itself on its HardwareLink (LoLA) instead; PacedRuntime turns one into the other.
#include "robot/hal/actuator_frame.hpp"
#include "robot/hal/sensor_frame.hpp"

namespace stride::hal {

class FrameController {
 public:
  virtual ~FrameController() = default;
  // One control frame: true with the frame's `commands`; false when there are none (no answer,
  // no client), and the body keeps its previous commands.
  virtual bool control_frame(const SensorFrame& sensors, ActuatorFrame& commands) = 0;
};

}  // namespace stride::hal
