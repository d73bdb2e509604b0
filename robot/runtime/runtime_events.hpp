#pragma once
// Events a person debugging a robot must not miss, as one console line each ("event: ..."),
// whatever debug requests are on: a fall, a module's first fault, a held override whose
// provider was swapped, a command the guard limited, the hardware link lost. Each is said when
// it starts, not every frame, so a walk lying on the floor does not flood the console. The frame
// loop only notes them (no allocation in a step); take() writes the lines when they are taken.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "robot/representations/command_safety.hpp"

namespace stride {

class RuntimeEvents {
 public:
  // After every frame: `tilt` is the IMU's largest |roll| or |pitch| (negative: no IMU),
  // `fall_tilt` the SensorConversion threshold.
  void after_frame(double time, double tilt, double fall_tilt, const CommandSafety& safety);
  // After every read of the link; `now` is a steady clock in seconds.
  void link_lost(bool lost, double now);
  // Appends the lines of the events noted since the last call.
  void take(std::vector<std::string>& lines);
  static std::string fault_line(const std::string& module, const std::string& what);
  static std::string swapped_override_line(const std::string& representation,
                                           const std::string& from, const std::string& to);

 private:
  enum class Kind { Fell, Limited, Nonfinite, LinkLost, LinkBack };
  struct Noted {
    Kind kind;
    double time, a, b;  // what the line says: s, and the event's numbers
  };
  void note(Kind kind, double time, double a = 0, double b = 0);

  std::array<Noted, 16> noted_{};  // not taken yet; more are counted
  std::size_t count_ = 0;
  std::size_t dropped_ = 0;
  bool fallen_ = false;
  double upright_since_ = -1;  // s, since a fallen robot stands upright again (-1: it does not)
  static constexpr double kLostAfter = 0.1;  // s without a frame before the link counts as lost
  bool link_lost_ = false;
  double lost_since_ = -1;  // s, the first of a run of failed reads (-1: the last one succeeded)
  std::int64_t clamped_ = 0, nonfinite_ = 0;  // the guard's counters after the previous frame
  double last_clamp_ = -1e300;                // s, the last frame with a clamped position
  double last_nonfinite_ = -1e300;
};

}  // namespace stride
