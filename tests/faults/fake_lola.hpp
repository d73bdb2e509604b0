#pragma once
// The test as a NAO's LoLA: a real unix socket the real `stride-robot` connects to, sensor packets
// sent on a wall-clock period, and each frame's answer looked for before the next packet goes, so
// a fault's cost is counted in frames missed (a packet not answered before the next one).
#include <chrono>
#include <optional>
#include <string>
#include <thread>

#include "robot/hal/lola/packet_stream.hpp"
#include "robot/hal/sensor_frame.hpp"
#include "robot/hal/unix_socket.hpp"
#include "simulator/lola/lola_frames.hpp"

namespace stride::test {

struct LolaTally {
  int sent = 0;      // sensor packets written whole
  int answered = 0;  // frames whose answer came before the next packet
  int missed = 0;    // frames without an answer in time
  int answers = 0;   // answers received in all (late ones too)
  bool peer_closed = false;
};

class FakeLola {
 public:
  using Clock = std::chrono::steady_clock;

  explicit FakeLola(const std::string& path) : listener_(path) {
    hal::SensorFrame s;
    s.stiffness.fill(1);
    s.position[hal::index(hal::JointId::LKneePitch)] = 0.6;
    s.position[hal::index(hal::JointId::RKneePitch)] = 0.6;
    sim::simulated_sensor_packet(s, packet_);
  }
  const std::string& packet() const { return packet_; }

  bool accept(double seconds) {
    client_ = listener_.accept(Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                  std::chrono::duration<double>(seconds)));
    return client_.has_value();
  }
  void close() { client_.reset(); }

  // `frames` packets `period` apart, each written in `pieces` parts spread over `spread` s (a peer
  // that sends slowly); with `read` false the answers are never read (a peer that stopped reading).
  LolaTally serve(int frames, double period, bool read = true, int pieces = 1, double spread = 0,
                  const std::string* packet = nullptr) {
    LolaTally t;
    const std::string& p = packet ? *packet : packet_;
    auto due = Clock::now();
    for (int f = 0; f < frames && client_; ++f) {
      const int before = t.answers;
      if (!send(p, pieces, spread, t)) break;
      due += seconds(period);
      if (read) take_answers(due, t);
      if (!read) std::this_thread::sleep_until(due);
      (t.answers > before ? t.answered : t.missed) += 1;
    }
    return t;
  }

  // Packets back to back as fast as the robot's socket takes them, answers read meanwhile.
  LolaTally flood(int packets) {
    LolaTally t;
    for (int f = 0; f < packets && client_; ++f) {
      if (!send(packet_, 1, 0, t)) break;
      take_answers(Clock::now(), t);
    }
    take_answers(Clock::now() + seconds(0.1), t);
    return t;
  }

 private:
  static Clock::duration seconds(double s) {
    return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
  }

  bool send(const std::string& p, int pieces, double spread, LolaTally& t) {
    const std::size_t step = (p.size() + pieces - 1) / pieces;
    for (std::size_t at = 0; at < p.size(); at += step) {
      if (at > 0) std::this_thread::sleep_for(seconds(spread / pieces));
      // Bounded: a robot that stopped reading must not hang the test either.
      if (client_->send_until({p.data() + at, std::min(step, p.size() - at)},
                              Clock::now() + seconds(5)) != hal::UnixSocket::Send::Sent) {
        t.peer_closed = true;
        return false;
      }
    }
    ++t.sent;
    return true;
  }

  // Answers until `until` (at least one look); an answer is any complete map.
  void take_answers(Clock::time_point until, LolaTally& t) {
    for (;;) {
      std::span<const char> answer;
      std::string error;
      while (stream_.next(answer, error) != hal::lola::PacketStream::Result::NeedMore) ++t.answers;
      const auto w = client_->wait_readable(until);
      if (w == hal::UnixSocket::Wait::Timeout) return;
      if (w == hal::UnixSocket::Wait::Interrupted) continue;
      const long n = client_->receive(stream_.reserve(65536));
      if (n <= 0) {
        t.peer_closed = true;
        client_.reset();
        return;
      }
      stream_.commit(static_cast<std::size_t>(n));
    }
  }

  hal::UnixListener listener_;
  std::optional<hal::UnixSocket> client_;
  hal::lola::PacketStream stream_;
  std::string packet_;
};

}  // namespace stride::test
