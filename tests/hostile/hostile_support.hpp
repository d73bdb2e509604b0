#pragma once
// Hostile-input tests run the real `stride` process and look at what it leaves behind: its exit
// status (1, never a signal), its one-line message, and files that must not have been written.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "console/system/child_process.hpp"

namespace stride::hostile {

namespace fs = std::filesystem;

inline std::string stride_binary() {
  return std::string(STRIDE_BINARY_DIR) + "/stride";
}

inline std::string source_path(const std::string& rel) {
  return std::string(STRIDE_SOURCE_DIR) + "/" + rel;
}

// A fresh directory per test, removed afterwards.
struct Scratch {
  fs::path dir;
  Scratch() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = fs::temp_directory_path() / ("stride_hostile_" + std::to_string(::getpid()) + "_" +
                                       info->test_suite_name() + "_" + info->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() { fs::remove_all(dir); }
  std::string path(const std::string& name) const { return (dir / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name) << text;
    return path(name);
  }
};

// `stride args...`; the result's err holds everything it printed on standard error.
inline console::ChildResult run_stride(std::vector<std::string> args) {
  args.insert(args.begin(), stride_binary());
  return console::run_child(args, "");
}

// Exit status `status` (console/cli/exit_codes.hpp: 3 bad input, 2 usage error, 1 run failure;
// not a signal) with exactly one line on standard error that contains each of `parts`.
inline void expect_refused(const console::ChildResult& r, const std::vector<std::string>& parts,
                           int status = 3) {
  EXPECT_EQ(r.signal, 0) << "killed by signal " << r.signal << "; stderr: " << r.err;
  EXPECT_EQ(r.exit_status, status) << r.err;
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  for (const auto& p : parts) EXPECT_NE(r.err.find(p), std::string::npos) << p << " in " << r.err;
  EXPECT_EQ(r.out.find("wrote"), std::string::npos) << r.out;
}

}  // namespace stride::hostile
