#pragma once
// The names a sweep reads from a run, bound to a live session:
//   per frame   representation:<Name>.<path>   a number on robot 0's blackboard
//               frame.<field>                  a WalkFrame field (torso, feet, CoM, CoP, ...)
//   at a time   every per-frame key, and
//               walk.<field>                   the simulator's walk metrics (steps, fell, ...)
//               module:<Name>.<path>           a module parameter
//               pattern.duration|start_delay   the walking pattern's timing (s)
//               sim.time|steps|hash            robot.period (the control period)
#include <string>
#include <vector>

#include "console/session/walk_frame.hpp"
#include "console/sweep/expression.hpp"
#include "robot/framework/leaf_reader.hpp"

namespace stride::sweep {

// Checks a key's namespace and, where that needs no session, its field; throws stride::Error
// saying what was expected. `per_frame` allows only keys that change every frame.
void check_key(const std::string& key, bool per_frame);
// walk.tipped and sim.hash are texts; every other key is a number.
bool key_is_text(const std::string& key);
// True for frame.* keys, which need the WalkFrame observer.
bool key_needs_walk_frame(const std::string& key);

// Per-frame keys bound to robot 0 of a session; sample() reads them all after a control frame.
class FrameKeys {
 public:
  // Binds the keys `needed` marks (all when it is empty); the others read NaN.
  FrameKeys(console::SimSession& session, const console::WalkFrameObserver* walk,
            const std::vector<std::string>& keys, const std::vector<bool>& needed = {});
  void sample();
  const std::vector<Cell>& values() const { return values_; }

 private:
  struct Bound {
    int slot = -1;  // into slots_ (representation keys)
    std::optional<LeafReader> reader;
    int frame_field = -1;  // WalkFrame field
  };
  std::vector<Bound> bound_;
  std::vector<const Slot*> slots_;
  std::vector<std::string> bytes_;
  const console::WalkFrameObserver* walk_;
  std::vector<Cell> values_;
};

// Any key's value now.
Cell read_key(console::SimSession& session, const console::WalkFrameObserver* walk,
              const std::string& key);

}  // namespace stride::sweep
