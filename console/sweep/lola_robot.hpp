#pragma once
// Robot 0 of a sweep run reached as a NAO is: a started `stride-robot` (built next to `stride`)
// with the run's controller as its robot config, talking LoLA in lockstep over a unix socket in a
// private temporary folder. Everything it starts ends with it: the robot process (SIGTERM, then
// SIGKILL), the socket, the folder. Every failure is one stride::Error line naming the run's
// robot process and what went wrong, so the sweep marks the run failed.
#include <memory>
#include <sstream>
#include <string>

#include "console/system/child_process.hpp"
#include "robot/app/robot_config.hpp"
#include "simulator/lola/lola_server.hpp"

namespace stride::sweep {

class LolaRobot final : public hal::FrameController {
 public:
  // Seconds the robot process gets to connect (a frame's answer: sim::kLockstepAnswerTimeout).
  static constexpr double kConnectTimeout = 30;

  // Writes `config` (its socket and the LoLA period set here), listens, starts the robot process
  // and waits for it to connect. `robot` is the simulated robot it controls.
  LolaRobot(RobotConfig config, const sim::SimulatedRobot& robot);
  ~LolaRobot();
  LolaRobot(const LolaRobot&) = delete;
  LolaRobot& operator=(const LolaRobot&) = delete;

  // One control frame over the socket (the simulation calls it as robot 0's controller); throws
  // when the robot process is gone or answered nothing.
  bool control_frame(const hal::SensorFrame& sensors, hal::ActuatorFrame& commands) override;
  // After the run: throws if any frame went without a valid answer; then ends the robot process.
  void finish();

  const sim::LolaServeReport& report() const { return server_->report(); }

 private:
  std::string failure(const std::string& what);  // "stride-robot (pid N, <socket>): what: ..."
  void wait_for_connection();

  std::string dir_;
  std::ostringstream events_;
  std::unique_ptr<sim::LolaServer> server_;
  std::unique_ptr<console::RunningChild> child_;
};

}  // namespace stride::sweep
