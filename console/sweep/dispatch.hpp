#pragma once
// The coordinator's side of every multi-worker executor: hand each idle worker the next run, take
// back rows as they come, and give a run whose worker died once more to another worker before
// recording it as failed. Workers are "slots": forked processes here, MPI ranks elsewhere.
#include <cstddef>
#include <string>
#include <vector>

#include "console/sweep/executor.hpp"

namespace stride::sweep {

class WorkerSlots {
 public:
  virtual ~WorkerSlots() = default;
  virtual int count() const = 0;
  // Gives the idle slot run `index`; a slot that cannot take it reports Died from wait().
  virtual void start(int slot, std::size_t index) = 0;

  struct Event {
    enum class Kind { None, Done, Died } kind = Kind::None;
    int slot = -1;
    RunRow row;          // Done
    std::string reason;  // Died: how the worker ended
  };
  // The next event of a busy slot, or None after `timeout_ms`.
  virtual Event wait(int timeout_ms) = 0;
  // Ends every worker (runs in flight are abandoned).
  virtual void stop_all() = 0;
};

void dispatch(WorkerSlots& slots, const std::vector<std::size_t>& todo,
              const ExecutorEvents& events);

}  // namespace stride::sweep
