#include "console/system/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <thread>

#include "robot/core/error.hpp"

extern char** environ;

namespace stride::console {
namespace {

// Socket pairs rather than pipes: a child that exits without reading its input makes our send
// fail with EPIPE (MSG_NOSIGNAL) instead of killing this process with SIGPIPE.
struct Channel {
  int ours = -1, theirs = -1;
  Channel() {
    int fds[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0)
      throw Error(std::string("cannot create a channel to a child process: ") +
                  std::strerror(errno));
    ours = fds[0];
    theirs = fds[1];
  }
  ~Channel() {
    close_ours();
    close_theirs();
  }
  void close_ours() {
    if (ours >= 0) ::close(ours);
    ours = -1;
  }
  void close_theirs() {
    if (theirs >= 0) ::close(theirs);
    theirs = -1;
  }
};

pid_t spawn(const std::vector<std::string>& argv, Channel& in, Channel& out, Channel& err) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in.theirs, 0);
  posix_spawn_file_actions_adddup2(&actions, out.theirs, 1);
  posix_spawn_file_actions_adddup2(&actions, err.theirs, 2);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = -1;
  const int rc = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw Error("cannot start '" + argv[0] + "': " + std::strerror(rc));
  return pid;
}

// Feeds `input` and drains both outputs until the child closes them.
void exchange(Channel& in, Channel& out, Channel& err, const std::string& input, ChildResult& r) {
  std::size_t sent = 0;
  if (input.empty()) in.close_ours();
  std::array<char, 65536> buf;
  while (out.ours >= 0 || err.ours >= 0) {
    pollfd fds[3] = {{in.ours, POLLOUT, 0}, {out.ours, POLLIN, 0}, {err.ours, POLLIN, 0}};
    if (::poll(fds, 3, -1) < 0) {
      if (errno == EINTR) continue;
      throw Error(std::string("waiting for a child process: ") + std::strerror(errno));
    }
    if (in.ours >= 0 && fds[0].revents) {
      const ssize_t n = ::send(in.ours, input.data() + sent, input.size() - sent, MSG_NOSIGNAL);
      if (n > 0) sent += static_cast<std::size_t>(n);
      if (n < 0 && errno != EINTR && errno != EAGAIN) sent = input.size();  // it stopped reading
      if (sent == input.size()) in.close_ours();
    }
    for (int k = 1; k < 3; ++k) {
      Channel& c = k == 1 ? out : err;
      if (c.ours < 0 || !fds[k].revents) continue;
      const ssize_t n = ::read(c.ours, buf.data(), buf.size());
      if (n > 0)
        (k == 1 ? r.out : r.err).append(buf.data(), static_cast<std::size_t>(n));
      else if (n == 0 || errno != EINTR)
        c.close_ours();
    }
  }
}

}  // namespace

ChildResult run_child(const std::vector<std::string>& argv, const std::string& input) {
  if (argv.empty()) throw Error("run_child: no program given");
  Channel in, out, err;
  const pid_t pid = spawn(argv, in, out, err);
  in.close_theirs();
  out.close_theirs();
  err.close_theirs();
  ChildResult r;
  try {
    exchange(in, out, err, input, r);
  } catch (...) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    throw;
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  r.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  return r;
}

std::string sibling_executable(const std::string& name) {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return (self.parent_path() / name).string();
}

RunningChild::RunningChild(const std::vector<std::string>& argv, const std::string& log) {
  if (argv.empty()) throw Error("RunningChild: no program given");
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (out < 0) throw Error("cannot open " + log + ": " + std::strerror(errno));
  const int in = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  const pid_t parent = ::getpid();
  // fork + exec rather than posix_spawn: only the child can ask for PR_SET_PDEATHSIG. Between
  // fork and exec the child calls async-signal-safe functions only.
  pid_ = ::fork();
  if (pid_ == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);  // the parent already went
    if (in >= 0) ::dup2(in, 0);
    ::dup2(out, 1);
    ::dup2(out, 2);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  const int fork_errno = errno;
  started_ = pid_;
  ::close(out);
  if (in >= 0) ::close(in);
  if (pid_ < 0) throw Error("cannot start '" + argv[0] + "': " + std::strerror(fork_errno));
}

RunningChild::~RunningChild() {
  stop();
}

void RunningChild::reaped(int status) {
  pid_ = -1;
  if (WIFEXITED(status))
    how_ = WEXITSTATUS(status) == 127 ? "could not be executed (exit status 127)"
                                      : "exit status " + std::to_string(WEXITSTATUS(status));
  else
    how_ = "killed by signal " + std::to_string(WTERMSIG(status));
}

bool RunningChild::ended() {
  if (pid_ < 0) return true;
  int status = 0;
  const pid_t r = ::waitpid(pid_, &status, WNOHANG);
  if (r == pid_) reaped(status);
  return pid_ < 0;
}

const std::string& RunningChild::stop(double grace) {
  if (ended()) return how_;
  ::kill(pid_, SIGTERM);
  const auto until =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(grace > 0 ? grace : 0);
  while (!ended() && std::chrono::steady_clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  if (pid_ >= 0) {
    ::kill(pid_, SIGKILL);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    reaped(status);
  }
  return how_;
}

}  // namespace stride::console
