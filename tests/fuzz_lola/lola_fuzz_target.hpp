#pragma once
// One fuzz input for LoLA's packet decoders: the first byte picks the decoder (sensor packet,
// actuator packet, or the byte stream cut into packets), the rest are the bytes a peer sent.
// Any outcome but a stride::Error or success is a bug (the caller sees other exceptions).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "robot/core/error.hpp"
#include "robot/hal/lola/actuator_packet.hpp"
#include "robot/hal/lola/packet_stream.hpp"
#include "robot/hal/lola/sensor_packet.hpp"

namespace stride::test {

// Returns the error message, or "" when everything decoded.
inline std::string decode_lola_fuzz_input(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return "";
  const std::span<const char> bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  std::string first_error;
  try {
    switch (data[0] % 3) {
      case 0: {
        hal::SensorFrame f;
        hal::lola::decode_sensor_packet(bytes, f);
        break;
      }
      case 1:
        hal::lola::decode_actuator_packet(bytes);
        break;
      default: {
        // Received in pieces of 1..64 bytes (sizes from the data): every complete value is
        // decoded as a sensor packet, as LolaLink does.
        hal::lola::PacketStream stream;
        std::size_t at = 0;
        while (at < bytes.size()) {
          const std::size_t n = std::min<std::size_t>(
              bytes.size() - at, 1 + static_cast<unsigned char>(bytes[at]) % 64);
          stream.append(bytes.subspan(at, n));
          at += n;
          std::span<const char> packet;
          std::string error;
          hal::lola::PacketStream::Result r;
          while ((r = stream.next(packet, error)) == hal::lola::PacketStream::Result::Packet) {
            hal::SensorFrame f;
            try {
              hal::lola::decode_sensor_packet(packet, f);
            } catch (const Error& e) {
              if (first_error.empty()) first_error = e.what();
            }
          }
          if (r == hal::lola::PacketStream::Result::Malformed && first_error.empty())
            first_error = "stream: " + error;
        }
      }
    }
  } catch (const Error& e) {
    return e.what();
  }
  return first_error;
}

}  // namespace stride::test
