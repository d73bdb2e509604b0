#pragma once
// The world one sweep run steps, with robot 0's controller wherever the sweep's link puts it: in
// this process (directly or through LoLA's packets) or in a started `stride-robot` on a LoLA
// socket (lola_robot.hpp). The run itself (run_execution.cpp) is the same for all three.
#include <functional>
#include <memory>
#include <optional>

#include "console/session/sim_session.hpp"
#include "console/session/walk_frame.hpp"
#include "console/sweep/run_plan.hpp"

namespace stride::sweep {

class LolaRobot;

class RunWorld {
 public:
  // Throws stride::Error (a bad setting, a robot process that does not start or connect).
  RunWorld(const SweepSpec& spec, const RunPlan& run);
  ~RunWorld();

  console::SimSession& session() { return *session_; }
  // The walking pattern robot 0's controller plays (its walk marks), wherever it runs.
  const std::optional<console::WalkPatternInfo>& walk() const { return walk_; }
  bool through_lola() const { return lola_ != nullptr; }
  // Called at every control frame of robot 0 after its controller (as SimSession's observer).
  void set_frame_observer(console::SimSession::FrameObserver observer);
  // After the last step: throws if the robot process failed a frame; ends the robot process.
  void finish();

 private:
  std::unique_ptr<console::SimSession> session_;
  std::optional<console::WalkPatternInfo> walk_;
  std::unique_ptr<LolaRobot> lola_;
};

}  // namespace stride::sweep
