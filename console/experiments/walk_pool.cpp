#include "console/experiments/walk_pool.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <thread>

#include "console/experiments/recording_codec.hpp"
#include "robot/core/error.hpp"

namespace stride::experiments {
namespace {

enum class Kind : char { Recording = 'R', Failure = 'E' };

// Moves all n bytes through read(2) or write(2), retrying short transfers and signals.
template <class Transfer, class Pointer>
bool transfer_all(Transfer transfer, int fd, Pointer data, std::size_t n) {
  while (n > 0) {
    const ssize_t k = transfer(fd, data, n);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    data += k;
    n -= static_cast<std::size_t>(k);
  }
  return true;
}

bool write_all(int fd, const char* data, std::size_t n) {
  return transfer_all(::write, fd, data, n);
}

bool read_all(int fd, char* data, std::size_t n) {
  return transfer_all(::read, fd, data, n);
}

// One message: kind, byte count, bytes.
bool send(int fd, Kind kind, const std::string& bytes) {
  const std::uint64_t n = bytes.size();
  return write_all(fd, reinterpret_cast<const char*>(&kind), 1) &&
         write_all(fd, reinterpret_cast<const char*>(&n), sizeof n) &&
         write_all(fd, bytes.data(), bytes.size());
}

// The worker's side: walks first, first + stride, ...; never returns.
[[noreturn]] void work(int fd, const std::vector<WalkSetup>& setups, std::size_t first,
                       std::size_t stride) {
  for (std::size_t i = first; i < setups.size(); i += stride) {
    bool sent;
    try {
      sent = send(fd, Kind::Recording, encode_recording(record_walk(setups[i])));
    } catch (const std::exception& e) {
      sent = send(fd, Kind::Failure, e.what());
    }
    if (!sent) break;  // the experiment stopped listening
  }
  ::close(fd);
  std::_Exit(0);  // no atexit handlers or static destructors of the parent's copy
}

struct Worker {
  pid_t pid = -1;
  int fd = -1;
};

// Ends whatever workers are still running, also when the experiment throws.
class Workers {
 public:
  ~Workers() {
    for (Worker& w : list) {
      if (w.fd >= 0) ::close(w.fd);
      if (w.pid > 0) {
        ::kill(w.pid, SIGKILL);
        ::waitpid(w.pid, nullptr, 0);
      }
    }
  }
  std::vector<Worker> list;
};

std::string walk_name(const WalkSetup& s) {
  return s.scene + " (seed " + std::to_string(s.seed) + ")";
}

}  // namespace

int default_jobs() {
  const unsigned n = std::thread::hardware_concurrency();
  return n > 0 ? static_cast<int>(n) : 1;
}

void record_walks(const std::vector<WalkSetup>& setups, int jobs,
                  const std::function<bool(std::size_t, WalkRecording&&)>& use) {
  const std::size_t workers = std::min<std::size_t>(jobs > 1 ? jobs : 1, setups.size());
  if (workers <= 1) {
    for (std::size_t i = 0; i < setups.size(); ++i)
      if (!use(i, record_walk(setups[i]))) return;
    return;
  }
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);  // a forked copy must not print the parent's buffered output again
  Workers pool;
  for (std::size_t w = 0; w < workers; ++w) {
    int fds[2];
    if (::pipe(fds) != 0) throw Error(std::string("experiment workers: pipe: ") + strerror(errno));
    const pid_t pid = ::fork();
    if (pid < 0) {
      ::close(fds[0]);
      ::close(fds[1]);
      throw Error(std::string("experiment workers: fork: ") + strerror(errno));
    }
    if (pid == 0) {
      ::close(fds[0]);
      for (const Worker& other : pool.list) ::close(other.fd);
      work(fds[1], setups, w, workers);
    }
    ::close(fds[1]);
    pool.list.push_back({pid, fds[0]});
  }
  for (std::size_t i = 0; i < setups.size(); ++i) {
    const Worker& w = pool.list[i % workers];
    Kind kind;
    std::uint64_t n = 0;
    std::string bytes;
    bool ok = read_all(w.fd, reinterpret_cast<char*>(&kind), 1) &&
              read_all(w.fd, reinterpret_cast<char*>(&n), sizeof n);
    if (ok) {
      bytes.resize(n);
      ok = read_all(w.fd, bytes.data(), n);
    }
    if (!ok)
      throw Error("experiment: the worker process for walk " + walk_name(setups[i]) +
                  " ended without a result");
    if (kind == Kind::Failure) throw Error(bytes);
    if (!use(i, decode_recording(bytes))) return;
  }
}

}  // namespace stride::experiments
