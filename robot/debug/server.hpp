#pragma once
// The debug server of one robot runtime (docs/architecture.md "The physical robot"): TCP,
// length-prefixed msgpack (protocol.hpp), one thread of its own. Attach it to the runtime and the
// loop exchanges with it only between frames:
//
//   DebugServer server(options);             // listens; throws stride::Error (one line)
//   runtime.set_frame_boundary(&server.boundary());
//   while (runtime.step()) {}                // requests are applied at frame boundaries
//
// Loopback needs no token; any other address refuses to start without one.
#include <atomic>
#include <memory>
#include <thread>

#include "robot/debug/exchange.hpp"
#include "robot/debug/loop_side.hpp"
#include "robot/debug/server_options.hpp"

namespace stride::debug {

class ServerThread;

class DebugServer {
 public:
  explicit DebugServer(ServerOptions options);
  ~DebugServer();
  DebugServer(const DebugServer&) = delete;
  DebugServer& operator=(const DebugServer&) = delete;

  const Endpoint& endpoint() const { return bound_; }  // with the port really bound
  FrameBoundary& boundary() { return loop_; }
  // Applies waiting requests while the runtime is not stepping (e.g. a paused console).
  void idle(Runtime& runtime) { loop_.idle(runtime); }
  // With ServerOptions::keep_debug_output: what the runtime's debug requests printed since the
  // last call (the loop side takes it from the runtime after every frame).
  DebugText take_kept_debug_output() { return loop_.take_kept_debug_output(); }
  // The owner of the loop restarts its scenario when this returns true (after allow_restart()).
  void allow_restart() { loop_.allow_restart(); }
  bool take_restart() { return loop_.take_restart(); }
  ServerStats stats() const;

 private:
  ServerOptions options_;
  Endpoint bound_;
  Exchange exchange_;
  LoopSide loop_;
  std::unique_ptr<ServerThread> thread_state_;
  int wake_fd_ = -1;  // the server thread's eventfd (it owns it): stopping wakes it at once
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace stride::debug
