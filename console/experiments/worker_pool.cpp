#include "console/experiments/worker_pool.hpp"

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

#include "robot/core/error.hpp"

namespace stride::experiments {
namespace {

enum class Kind : char { Result = 'R', Failure = 'E' };

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

// The worker's side: jobs first, first + stride, ...; never returns.
[[noreturn]] void work(int fd, std::size_t n,
                       const std::function<std::string(std::size_t)>& produce, std::size_t first,
                       std::size_t stride) {
  for (std::size_t i = first; i < n; i += stride) {
    bool sent;
    try {
      sent = send(fd, Kind::Result, produce(i));
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

}  // namespace

int default_jobs() {
  const unsigned n = std::thread::hardware_concurrency();
  return n > 0 ? static_cast<int>(n) : 1;
}

namespace {

// A worker for jobs first, first + stride, ...; its pipe's read end and pid.
Worker spawn_worker(std::size_t n, const std::function<std::string(std::size_t)>& produce,
                    std::size_t first, std::size_t stride, const Workers& pool) {
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
    work(fds[1], n, produce, first, stride);
  }
  ::close(fds[1]);
  return {pid, fds[0]};
}

// Reads the next message from a worker; false if it ended without one.
bool receive(const Worker& w, Kind& kind, std::string& bytes) {
  std::uint64_t n = 0;
  if (!read_all(w.fd, reinterpret_cast<char*>(&kind), 1) ||
      !read_all(w.fd, reinterpret_cast<char*>(&n), sizeof n))
    return false;
  bytes.resize(n);
  return read_all(w.fd, bytes.data(), n);
}

// How a worker that sent nothing more ended, for the failed job's reason.
std::string worker_end(Worker& w) {
  ::close(w.fd);
  w.fd = -1;
  int status = 0;
  const pid_t done = ::waitpid(w.pid, &status, 0);
  w.pid = -1;
  if (done > 0 && WIFSIGNALED(status))
    return "its worker process was killed by signal " + std::to_string(WTERMSIG(status));
  return "its worker process ended without a result";
}

}  // namespace

void run_in_workers(std::size_t n, int jobs, const std::function<std::string(std::size_t)>& produce,
                    const std::function<bool(std::size_t, std::string&&)>& use,
                    const std::function<std::string(std::size_t)>& name, const Failed& failed) {
  const auto fail = [&](std::size_t i, const std::string& reason) {
    if (!failed) throw Error(reason);
    failed(i, reason);
  };
  const std::size_t workers = std::min<std::size_t>(jobs > 1 ? jobs : 1, n);
  if (workers <= 1) {
    for (std::size_t i = 0; i < n; ++i) {
      std::string bytes;
      try {
        bytes = produce(i);
      } catch (const std::exception& e) {  // Error, bad_alloc: the job fails, not the run
        if (!failed) throw;
        fail(i, e.what());
        continue;
      }
      if (!use(i, std::move(bytes))) return;
    }
    return;
  }
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);  // a forked copy must not print the parent's buffered output again
  Workers pool;
  for (std::size_t w = 0; w < workers; ++w)
    pool.list.push_back(spawn_worker(n, produce, w, workers, pool));
  for (std::size_t i = 0; i < n; ++i) {
    Worker& w = pool.list[i % workers];
    Kind kind;
    std::string bytes;
    if (!receive(w, kind, bytes)) {
      const std::string why = worker_end(w);
      fail(i, "experiment: " + name(i) + ": " + why);
      // A fresh worker takes over the jobs this one had still to do.
      if (i + workers < n) w = spawn_worker(n, produce, i + workers, workers, pool);
      continue;
    }
    if (kind == Kind::Failure) {
      fail(i, bytes);
      continue;
    }
    if (!use(i, std::move(bytes))) return;
  }
}

}  // namespace stride::experiments
