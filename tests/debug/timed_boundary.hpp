#pragma once
// A frame boundary that times another: the last and the longest time the inner boundary (the
// loop's whole exchange with a debug server) took, for the debug tests and the load tool.
#include <atomic>
#include <chrono>
#include <cstdint>

#include "robot/runtime/frame_boundary.hpp"

namespace stride::test {

class TimedBoundary final : public FrameBoundary {
 public:
  explicit TimedBoundary(FrameBoundary& inner) : inner_(inner) {}
  void after_frame(Runtime& rt) override {
    const auto t0 = std::chrono::steady_clock::now();
    inner_.after_frame(rt);
    const auto ns =
        std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0)
            .count();
    last_ns = ns;
    if (ns > longest_ns.load()) longest_ns = ns;
  }
  void detached(Runtime& rt) override { inner_.detached(rt); }
  std::atomic<std::int64_t> longest_ns{0}, last_ns{0};

 private:
  FrameBoundary& inner_;
};

}  // namespace stride::test
