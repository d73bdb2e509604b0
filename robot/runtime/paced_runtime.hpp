#pragma once
// A Runtime whose frames a body hands it (hal::FrameController, the simulator): at each frame the
// controller's timed changes due, then the runtime's step over its HandedFrameLink.
#include <vector>

#include "robot/hal/controller_config.hpp"
#include "robot/hal/frame_controller.hpp"
#include "robot/hal/handed_frame_link.hpp"
#include "robot/runtime/controller_schedule.hpp"
#include "robot/runtime/runtime.hpp"

namespace stride {

class PacedRuntime final : public hal::FrameController {
 public:
  // `runtime` reads and writes `link`, directly or through a link around it (LoLA's packets).
  PacedRuntime(Runtime& runtime, hal::HandedFrameLink& link, std::vector<ControllerChange> changes)
      : runtime_(runtime), link_(link), schedule_(std::move(changes)) {}

  // The changes due at the frame's time (s since the controller started), then step().
  bool control_frame(const hal::SensorFrame& sensors, hal::ActuatorFrame& commands) override;
  // The runtime's frame alone: sensors in, Runtime::step(), commands out.
  bool step(const hal::SensorFrame& sensors, hal::ActuatorFrame& commands);

  Runtime& runtime() { return runtime_; }

 private:
  Runtime& runtime_;
  hal::HandedFrameLink& link_;
  ControllerSchedule schedule_;
};

}  // namespace stride
