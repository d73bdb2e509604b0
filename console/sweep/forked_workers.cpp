#include "console/sweep/forked_workers.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "robot/core/error.hpp"

namespace stride::sweep {
namespace {

constexpr std::uint32_t kMaxMessage = 256u << 20;  // a row with a long trace stays far below

// The child's loop: a run index in, its row out, until the coordinator closes the socket.
[[noreturn]] void serve(int fd, const RunFunction& run) {
  ::signal(SIGINT, SIG_IGN);  // Ctrl-C is the coordinator's to handle
  for (;;) {
    std::uint64_t index = 0;
    if (!receive_all(fd, reinterpret_cast<char*>(&index), sizeof index)) break;
    if (!send_message(fd, encode_row(run(static_cast<std::size_t>(index))))) break;
  }
  ::close(fd);
  std::_Exit(0);  // no atexit handlers or static destructors of the coordinator's copy
}

std::string ending(pid_t pid, int status) {
  char text[160];
  if (WIFSIGNALED(status))
    std::snprintf(text, sizeof text, "worker process %d was killed by signal %d (%s)", pid,
                  WTERMSIG(status), strsignal(WTERMSIG(status)));
  else if (WIFEXITED(status))
    std::snprintf(text, sizeof text, "worker process %d exited with code %d", pid,
                  WEXITSTATUS(status));
  else
    std::snprintf(text, sizeof text, "worker process %d ended", pid);
  return text;
}

}  // namespace

bool send_all(int fd, const char* data, std::size_t n) {
  while (n > 0) {
    const ssize_t k = ::send(fd, data, n, MSG_NOSIGNAL);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    data += k;
    n -= static_cast<std::size_t>(k);
  }
  return true;
}

bool receive_all(int fd, char* data, std::size_t n) {
  while (n > 0) {
    const ssize_t k = ::read(fd, data, n);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    data += k;
    n -= static_cast<std::size_t>(k);
  }
  return true;
}

bool send_message(int fd, const std::string& bytes) {
  const auto n = static_cast<std::uint32_t>(bytes.size());
  return send_all(fd, reinterpret_cast<const char*>(&n), sizeof n) &&
         send_all(fd, bytes.data(), bytes.size());
}

bool receive_message(int fd, std::string& bytes) {
  std::uint32_t n = 0;
  if (!receive_all(fd, reinterpret_cast<char*>(&n), sizeof n) || n > kMaxMessage) return false;
  bytes.resize(n);
  return receive_all(fd, bytes.data(), n);
}

ForkedWorkers::ForkedWorkers(int count, RunFunction run)
    : run_(std::move(run)), workers_(static_cast<std::size_t>(count)) {}

ForkedWorkers::~ForkedWorkers() {
  stop_all();
}

void ForkedWorkers::spawn(Worker& w) {
  int fds[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0)
    throw Error(std::string("sweep workers: socketpair: ") + std::strerror(errno));
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);  // a forked copy must not print the coordinator's buffered output again
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw Error(std::string("sweep workers: fork: ") + std::strerror(errno));
  }
  if (pid == 0) {
    ::close(fds[0]);
    for (const Worker& other : workers_)
      if (other.fd >= 0) ::close(other.fd);
    serve(fds[1], run_);
  }
  ::close(fds[1]);
  w.pid = pid;
  w.fd = fds[0];
}

std::string ForkedWorkers::end(Worker& w) {
  if (w.fd >= 0) ::close(w.fd);
  w.fd = -1;
  int status = 0;
  std::string how = "worker process ended";
  if (w.pid > 0 && ::waitpid(w.pid, &status, 0) == w.pid) how = ending(w.pid, status);
  w.pid = -1;
  return how;
}

void ForkedWorkers::start(int slot, std::size_t index) {
  Worker& w = workers_[static_cast<std::size_t>(slot)];
  if (w.pid < 0) spawn(w);
  const auto i = static_cast<std::uint64_t>(index);
  w.busy = true;
  w.lost = !send_all(w.fd, reinterpret_cast<const char*>(&i), sizeof i);
}

WorkerSlots::Event ForkedWorkers::wait(int timeout_ms) {
  std::vector<pollfd> polled;
  std::vector<std::size_t> which;
  for (std::size_t s = 0; s < workers_.size(); ++s) {
    Worker& w = workers_[s];
    if (!w.busy) continue;
    if (w.lost) {
      w.busy = w.lost = false;
      return {Event::Kind::Died, static_cast<int>(s), {}, end(w)};
    }
    polled.push_back({w.fd, POLLIN, 0});
    which.push_back(s);
  }
  if (polled.empty() || ::poll(polled.data(), polled.size(), timeout_ms) <= 0) return {};
  for (std::size_t k = 0; k < polled.size(); ++k) {
    if (polled[k].revents == 0) continue;
    Worker& w = workers_[which[k]];
    w.busy = false;
    std::string bytes;
    if (receive_message(w.fd, bytes)) {
      try {
        return {Event::Kind::Done, static_cast<int>(which[k]), decode_row(bytes), {}};
      } catch (const Error& e) {
        ::kill(w.pid, SIGKILL);
        return {Event::Kind::Died,
                static_cast<int>(which[k]),
                {},
                end(w) + " after a bad message (" + e.what() + ")"};
      }
    }
    return {Event::Kind::Died, static_cast<int>(which[k]), {}, end(w)};
  }
  return {};
}

void ForkedWorkers::stop_all() {
  for (Worker& w : workers_) {
    if (w.pid > 0) ::kill(w.pid, SIGKILL);
    end(w);
    w.busy = w.lost = false;
  }
}

}  // namespace stride::sweep
