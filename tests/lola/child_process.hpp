#pragma once
// A real process for the LoLA tests: started with its output in files, waited for with a bound,
// killed and reaped if the test ends first; optionally on a "full disk" (a file size limit).
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace stride::test {

class ChildProcess {
 public:
  // `cwd`: the directory it starts in (default: this process's).
  ChildProcess(const std::vector<std::string>& argv, const std::string& name,
               const std::string& cwd = "")
      : out_(scratch(name + ".out")), err_(scratch(name + ".err")) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (!cwd.empty()) posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
    posix_spawn_file_actions_addopen(&actions, 1, out_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, err_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    if (posix_spawn(&pid_, args[0], &actions, nullptr, args.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&actions);
  }
  // The same with every file it writes bounded to `file_size_limit` bytes (RLIMIT_FSIZE) and
  // SIGXFSZ ignored, so a write past it fails (EFBIG) as one on a full disk does.
  ChildProcess(const std::vector<std::string>& argv, const std::string& name,
               std::uint64_t file_size_limit)
      : out_(scratch(name + ".out")), err_(scratch(name + ".err")) {
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    pid_ = ::fork();
    if (pid_ != 0) return;
    // In the child only async-signal-safe calls until exec (the parent may have threads).
    const int o = ::open(out_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = ::open(err_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(o, 1), ::dup2(e, 2);
    const rlimit limit{file_size_limit, file_size_limit};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    ::signal(SIGXFSZ, SIG_IGN);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  ~ChildProcess() {
    if (pid_ > 0 && !code_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  bool started() const { return pid_ > 0; }
  int pid() const { return pid_; }
  void signal(int sig) const { ::kill(pid_, sig); }

  // The exit code (128 + signal when killed), or nothing if still running after `seconds`.
  std::optional<int> wait_for(double seconds) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (!code_) {
      int status = 0;
      const pid_t r = ::waitpid(pid_, &status, WNOHANG);
      if (r == pid_)
        code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      else if (std::chrono::steady_clock::now() >= give_up)
        break;
      else
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return code_;
  }

  std::string out() const { return read(out_); }
  std::string err() const { return read(err_); }

  // A path under the temporary directory unique to this test process.
  static std::string scratch(const std::string& name) {
    const auto dir =
        std::filesystem::temp_directory_path() / ("stride_lola_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return (dir / name).string();
  }

 private:
  static std::string read(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }

  std::string out_, err_;
  pid_t pid_ = -1;
  std::optional<int> code_;
};

// Waits (bounded) until `path` exists: a server's socket is ready.
inline bool wait_for_file(const std::string& path, double seconds) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!std::filesystem::exists(path)) {
    if (std::chrono::steady_clock::now() >= give_up) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

}  // namespace stride::test
