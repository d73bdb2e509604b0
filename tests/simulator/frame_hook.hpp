#pragma once
// A test's own controller for a simulated robot: `frame(sensors, commands)` runs at each of its
// control frames (e.g. timing or counting around the session's PacedRuntime::step).
#include <utility>

#include "robot/hal/frame_controller.hpp"

namespace stride::test {

template <class Frame>
class FrameHook final : public hal::FrameController {
 public:
  explicit FrameHook(Frame frame) : frame_(std::move(frame)) {}
  bool control_frame(const hal::SensorFrame& sensors, hal::ActuatorFrame& commands) override {
    return frame_(sensors, commands);
  }

 private:
  Frame frame_;
};

}  // namespace stride::test
