#pragma once
// The simulator's side of LoLA's packets, shared by the socket server and the in-process codec
// link so that both put exactly the same bytes between a simulated NAO and its controller.
#include <span>
#include <string>

#include "robot/hal/actuator_frame.hpp"
#include "robot/hal/sensor_frame.hpp"

namespace stride::sim {

// The 896-byte sensor packet of a simulated NAO's frame (the simulator's RobotConfig strings).
void simulated_sensor_packet(const hal::SensorFrame& s, std::string& out);

// Decodes a client's answer and applies it to `commands` (the keys it gives replace those of the
// previous answer, as on the robot). Throws stride::Error naming the key and leaves `commands`
// unchanged on a bad packet.
void apply_lola_answer(std::span<const char> packet, hal::ActuatorFrame& commands);

}  // namespace stride::sim
