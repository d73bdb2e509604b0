#pragma once
// The HardwareLink of a runtime whose frames are handed to it (hal::FrameController): read() gives
// the sensors handed in, write() keeps the commands until they are taken back.
#include <string>
#include <utility>

#include "robot/hal/hardware_link.hpp"

namespace stride::hal {

class HandedFrameLink final : public HardwareLink {
 public:
  HandedFrameLink(double period, std::string name) : period_(period), name_(std::move(name)) {}

  void hand(const SensorFrame& sensors) { sensors_ = sensors; }
  // The commands written since the last take; false if none were.
  bool take(ActuatorFrame& commands) {
    if (!written_) return false;
    commands = commands_;
    written_ = false;
    return true;
  }

  bool read(SensorFrame& out) override {
    out = sensors_;
    return true;
  }
  void write(const ActuatorFrame& in) override {
    commands_ = in;
    written_ = true;
  }
  double period() const override { return period_; }
  std::string name() const override { return name_; }

 private:
  double period_;
  std::string name_;
  SensorFrame sensors_;
  ActuatorFrame commands_;
  bool written_ = false;
};

}  // namespace stride::hal
