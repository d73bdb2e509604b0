#include "simulator/lola/lola_server.hpp"

#include <ostream>
#include <sstream>
#include <thread>

#include "robot/core/error.hpp"
#include "robot/framework/enum_names.hpp"
#include "robot/hal/lola/lola_protocol.hpp"
#include "simulator/lola/lola_frames.hpp"

namespace stride::sim {
namespace {

std::chrono::steady_clock::duration seconds(double s) {
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(s));
}

}  // namespace

LolaServer::LolaServer(const std::string& path, LolaPacing pacing, const SimulatedRobot& robot,
                       std::ostream& events)
    : listener_(path), commands_(robot.latest_commands()), events_(events) {
  report_.socket = path;
  report_.robot = robot.name();
  report_.pacing = pacing;
  report_.period = robot.period();
  packet_.reserve(1024);
}

void LolaServer::event(double time, const std::string& what) {
  std::ostringstream o;
  o.setf(std::ios::fixed);
  o.precision(3);
  o << "t " << time << " s, frame " << report_.frames << ": " << what;
  report_.events.push_back(o.str());
  events_ << "lola: " << o.str() << std::endl;
}

void LolaServer::wait_for_client(double timeout) {
  client_ = listener_.accept(Clock::now() + seconds(timeout));
  if (!client_)
    throw Error("lola: no client connected to '" + listener_.path() + "' within " +
                std::to_string(static_cast<int>(timeout)) + " s");
  ++report_.clients;
  event(0, "client connected");
}

void LolaServer::restarted(const SimulatedRobot& robot) {
  commands_ = robot.latest_commands();
  event(robot.latest_sensors().time, "scene back at its start (the client's controller restarted)");
}

void LolaServer::lose_client(double time, const std::string& why) {
  client_.reset();
  stream_.clear();
  ++report_.clients_lost;
  event(time, "client lost (" + why + "); robot '" + report_.robot + "' holds its last command");
}

// Answers that arrived after their frame's deadline: the robot's latest wish, applied now.
bool LolaServer::drain_late_answers() {
  for (;;) {
    std::span<const char> packet;
    std::string error;
    const auto r = stream_.next(packet, error);
    if (r == hal::lola::PacketStream::Result::Packet) {
      ++report_.late_answers;
      try {
        apply_lola_answer(packet, commands_);
        answered_ = true;
      } catch (const Error&) {
        ++report_.bad_packets;
      }
      continue;
    }
    if (r == hal::lola::PacketStream::Result::Malformed) {
      ++report_.bad_packets;
      continue;
    }
    if (client_->wait_readable(Clock::now()) != hal::UnixSocket::Wait::Readable) return true;
    const long n = client_->receive(stream_.reserve(hal::lola::kMaxPacketSize));
    if (n == 0 || n == -1) return false;
    if (n > 0) stream_.commit(static_cast<std::size_t>(n));
  }
}

// Waits for this frame's answer until `deadline`; false when the client is gone.
bool LolaServer::take_answer(double time, hal::Deadline deadline) {
  for (;;) {
    std::span<const char> packet;
    std::string error;
    const auto r = stream_.next(packet, error);
    if (r == hal::lola::PacketStream::Result::Packet) {
      try {
        apply_lola_answer(packet, commands_);
        answered_ = true;
        ++report_.exchanged;
      } catch (const Error& e) {
        if (report_.bad_packets++ == 0) event(time, e.what());
        if (report_.pacing == LolaPacing::Realtime) ++report_.missed;
      }
      return true;
    }
    if (r == hal::lola::PacketStream::Result::Malformed) {
      if (report_.bad_packets++ == 0) event(time, "LoLA actuator packet: " + error);
      if (report_.pacing == LolaPacing::Realtime) ++report_.missed;
      return true;
    }
    const auto wait = client_->wait_readable(deadline);
    if (wait == hal::UnixSocket::Wait::Timeout) {
      if (report_.pacing == LolaPacing::Realtime) {
        ++report_.missed;
        return true;
      }
      lose_client(
          time, "no answer for " + std::to_string(static_cast<int>(kLockstepAnswerTimeout)) + " s");
      return true;
    }
    if (wait == hal::UnixSocket::Wait::Interrupted) continue;
    const long n = client_->receive(stream_.reserve(hal::lola::kMaxPacketSize));
    if (n == -2) continue;
    if (n <= 0) return false;
    stream_.commit(static_cast<std::size_t>(n));
  }
}

bool LolaServer::control_frame(const hal::SensorFrame& sensors, hal::ActuatorFrame& commands) {
  answered_ = false;
  exchange(sensors);
  if (answered_) commands = commands_;
  return answered_;
}

void LolaServer::exchange(const hal::SensorFrame& sensors) {
  const double time = sensors.time;
  const bool realtime = report_.pacing == LolaPacing::Realtime;
  Clock::time_point due = Clock::now();
  if (realtime) {
    if (!start_) start_ = Clock::now() - seconds(report_.frames * report_.period);
    due = *start_ + seconds(report_.frames * report_.period);
    if (Clock::now() < due)
      std::this_thread::sleep_until(due);
    else if (Clock::now() > due + seconds(report_.period / 2))
      ++report_.late_frames;
  }
  ++report_.frames;
  if (!client_) {
    if ((client_ = listener_.accept(Clock::now()))) {
      ++report_.clients;
      event(time, "client connected");
    } else {
      ++report_.without_client;
      return;
    }
  }
  if (realtime && !drain_late_answers()) return lose_client(time, "it closed the socket");
  simulated_sensor_packet(sensors, packet_);
  const auto deadline =
      realtime ? due + seconds(report_.period) : Clock::now() + seconds(kLockstepAnswerTimeout);
  // Bounded like the robot's writes: a robot that stopped reading (SIGSTOP) never blocks the world.
  switch (client_->send_until(packet_, deadline)) {
    case hal::UnixSocket::Send::Closed:
      return lose_client(time, "it closed the socket");
    case hal::UnixSocket::Send::Timeout:
      return lose_client(time, "it stopped reading");
    case hal::UnixSocket::Send::Sent:
      break;
  }
  if (!take_answer(time, deadline)) lose_client(time, "it closed the socket");
}

std::string lola_report_text(const LolaServeReport& r) {
  std::ostringstream o;
  o << "lola " << r.socket << " (robot " << r.robot << ", " << enum_name(r.pacing) << ", "
    << r.period * 1e3 << " ms): " << r.frames << " frames, " << r.exchanged << " exchanged, "
    << r.missed << " missed, " << r.bad_packets << " bad packets";
  if (r.pacing == LolaPacing::Realtime)
    o << ", " << r.late_answers << " late answers, " << r.late_frames << " sent late";
  o << ", " << r.without_client << " without a client, " << r.clients << " client"
    << (r.clients == 1 ? "" : "s") << " (" << r.clients_lost << " lost)";
  return o.str();
}

}  // namespace stride::sim
