#pragma once
// A `stride run <scene> --debug` (or `stride robot --debug`) process for tests that talk to it:
// the endpoint it printed, a fresh directory for it to start in, and the tokens it accepts.
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "robot/debug/socket_io.hpp"
#include "tests/lola/child_process.hpp"

namespace stride::test {

// The `stride` under test: $STRIDE_TEST_STRIDE if set (another build's, e.g. to see a test fail
// on the code before a fix), else this build's.
inline std::string stride_under_test() {
  const char* other = std::getenv("STRIDE_TEST_STRIDE");
  return other && *other ? other : STRIDE_BINARY_DIR "/stride";
}

// The endpoint a server printed ("debug server on 127.0.0.1:P"), waiting for it (bounded).
inline std::string served_endpoint(const ChildProcess& server, bool on_stderr) {
  const std::string marker = "debug server on ";
  for (int i = 0; i < 6000; ++i) {
    const std::string text = on_stderr ? server.err() : server.out();
    if (const auto at = text.find(marker); at != std::string::npos) {
      const auto begin = at + marker.size();
      return text.substr(begin, text.find_first_of(" \n", begin) - begin);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return "";
}

// A directory of its own under the test's scratch directory, for a process to start in.
inline std::string fresh_dir(const std::string& name) {
  const std::string dir = ChildProcess::scratch(name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline const std::string kStandScene = STRIDE_SOURCE_DIR "/scenes/nao_stand_controlled.xml";
inline const std::string kFullToken = "full-token-0123456789abcdef";
inline const std::string kReadOnlyToken = "read-only-token-0123456789";

// A token file ("tokens", chmod 600) in `dir` with both tokens.
inline std::string write_tokens(const std::string& dir) {
  const std::string path = dir + "/tokens";
  std::ofstream(path) << kFullToken << "\nread-only " << kReadOnlyToken << "\n";
  ::chmod(path.c_str(), 0600);
  return path;
}

// `stride run` serving the standing NAO on loopback for `seconds`, started in a fresh `dir` (its
// default log directory), with the token file there when `tokens`; stopped with SIGTERM.
struct Served {
  std::string dir;
  ChildProcess process;
  debug::Endpoint at;  // port 0: it did not start
  Served(const std::string& name, bool tokens, double seconds = 60)
      : dir(fresh_dir(name)), process(argv(dir, tokens, seconds), name, dir) {
    const std::string text = served_endpoint(process, false);
    if (!text.empty()) at = debug::parse_endpoint(text, "test");
  }
  ~Served() {
    process.signal(SIGTERM);
    process.wait_for(30);
  }
  static std::vector<std::string> argv(const std::string& dir, bool tokens, double seconds) {
    std::vector<std::string> a = {stride_under_test(),     "run",     kStandScene,  "--seconds",
                                  std::to_string(seconds), "--debug", "127.0.0.1:0"};
    if (tokens) a.insert(a.end(), {"--token-file", write_tokens(dir)});
    return a;
  }
};

}  // namespace stride::test
