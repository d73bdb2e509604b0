#pragma once
// The real `stride` program started as a process from a fresh temporary folder outside the
// checkout, with its standard output and error captured in files there.
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

extern char** environ;

namespace stride::test_support {

struct Finished {
  int exit_code = -1;  // -1 when ended by a signal
  int signal = 0;
  std::string out, err;
  double seconds = 0;  // wall time from start to exit
};

class StrideProcess {
 public:
  // Starts `stride args...` in `folder` with `env` added to this process's environment.
  StrideProcess(const std::vector<std::string>& args, const std::filesystem::path& folder,
                const std::map<std::string, std::string>& env = {});
  ~StrideProcess();  // kills a process still running
  StrideProcess(const StrideProcess&) = delete;
  StrideProcess& operator=(const StrideProcess&) = delete;

  pid_t pid() const { return pid_; }
  void signal(int sig) const;
  // Standard error so far (while it runs).
  std::string err_so_far() const;
  Finished wait();

 private:
  pid_t pid_ = -1;
  std::filesystem::path out_, err_;
  double started_ = 0;
};

// Runs to the end.
Finished run_stride(const std::vector<std::string>& args, const std::filesystem::path& folder,
                    const std::map<std::string, std::string>& env = {});

// A new empty folder under the system's temporary folder, removed by the destructor.
class TempFolder {
 public:
  TempFolder();
  ~TempFolder();
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  // Every entry below the folder, relative, sorted (what a command created).
  std::vector<std::string> entries() const;

 private:
  std::filesystem::path path_;
};

// The checkout's file `relative` (scenes are read from there).
std::string source_file(const std::string& relative);

// Implementation (header-only: the test folders build only *_test.cpp files).
namespace detail {

inline double now() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

inline std::string read_all(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace detail

inline StrideProcess::StrideProcess(const std::vector<std::string>& args,
                                    const std::filesystem::path& folder,
                                    const std::map<std::string, std::string>& env) {
  static int count = 0;
  const std::string tag = std::to_string(::getpid()) + "_" + std::to_string(++count);
  out_ = std::filesystem::temp_directory_path() / ("stride_out_" + tag);
  err_ = std::filesystem::temp_directory_path() / ("stride_err_" + tag);
  std::vector<std::string> envs;
  for (char** e = environ; *e; ++e) {
    const std::string kv = *e;
    const std::string key = kv.substr(0, kv.find('='));
    if (!env.count(key)) envs.push_back(kv);
  }
  for (const auto& [k, v] : env) envs.push_back(k + "=" + v);
  std::vector<std::string> argv_s{STRIDE_BINARY_DIR "/stride"};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv, envp;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  for (auto& e : envs) envp.push_back(e.data());
  envp.push_back(nullptr);
  started_ = detail::now();
  pid_ = ::fork();
  if (pid_ < 0) throw std::runtime_error("fork failed");
  if (pid_ == 0) {
    if (::chdir(folder.c_str()) != 0) std::_Exit(126);
    const std::string o = out_.string(), e = err_.string();
    if (!std::freopen(o.c_str(), "w", stdout) || !std::freopen(e.c_str(), "w", stderr))
      std::_Exit(126);
    ::execve(argv[0], argv.data(), envp.data());
    std::_Exit(127);
  }
}

inline StrideProcess::~StrideProcess() {
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
  }
  std::error_code ec;
  std::filesystem::remove(out_, ec);
  std::filesystem::remove(err_, ec);
}

inline void StrideProcess::signal(int sig) const {
  ::kill(pid_, sig);
}

inline std::string StrideProcess::err_so_far() const {
  return detail::read_all(err_);
}

inline Finished StrideProcess::wait() {
  int status = 0;
  ::waitpid(pid_, &status, 0);
  pid_ = -1;
  Finished f;
  f.seconds = detail::now() - started_;
  if (WIFEXITED(status)) f.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) f.signal = WTERMSIG(status);
  f.out = detail::read_all(out_);
  f.err = detail::read_all(err_);
  return f;
}

inline Finished run_stride(const std::vector<std::string>& args,
                           const std::filesystem::path& folder,
                           const std::map<std::string, std::string>& env) {
  StrideProcess p(args, folder, env);
  return p.wait();
}

inline TempFolder::TempFolder() {
  std::string templ = (std::filesystem::temp_directory_path() / "stride_cli_XXXXXX").string();
  if (!::mkdtemp(templ.data())) throw std::runtime_error("mkdtemp failed");
  path_ = templ;
}

inline TempFolder::~TempFolder() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

inline std::vector<std::string> TempFolder::entries() const {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(path_))
    out.push_back(std::filesystem::relative(e.path(), path_).string());
  std::sort(out.begin(), out.end());
  return out;
}

inline std::string source_file(const std::string& relative) {
  return STRIDE_SOURCE_DIR "/" + relative;
}

}  // namespace stride::test_support
