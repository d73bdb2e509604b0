#include "simulator/lola/lola_codec_link.hpp"

#include "robot/hal/lola/actuator_packet.hpp"
#include "robot/hal/lola/lola_link.hpp"
#include "robot/hal/lola/sensor_packet.hpp"
#include "simulator/lola/lola_frames.hpp"

namespace stride::sim {

LolaCodecLink::LolaCodecLink(hal::HardwareLink& inner, const hal::ActuatorFrame& commands)
    : inner_(inner), commands_(commands) {
  packet_.reserve(1024);
}

bool LolaCodecLink::read(hal::SensorFrame& out) {
  if (!inner_.read(sensors_)) return false;
  simulated_sensor_packet(sensors_, packet_);     // as the server sends it
  hal::lola::decode_sensor_packet(packet_, out);  // as LolaLink receives it
  out.time = hal::lola::lola_frame_time(packets_++, period());
  return true;
}

void LolaCodecLink::write(const hal::ActuatorFrame& in) {
  hal::lola::encode_actuator_packet(in, packet_);  // as LolaLink sends it
  apply_lola_answer(packet_, commands_);           // as the server applies it
  inner_.write(commands_);
}

}  // namespace stride::sim
