#pragma once
// What the tests that run the real `stride` binary share: a fresh temporary folder, a file's
// text, and a child process with its output in files, in its own process group so that a kill
// reaches it and its workers.
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace stride::test_support {

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// <tmp>/stride_<prefix>_<name>_<pid>, removed if it was there (not created).
inline std::filesystem::path fresh_path(const std::string& prefix, const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() /
                 ("stride_" + prefix + "_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  return d;
}

// Starts argv with stdout and stderr in files.
inline pid_t start_process(const std::vector<std::string>& args, const std::filesystem::path& out,
                           const std::filesystem::path& err) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setpgid(0, 0);
    const int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(o, 1), ::dup2(e, 2);
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    std::_Exit(127);
  }
  return pid;
}

// `mpirun -n <ranks> <args>`, as root if need be and on fewer cores than ranks. OpenMPI's runtime
// allocations live until exit (.ci/lsan.supp names its libraries); full unwinding and loaded
// components let the sanitized build's leak checker see those frames.
inline std::vector<std::string> under_mpirun(int ranks, const std::vector<std::string>& args) {
  const char* asan = std::getenv("ASAN_OPTIONS");
  std::vector<std::string> all = {
      "/usr/bin/env",
      "ASAN_OPTIONS=" + std::string(asan ? asan : "") + ":fast_unwind_on_malloc=0",
      "OMPI_MCA_mca_base_component_disable_dlclose=1",
      "mpirun",
      "--allow-run-as-root",
      "--oversubscribe",
      "-n",
      std::to_string(ranks)};
  all.insert(all.end(), args.begin(), args.end());
  return all;
}

// Its exit code, or 128 + the signal that ended it.
inline int finish_process(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace stride::test_support
