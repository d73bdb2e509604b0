#include "robot/debug/server.hpp"

#include <sys/eventfd.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>

#include "robot/core/thread_priority.hpp"
#include "robot/debug/server_thread.hpp"

namespace stride::debug {

DebugServer::DebugServer(ServerOptions options)
    : options_(std::move(options)), loop_(exchange_, options_.robot, options_.keep_debug_output) {
  if (options_.tokens.empty() && !is_loopback(options_.listen))
    throw Error("debug server on " + options_.listen.text() +
                ": an address other than loopback needs a token (--token-file or STRIDE_TOKEN)");
  if (!options_.log) options_.log = [](const std::string& line) { std::cerr << line << "\n"; };
  Fd listener = listen_tcp(options_.listen, bound_);
  Fd wake(::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC));
  if (!wake) throw Error(std::string("eventfd: ") + std::strerror(errno));
  wake_fd_ = wake.get();
  thread_state_ =
      std::make_unique<ServerThread>(options_, exchange_, std::move(listener), std::move(wake));
  thread_ = std::thread([this] {
    set_normal_priority();  // never at the control loop's real-time priority
    thread_state_->run(stop_);
  });
}

DebugServer::~DebugServer() {
  stop_.store(true, std::memory_order_release);
  const std::uint64_t one = 1;
  [[maybe_unused]] const auto n = ::write(wake_fd_, &one, sizeof one);
  if (thread_.joinable()) thread_.join();
}

ServerStats DebugServer::stats() const {
  return thread_state_->stats();
}

}  // namespace stride::debug
