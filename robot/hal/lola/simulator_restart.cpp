#include "robot/hal/lola/simulator_restart.hpp"

#include <sys/stat.h>

#include <array>
#include <chrono>

#include "robot/core/error.hpp"

namespace stride::hal::lola {

std::optional<SimulatorRestart> SimulatorRestart::ask(const std::string& lola_socket) {
  const std::string path = simulator_restart_path(lola_socket);
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISSOCK(st.st_mode)) return std::nullopt;
  try {
    UnixSocket s = UnixSocket::connect(path);
    const std::string line = "restart\n";
    if (!s.send_all(line)) return std::nullopt;
    return SimulatorRestart(std::move(s));
  } catch (const Error&) {
    return std::nullopt;  // a stale socket file: nobody to ask
  }
}

bool SimulatorRestart::done() {
  if (got_.find("done\n") != std::string::npos) return true;
  std::array<char, 64> buffer{};
  while (socket_.open() &&
         socket_.wait_readable(std::chrono::steady_clock::now()) == UnixSocket::Wait::Readable) {
    const long n = socket_.receive(buffer);
    if (n <= 0) {
      socket_.close();  // closed before saying done: nothing more will come
      break;
    }
    if (got_.size() < 64) got_.append(buffer.data(), static_cast<std::size_t>(n));
  }
  return got_.find("done\n") != std::string::npos;
}

}  // namespace stride::hal::lola
