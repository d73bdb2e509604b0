#pragma once
// Many experiment walks at once in worker processes (worker_pool.hpp); results come back in
// setup order and equal those of running the walks one by one.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "console/experiments/walk_recording.hpp"
#include "console/experiments/worker_pool.hpp"

namespace stride::experiments {

// Records every setup with up to `jobs` workers (1: in this process) and hands each recording to
// `use` in setup order; `use` returns false to stop early (the remaining walks are abandoned).
// A walk that fails (its stride::Error, or its worker process dying) goes to `failed` with the
// reason, in the same order, and the others go on; without `failed` the first failure is thrown
// as a stride::Error when its turn comes, after the earlier walks were used.
// A progress line named `label` counts the walks done and lost (fell, tipped or failed) on stderr.
void record_walks(const std::vector<WalkSetup>& setups, int jobs,
                  const std::function<bool(std::size_t, WalkRecording&&)>& use,
                  const Failed& failed = {}, const std::string& label = "experiment");

}  // namespace stride::experiments
