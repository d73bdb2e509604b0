#pragma once
// A LocalTarget for fuzzing the console's execution: every command reaches the real target, but
// the simulation may advance only a bounded number of steps per input (so `run 1e5` cannot stall
// the fuzzer) and files are written only under the scratch directory (a fuzzer must not overwrite
// /etc/passwd).
#include <algorithm>
#include <string>

#include "console/target/local_target.hpp"
#include "robot/core/error.hpp"

namespace stride::test {

class BudgetTarget final : public console::LocalTarget {
 public:
  explicit BudgetTarget(std::uint64_t step_budget) : budget_(step_budget) {}

  std::uint64_t advance(std::uint64_t steps, const std::function<bool()>& after) override {
    const std::uint64_t n = std::min(steps, budget_);
    budget_ -= n;
    return LocalTarget::advance(n, after);
  }
  void log_start(const std::string& p) override { LocalTarget::log_start(scratch(p)); }
  std::string log_save(const std::string& p, const std::string& to) override {
    return LocalTarget::log_save(p, scratch(to));
  }
  void log_export(const std::string& p, const std::vector<std::string>& k) override {
    LocalTarget::log_export(scratch(p), k);
  }
  void snapshot(const std::string& p, const std::string& v) override {
    LocalTarget::snapshot(scratch(p), v);
  }
  void video_start(const std::string& d, const std::string& v, std::uint64_t every) override {
    LocalTarget::video_start(scratch(d), v, every);
  }

  // A name for a file the console writes: a plain name inside the current directory (the
  // fuzzer's scratch directory), else refused like any bad argument.
  static const std::string& scratch(const std::string& path) {
    if (path.empty() || path.find('/') != std::string::npos || path == "." || path == "..")
      throw Error("fuzz: '" + path + "' is not a plain file name in the scratch directory");
    return path;
  }

 private:
  std::uint64_t budget_;
};

}  // namespace stride::test
