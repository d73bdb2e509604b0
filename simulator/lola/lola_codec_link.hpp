#pragma once
// An in-process link through LoLA's packets, around a simulated NAO's link (the frames the
// simulation hands its controller): its sensors go through the 896-byte sensor packet and its
// commands through the actuator packet, encoded and decoded by the same
// code as the two ends of the socket (float32 values, LoLA's signs and units, LoLA's clock of one
// period per packet). A controller run over this link is what a lockstep run of `stride robot`
// against `stride run --lola` must equal bit for bit: the process boundary then changes nothing.
#include <cstdint>
#include <string>

#include "robot/hal/hardware_link.hpp"

namespace stride::sim {

class LolaCodecLink final : public hal::HardwareLink {
 public:
  // `commands`: what the robot's servos follow before the first answer (an answer's keys replace
  // only those it gives, as on the robot).
  LolaCodecLink(hal::HardwareLink& inner, const hal::ActuatorFrame& commands);

  bool read(hal::SensorFrame& out) override;
  // Throws stride::Error for a frame that commands torque mode (LoLA takes none).
  void write(const hal::ActuatorFrame& in) override;
  double period() const override { return inner_.period(); }
  std::string name() const override { return inner_.name() + " through LoLA packets"; }

 private:
  hal::HardwareLink& inner_;
  hal::SensorFrame sensors_;
  std::string packet_;
  std::int64_t packets_ = 0;
  hal::ActuatorFrame commands_;
};

}  // namespace stride::sim
