#pragma once
// Test doubles: a deterministic HardwareLink and a few tiny modules around test representations.
#include <cmath>

#include "behaviours/stand/stand.hpp"
#include "robot/framework/module_registry.hpp"
#include "robot/hal/hardware_link.hpp"
#include "robot/representations/frame_info.hpp"
#include "robot/representations/joint_request.hpp"
#include "robot/runtime/nao_io_modules.hpp"

namespace stride::test {

// Sensor data is a closed-form function of the frame number, so two runs see the same bits.
class FakeLink final : public hal::HardwareLink {
 public:
  explicit FakeLink(double period = 0.01, int frames = 1 << 30)
      : period_(period), frames_(frames) {}
  bool read(hal::SensorFrame& s) override {
    if (n_ >= frames_) return false;
    s.time = n_ * period_;
    for (int i = 0; i < hal::kNumJoints; ++i) {
      s.position[i] = 0.1 * std::sin(0.3 * i + 0.01 * n_);
      s.current[i] = 0.05 * i;
      s.temperature[i] = 30 + i;
      s.stiffness[i] = 0.5;
    }
    s.accelerometer = {0.1, -0.2, 9.81};
    s.gyroscope = {0.01 * n_, 0, 0};
    s.angles = {0.02, -0.01};
    for (int i = 0; i < hal::kNumFsr; ++i) s.fsr[i] = 5.0 + i + 0.1 * std::cos(0.05 * n_);
    ++n_;
    return true;
  }
  void write(const hal::ActuatorFrame& a) override {
    last = a;
    ++writes;
  }
  double period() const override { return period_; }
  std::string name() const override { return "fake"; }

  hal::ActuatorFrame last;
  int writes = 0;

 private:
  double period_;
  int frames_;
  int n_ = 0;
};

struct Counter {
  STRIDE_FIELDS(Counter);
  STRIDE_FIELD(std::int64_t, n) = 0;
  static constexpr std::string_view kTypeName = "Counter";
};

struct Doubled {
  STRIDE_FIELDS(Doubled);
  STRIDE_FIELD(std::int64_t, n) = 0;
  static constexpr std::string_view kTypeName = "Doubled";
};

// Counter = frame number.
class CounterFromFrame final : public Module {
 public:
  explicit CounterFromFrame(ModuleContext& c)
      : frame_(c.require<FrameInfo>()), out_(c.provide<Counter>()) {}
  void update() override { out_.n = frame_.frame; }

 private:
  const FrameInfo& frame_;
  Counter& out_;
};

// Counter = -1000 - frame number; runs after Stand because it reads JointRequest.
class CounterAfterStand final : public Module {
 public:
  explicit CounterAfterStand(ModuleContext& c)
      : frame_(c.require<FrameInfo>()),
        request_(c.require<JointRequest>()),
        out_(c.provide<Counter>()) {}
  void update() override { out_.n = -1000 - frame_.frame; }  // request_ only orders it

 private:
  const FrameInfo& frame_;
  const JointRequest& request_;
  Counter& out_;
};

// Doubled = 2 * Counter, negated while the debug request "test:negate" is on.
class Doubler final : public Module {
 public:
  explicit Doubler(ModuleContext& c)
      : in_(c.require<Counter>()),
        out_(c.provide<Doubled>()),
        negate_(c.debug_request("test:negate")) {}
  void update() override { out_.n = (negate_.on() ? -2 : 2) * in_.n; }

 private:
  const Counter& in_;
  Doubled& out_;
  DebugRequest negate_;
};

inline ModuleRegistry test_registry() {
  ModuleRegistry r;
  register_nao_io_modules(r);
  behaviours::register_stand(r);
  r.add<CounterFromFrame>("CounterFromFrame");
  r.add<CounterAfterStand>("CounterAfterStand");
  r.add<Doubler>("Doubler");
  return r;
}

inline RuntimeConfig test_config() {
  RuntimeConfig c;
  c.providers = {{"Counter", "CounterFromFrame"}, {"Doubled", "Doubler"}};
  return c;
}

}  // namespace stride::test
