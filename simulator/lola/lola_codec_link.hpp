#pragma once
// A simulated NAO's in-process link through LoLA's packets: its sensors go through the 896-byte
// sensor packet and its commands through the actuator packet, encoded and decoded by the same
// code as the two ends of the socket (float32 values, LoLA's signs and units, LoLA's clock of one
// period per packet). A controller run over this link is what a lockstep run of `stride robot`
// against `stride run --lola` must equal bit for bit: the process boundary then changes nothing.
#include <cstdint>
#include <string>

#include "robot/hal/hardware_link.hpp"
#include "simulator/simulated_robot.hpp"

namespace stride::sim {

class LolaCodecLink final : public hal::HardwareLink {
 public:
  explicit LolaCodecLink(SimulatedRobot& robot);

  bool read(hal::SensorFrame& out) override;
  // Throws stride::Error for a frame that commands torque mode (LoLA takes none).
  void write(const hal::ActuatorFrame& in) override;
  double period() const override { return robot_.period(); }
  std::string name() const override { return robot_.name() + " through LoLA packets"; }

 private:
  SimulatedRobot& robot_;
  std::string packet_;
  std::int64_t packets_ = 0;
  hal::ActuatorFrame commands_;
};

}  // namespace stride::sim
