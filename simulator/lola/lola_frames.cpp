#include "simulator/lola/lola_frames.hpp"

#include "robot/hal/lola/actuator_packet.hpp"
#include "robot/hal/lola/lola_protocol.hpp"
#include "robot/hal/lola/sensor_packet.hpp"

namespace stride::sim {

void simulated_sensor_packet(const hal::SensorFrame& s, std::string& out) {
  hal::lola::encode_sensor_packet(s, hal::lola::kSimulatedRobotConfig, out);
}

void apply_lola_answer(std::span<const char> packet, hal::ActuatorFrame& commands) {
  const hal::lola::ActuatorCommand c = hal::lola::decode_actuator_packet(packet);
  hal::lola::apply_actuator_command(c, commands);
}

}  // namespace stride::sim
