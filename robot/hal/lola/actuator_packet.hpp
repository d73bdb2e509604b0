#pragma once
// LoLA's actuator packet <-> ActuatorFrame. LoLA takes positions and stiffness only (no torque
// mode); RHipYawPitch has no entry: the robot's one motor follows LHipYawPitch.
#include <array>
#include <optional>
#include <span>
#include <string>

#include <msgpack.hpp>

#include "robot/hal/actuator_frame.hpp"

namespace stride::hal::lola {

// The full actuator map (every key, LEDs off, sonar on): 786 bytes. Throws stride::Error naming
// the first joint that commands torque mode, and writes nothing then.
void encode_actuator_packet(const ActuatorFrame& a, std::string& out);

// What a client sent: LoLA accepts any subset of the keys.
struct ActuatorCommand {
  std::optional<std::array<double, kNumJoints>> position;
  std::optional<std::array<double, kNumJoints>> stiffness;
};

// Every key checked (known, once, right type and length, finite); throws stride::Error
// ("LoLA actuator packet: <key>: ...").
ActuatorCommand decode_actuator_packet(std::span<const char> packet);
ActuatorCommand decode_actuator_map(const msgpack::object& map);

// The command as the servos take it: given keys replace those of `frame`, in Position mode.
void apply_actuator_command(const ActuatorCommand& c, ActuatorFrame& frame);

}  // namespace stride::hal::lola
