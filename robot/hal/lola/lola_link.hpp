#pragma once
// The robot's end of LoLA as a HardwareLink: reads each sensor packet from the unix socket and
// answers it with the frame's commands. A packet that does not decode is answered with the last
// command (the frame is held) and counted; no valid packet for two periods, or the socket gone,
// and read() returns false with state() saying which. Every write has a deadline of one period:
// a peer that stops reading closes the link (the stream may hold part of an answer) instead of
// blocking the control loop.
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "robot/hal/hardware_link.hpp"
#include "robot/hal/lola/packet_stream.hpp"
#include "robot/hal/unix_socket.hpp"

namespace stride::hal::lola {

struct LolaLinkStats {
  std::int64_t packets = 0;         // sensor packets received, good or bad
  std::int64_t bad_packets = 0;     // held: wrong size, type, key, or a value not finite
  std::int64_t stale_skipped = 0;   // older packets dropped because a newer one was waiting
  std::int64_t torque_refused = 0;  // frames that asked for torque mode (held instead)
  std::int64_t stalls = 0;          // times two periods passed without a valid packet
  std::int64_t reconnects = 0;
  std::int64_t unsent_answers = 0;  // answers the peer did not take within a period (link closed)
  std::string first_error;          // the first bad packet or refused frame, one line
};

// The time of packet `index` (from 0) as LoLA implies it: it sends no clock, each packet is one
// period. From 0 like a simulated robot's frames, so timed changes fall on the same frame.
inline double lola_frame_time(std::int64_t index, double period) {
  return static_cast<double>(index) * period;
}

class LolaLink final : public HardwareLink {
 public:
  // Connects to the LoLA socket at `path`; throws stride::Error naming it.
  explicit LolaLink(std::string path, double period);
  // The same, trying again until `timeout` seconds passed (LoLA may still be starting).
  static std::unique_ptr<LolaLink> connect(const std::string& path, double period, double timeout);

  bool read(SensorFrame& out) override;
  // Encodes and sends the answer to the packet last read. A frame that commands torque mode is
  // refused: the last command is sent instead, and the refusal counted (stats().first_error).
  void write(const ActuatorFrame& in) override;
  // Answers the packet last read with an empty map: LoLA keeps every command as it was.
  void write_nothing();
  double period() const override { return period_; }
  std::string name() const override { return "LoLA " + path_; }

  enum class State { Connected, Stalled, Closed };
  State state() const { return state_; }
  // Why the link is Closed, for the lost-link line: "socket closed", or the peer stopped reading.
  const std::string& closed_because() const { return closed_because_; }
  // One attempt to connect again after the socket closed; true when connected.
  bool reconnect();
  // Seconds since the last valid sensor packet arrived (since connecting, before the first).
  double since_last_packet() const;
  const LolaLinkStats& stats() const { return stats_; }
  // True once after each new event worth a report line (a bad packet, a refusal); `frame` is
  // the index of the packet it concerns.
  bool take_new_error(std::string& line, std::int64_t& frame);

 private:
  bool answer(const ActuatorFrame& frame);
  bool send(std::span<const char> bytes);  // false: the link is closed now (closed_because())
  void close(std::string why);
  void record_error(const std::string& line);

  std::string path_;
  double period_;
  UnixSocket socket_;
  PacketStream stream_;
  std::string out_;  // encoded answer, reused
  ActuatorFrame last_sent_{};
  bool have_sent_ = false;
  bool reading_ = false;  // read() was called: before, building the controller is not silence
  State state_ = State::Connected;
  std::string closed_because_;
  std::chrono::steady_clock::time_point last_packet_;
  LolaLinkStats stats_;
  std::string new_error_;
  std::int64_t new_error_frame_ = 0;
};

}  // namespace stride::hal::lola
