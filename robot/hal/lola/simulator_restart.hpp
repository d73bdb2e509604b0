#pragma once
// A side channel beside LoLA that only the simulator serves: `stride run <scene> --lola S` listens
// at S + ".restart", so that when `stride robot` restarts its controller the simulated NAO goes
// back to its scene's start too and a walk can be watched again from the beginning. Not LoLA: a
// NAO v6 has no such socket, and there a restart is the controller's alone.
//   robot -> simulator: "restart\n"     simulator -> robot: "done\n" (then closes)
// The simulator writes "done" before it sends the first LoLA packet of the restarted scene, so a
// robot that sees "done" after reading a packet knows every later packet is of the new start.
#include <optional>
#include <string>

#include "robot/hal/unix_socket.hpp"

namespace stride::hal::lola {

inline std::string simulator_restart_path(const std::string& lola_socket) {
  return lola_socket + ".restart";
}

class SimulatorRestart {
 public:
  // Asks the simulator behind `lola_socket` to put the robot back at its start; nullopt when
  // nothing listens there (a NAO, or a simulator from before the channel).
  static std::optional<SimulatorRestart> ask(const std::string& lola_socket);
  // True once the simulator said it did; never blocks.
  bool done();

 private:
  explicit SimulatorRestart(UnixSocket s) : socket_(std::move(s)) {}
  UnixSocket socket_;
  std::string got_;
};

}  // namespace stride::hal::lola
