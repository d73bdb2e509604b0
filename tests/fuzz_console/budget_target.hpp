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

class BudgetTarget final : public console::Target {
 public:
  explicit BudgetTarget(std::uint64_t step_budget) : budget_(step_budget) {}
  console::LocalTarget& inner() { return inner_; }

  std::string name() const override { return inner_.name(); }
  bool loaded() const override { return inner_.loaded(); }
  void load(const std::string& p) override { inner_.load(p); }
  void reset() override { inner_.reset(); }
  std::uint64_t advance(std::uint64_t steps, const std::function<bool()>& after) override {
    const std::uint64_t n = std::min(steps, budget_);
    budget_ -= n;
    return inner_.advance(n, after);
  }
  double step_seconds() const override { return inner_.step_seconds(); }
  std::vector<std::string> robot_names() override { return inner_.robot_names(); }
  std::string selected_robot() override { return inner_.selected_robot(); }
  void select_robot(const std::string& n) override { inner_.select_robot(n); }
  std::string get(const std::string& k) override { return inner_.get(k); }
  const TypeDesc& type_of(const std::string& k) override { return inner_.type_of(k); }
  void set(const std::string& k, const std::string& f) override { inner_.set(k, f); }
  std::vector<std::string> representations() override { return inner_.representations(); }
  std::vector<std::string> parameter_modules() override { return inner_.parameter_modules(); }
  std::string provider_of(const std::string& r) override { return inner_.provider_of(r); }
  std::vector<std::string> providers_available(const std::string& r) override {
    return inner_.providers_available(r);
  }
  void swap_provider(const std::string& r, const std::string& m) override {
    inner_.swap_provider(r, m);
  }
  std::vector<std::pair<std::string, DebugSwitch>> debug_requests() override {
    return inner_.debug_requests();
  }
  void set_debug_request(const std::string& n, DebugSwitch state) override {
    inner_.set_debug_request(n, state);
  }
  console::DebugOutput take_debug_output() override { return inner_.take_debug_output(); }
  void log_start(const std::string& p) override { inner_.log_start(scratch(p)); }
  void log_stop() override { inner_.log_stop(); }
  std::string log_load(const std::string& p) override { return inner_.log_load(p); }
  std::vector<std::string> log_goto(std::size_t f) override { return inner_.log_goto(f); }
  void log_export(const std::string& p, const std::vector<std::string>& k) override {
    inner_.log_export(scratch(p), k);
  }
  console::ReplaySummary log_replay() override { return inner_.log_replay(); }
  std::vector<std::string> log_info() override { return inner_.log_info(); }
  std::string report_text() override { return inner_.report_text(); }
  std::string report_json() override { return inner_.report_json(); }
  void push(const std::string& b, double fx, double fy, double fz, double s) override {
    inner_.push(b, fx, fy, fz, s);
  }
  void move_robot(double x, double y, double z, double yaw) override {
    inner_.move_robot(x, y, z, yaw);
  }
  void sensor_switch(const std::string& w, bool on) override { inner_.sensor_switch(w, on); }
  void snapshot(const std::string& p, const std::string& v) override {
    inner_.snapshot(scratch(p), v);
  }
  void video_start(const std::string& d, const std::string& v, std::uint64_t every) override {
    inner_.video_start(scratch(d), v, every);
  }
  std::uint64_t video_stop() override { return inner_.video_stop(); }

  // A name for a file the console writes: a plain name inside the current directory (the
  // fuzzer's scratch directory), else refused like any bad argument.
  static const std::string& scratch(const std::string& path) {
    if (path.empty() || path.find('/') != std::string::npos || path == "." || path == "..")
      throw Error("fuzz: '" + path + "' is not a plain file name in the scratch directory");
    return path;
  }

 private:
  console::LocalTarget inner_;
  std::uint64_t budget_;
};

}  // namespace stride::test
