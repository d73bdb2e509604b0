#include "simulator/lola/lola_restart_listener.hpp"

#include <array>
#include <chrono>

#include "robot/hal/lola/simulator_restart.hpp"

namespace stride::sim {

LolaRestartListener::LolaRestartListener(const std::string& lola_socket)
    : listener_(hal::lola::simulator_restart_path(lola_socket)) {}

bool LolaRestartListener::take_request() {
  const auto now = std::chrono::steady_clock::now();
  if (!asker_) {
    asker_ = listener_.accept(now);
    got_.clear();
    if (!asker_) return false;
  }
  std::array<char, 64> buffer{};
  while (asker_->wait_readable(now) == hal::UnixSocket::Wait::Readable) {
    const long n = asker_->receive(buffer);
    if (n <= 0) {  // gone before asking
      asker_.reset();
      return false;
    }
    if (got_.size() < 64) got_.append(buffer.data(), static_cast<std::size_t>(n));
  }
  if (got_.find("restart\n") != std::string::npos) return true;
  if (got_.size() >= 64) asker_.reset();  // not this channel's words: dropped
  return false;
}

void LolaRestartListener::answer_done() {
  if (!asker_) return;
  const std::string line = "done\n";
  asker_->send_until(line, std::chrono::steady_clock::now() + std::chrono::milliseconds(100));
  asker_.reset();
}

}  // namespace stride::sim
