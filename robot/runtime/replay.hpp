#pragma once
// Replaying a log: its sensor data drives the same modules again, and every representation they
// produce can be compared bit for bit with the logged one.
#include <ostream>
#include <string>
#include <vector>

#include "robot/hal/hardware_link.hpp"
#include "robot/runtime/log.hpp"
#include "robot/runtime/runtime.hpp"

namespace stride {

// A HardwareLink that delivers the logged SensorFrames in order, up to the first damaged frame;
// period from the logged FrameInfo.
class ReplayLink final : public hal::HardwareLink {
 public:
  explicit ReplayLink(const LogReader& log, std::size_t first_frame = 0);
  bool read(hal::SensorFrame& out) override;  // false after the last logged frame
  void write(const hal::ActuatorFrame&) override {}
  double period() const override { return period_; }
  std::string name() const override { return "replay"; }
  std::size_t next_frame() const { return next_; }

 private:
  const LogReader& log_;
  std::size_t next_;
  double period_ = 0;
};

struct ReplayMismatch {
  std::size_t frame;
  std::string representation;
};

struct ReplayResult {
  std::size_t frames = 0;               // frames replayed
  bool stopped_before_damaged = false;  // the log has a damaged frame; frames from it were not
  std::vector<std::string> compared;    // representations compared every frame
  std::vector<ReplayMismatch> mismatches;
};

// Runs a fresh Runtime over the log up to its first damaged frame and compares every logged
// representation except ModuleTimes (wall-clock measurements) with what the replay produced, byte
// for byte. `config` should be the one the log was recorded with: recorded_config(log.metadata(),
// ...) gives it (recorded_config.hpp). Provider swaps and parameter changes during the recording
// are not in it.
ReplayResult replay_and_compare(const LogReader& log, const ModuleRegistry& registry,
                                const RuntimeConfig& config);

// CSV of chosen fields, one row per readable frame (damaged frames have none): keys like
// "FrameInfo.time", "JointRequest.position[3]", or a whole representation/sub-struct, which expands
// to all its leaf columns.
void export_csv(const LogReader& log, const std::vector<std::string>& keys, std::ostream& out);

}  // namespace stride
