#pragma once
// The simulator's end of the restart side channel (robot/hal/lola/simulator_restart.hpp): a LoLA
// client whose controller restarts asks, and the run puts its scene back at the start.
#include <optional>
#include <string>

#include "robot/hal/unix_socket.hpp"

namespace stride::sim {

class LolaRestartListener {
 public:
  // Listens beside the LoLA socket `lola_socket`; throws stride::Error naming the path.
  explicit LolaRestartListener(const std::string& lola_socket);

  // True once per "restart" a client sent; never blocks (one poll when nobody asks).
  bool take_request();
  // Tells the asker its robot is back at the start (before the next LoLA packet is sent).
  void answer_done();

 private:
  hal::UnixListener listener_;
  std::optional<hal::UnixSocket> asker_;
  std::string got_;
};

}  // namespace stride::sim
