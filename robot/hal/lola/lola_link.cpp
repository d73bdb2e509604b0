#include "robot/hal/lola/lola_link.hpp"

#include <cmath>
#include <thread>

#include "robot/core/error.hpp"
#include "robot/hal/lola/actuator_packet.hpp"
#include "robot/hal/lola/lola_protocol.hpp"
#include "robot/hal/lola/sensor_packet.hpp"

namespace stride::hal::lola {
namespace {

using Clock = std::chrono::steady_clock;

Clock::duration periods(double n, double period) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(n * period));
}

constexpr char kEmptyMap[] = {'\x80'};  // an answer that changes nothing (LoLA takes subsets)

}  // namespace

LolaLink::LolaLink(std::string path, double period)
    : path_(std::move(path)),
      period_(period),
      socket_(UnixSocket::connect(path_)),
      last_packet_(Clock::now()) {
  if (!(period_ > 0)) throw Error("LoLA: period must be > 0 s");
  out_.reserve(1024);
}

std::unique_ptr<LolaLink> LolaLink::connect(const std::string& path, double period,
                                            double timeout) {
  const auto give_up = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                          std::chrono::duration<double>(timeout));
  for (;;) {
    try {
      return std::make_unique<LolaLink>(path, period);
    } catch (const Error&) {
      if (Clock::now() >= give_up) throw;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

void LolaLink::write_nothing() {
  if (state_ != State::Closed) send(kEmptyMap);
}

void LolaLink::close(std::string why) {
  state_ = State::Closed;
  closed_because_ = std::move(why);
  socket_.close();
}

bool LolaLink::send(std::span<const char> bytes) {
  // One period: the answer is due before LoLA's next packet, and a full buffer means a peer that
  // has not read for many frames.
  switch (socket_.send_until(bytes, Clock::now() + periods(1, period_))) {
    case UnixSocket::Send::Sent:
      return true;
    case UnixSocket::Send::Timeout:
      ++stats_.unsent_answers;
      close("the peer took no answer for " + std::to_string(std::lround(period_ * 1e3)) +
            " ms: it stopped reading");
      return false;
    case UnixSocket::Send::Closed:
      break;
  }
  close("socket closed");
  return false;
}

bool LolaLink::reconnect() {
  try {
    socket_ = UnixSocket::connect(path_);
  } catch (const Error&) {
    return false;
  }
  stream_.clear();
  state_ = State::Connected;
  closed_because_.clear();
  last_packet_ = Clock::now();
  ++stats_.reconnects;
  return true;
}

double LolaLink::since_last_packet() const {
  return std::chrono::duration<double>(Clock::now() - last_packet_).count();
}

void LolaLink::record_error(const std::string& line) {
  if (stats_.first_error.empty()) stats_.first_error = line;
  new_error_ = line;
  new_error_frame_ = stats_.packets - 1;
}

bool LolaLink::take_new_error(std::string& line, std::int64_t& frame) {
  if (new_error_.empty()) return false;
  frame = new_error_frame_;
  line.swap(new_error_);
  new_error_.clear();
  return true;
}

bool LolaLink::answer(const ActuatorFrame& frame) {
  if (!have_sent_) return send(kEmptyMap);
  encode_actuator_packet(frame, out_);
  return send(out_);
}

bool LolaLink::read(SensorFrame& out) {
  if (state_ == State::Closed) return false;
  if (stats_.packets == 0 && !reading_) last_packet_ = Clock::now();  // silence counts from here
  reading_ = true;
  // Two periods after the last valid packet; while stalled, look again every period.
  const auto deadline = state_ == State::Stalled ? Clock::now() + periods(1, period_)
                                                 : last_packet_ + periods(2, period_);
  for (;;) {
    std::span<const char> packet, newest;
    std::string error;
    PacketStream::Result r;
    while ((r = stream_.next(packet, error)) == PacketStream::Result::Packet) {
      if (!newest.empty()) ++stats_.stale_skipped;
      newest = packet;
      ++stats_.packets;
    }
    if (r == PacketStream::Result::Malformed) {
      ++stats_.packets;
      ++stats_.bad_packets;
      record_error("LoLA sensor packet: " + error);
      newest = {};
      answer(last_sent_);
    }
    if (!newest.empty()) {
      try {
        decode_sensor_packet(newest, out);
        out.time = lola_frame_time(stats_.packets - 1, period_);
        last_packet_ = Clock::now();
        state_ = State::Connected;
        return true;
      } catch (const Error& e) {
        ++stats_.bad_packets;
        record_error(e.what());
        answer(last_sent_);
      }
    }
    if (state_ == State::Closed) return false;
    const auto wait = socket_.wait_readable(deadline);
    if (wait == UnixSocket::Wait::Timeout) {
      if (state_ != State::Stalled) ++stats_.stalls;
      state_ = State::Stalled;
      return false;
    }
    if (wait == UnixSocket::Wait::Interrupted) continue;
    const long n = socket_.receive(stream_.reserve(kMaxPacketSize));
    if (n == -2) continue;
    if (n <= 0) {
      close("socket closed");
      return false;
    }
    stream_.commit(static_cast<std::size_t>(n));
  }
}

void LolaLink::write(const ActuatorFrame& in) {
  if (state_ == State::Closed) return;
  try {
    encode_actuator_packet(in, out_);
  } catch (const Error& e) {  // torque mode: LoLA cannot take it
    ++stats_.torque_refused;
    record_error(e.what());
    answer(last_sent_);
    return;
  }
  last_sent_ = in;
  have_sent_ = true;
  send(out_);
}

}  // namespace stride::hal::lola
