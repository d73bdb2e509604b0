#pragma once
// A simulated NAO served over a LoLA socket, byte for byte as a NAO v6's LoLA does, so that the
// very `stride robot` binary that goes onto the robot is tested against the simulator.
//   Lockstep: physics advances one control frame per answered packet: deterministic, as fast as
//             both processes allow.
//   Realtime: one packet per period of wall-clock time like the robot; a frame whose answer has
//             not arrived by the next one is missed (the servos keep the previous command).
// A lost client (socket closed, or no answer in lockstep for kLockstepAnswerTimeout) is reported
// at once; the robot holds its last command, and a new client may connect and take over.
#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "robot/framework/reflect.hpp"
#include "robot/hal/frame_controller.hpp"
#include "robot/hal/lola/packet_stream.hpp"
#include "robot/hal/unix_socket.hpp"
#include "simulator/simulated_robot.hpp"

namespace stride::sim {

enum class LolaPacing { Lockstep, Realtime };

}  // namespace stride::sim

template <>
struct stride::EnumNames<stride::sim::LolaPacing> {
  static constexpr std::string_view type_name = "LolaPacing";
  static constexpr std::array<std::string_view, 2> names{"lockstep", "realtime"};
};

namespace stride::sim {

inline constexpr double kLockstepAnswerTimeout = 10.0;  // s

struct LolaServeReport {
  std::string socket, robot;
  LolaPacing pacing = LolaPacing::Lockstep;
  double period = 0;
  std::int64_t frames = 0;          // sensor packets sent
  std::int64_t exchanged = 0;       // frames answered in time by a valid packet
  std::int64_t missed = 0;          // realtime: frames without a valid answer in time
  std::int64_t bad_packets = 0;     // answers that did not decode (the frame held its command)
  std::int64_t late_answers = 0;    // realtime: answers that came after their frame
  std::int64_t late_frames = 0;     // realtime: packets the simulator itself sent late
  std::int64_t without_client = 0;  // frames held while no client was connected
  int clients = 0, clients_lost = 0;
  std::vector<std::string> events;  // connections and losses, as reported
};

class LolaServer final : public hal::FrameController {
 public:
  // Listens at `path` (see hal::UnixListener); `events` gets one line per event as it happens.
  LolaServer(const std::string& path, LolaPacing pacing, const SimulatedRobot& robot,
             std::ostream& events);

  // Blocks until a client connects; throws stride::Error after `timeout` seconds.
  void wait_for_client(double timeout);
  // One control frame of the robot it serves (the Simulation calls it as the robot's controller):
  // the sensors out to the client, the commands its answer gives back (false: none this frame).
  bool control_frame(const hal::SensorFrame& sensors, hal::ActuatorFrame& commands) override;

  // The scene was put back at its start (its client's controller restarted): the commands an
  // empty answer keeps are the restarted robot's own from now on.
  void restarted(const SimulatedRobot& robot);

  const LolaServeReport& report() const { return report_; }

 private:
  using Clock = std::chrono::steady_clock;
  void event(double time, const std::string& what);
  void lose_client(double time, const std::string& why);
  bool drain_late_answers();
  bool take_answer(double time, hal::Deadline deadline);
  void exchange(const hal::SensorFrame& sensors);

  hal::UnixListener listener_;
  std::optional<hal::UnixSocket> client_;
  hal::lola::PacketStream stream_;
  std::string packet_;
  hal::ActuatorFrame commands_;  // the client's latest wish
  bool answered_ = false;        // commands_ changed in this frame
  std::ostream& events_;
  std::optional<Clock::time_point> start_;  // realtime: when frame 0's packet was due
  LolaServeReport report_;
};

// One line for the run report: "lola <socket> lockstep 12 ms: ... frames, ... missed ...".
std::string lola_report_text(const LolaServeReport& r);

}  // namespace stride::sim
