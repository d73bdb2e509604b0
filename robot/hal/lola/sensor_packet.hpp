#pragma once
// LoLA's sensor packet <-> SensorFrame. The packet holds LoLA's raw values (accelerometer z
// reversed, FSRs in kg, float32); the SensorFrame holds SI units in the torso frame.
#include <span>
#include <string_view>
#include <string>

#include <msgpack.hpp>

#include "robot/hal/sensor_frame.hpp"

namespace stride::hal::lola {

// The packet as LoLA writes it (keys in LoLA's order), with `robot_config` as its RobotConfig
// strings; `out` is replaced. 896 bytes with a NAO v6's (or the simulator's) strings.
void encode_sensor_packet(const SensorFrame& s,
                          const std::array<std::string_view, 4>& robot_config, std::string& out);
// The same with the frame's own robot_config strings.
void encode_sensor_packet(const SensorFrame& s, std::string& out);

// Every key decoded and checked. Throws stride::Error ("LoLA sensor packet: <key>: ...") and
// leaves `out` untouched on a packet of the wrong size, a missing, repeated or unknown key, a
// wrong type or length, or a value that is not finite. `out.time` is kept (LoLA sends none).
// Allocates nothing once `out`'s strings have held a robot's ids.
void decode_sensor_packet(std::span<const char> packet, SensorFrame& out);
// The same for a map already unpacked from a packet of `size` bytes.
void decode_sensor_map(const msgpack::object& map, std::size_t size, SensorFrame& out);

// LoLA's accelerometer reading of a torso-frame specific force, and back.
std::array<double, 3> lola_accelerometer(const std::array<double, 3>& torso);
std::array<double, 3> torso_accelerometer(const std::array<double, 3>& lola);

}  // namespace stride::hal::lola
