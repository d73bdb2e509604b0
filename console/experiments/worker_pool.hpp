#pragma once
// Many independent jobs at once. ODE keeps process-wide state (its random generator drives the
// solver's row order), so jobs run in forked worker processes, not threads; results come back
// as bytes in job order and equal those of running the jobs one by one.
#include <cstddef>
#include <functional>
#include <string>

namespace stride::experiments {

// Runs produce(i) for i in [0, n) with up to `jobs` workers (1: in this process) and hands each
// result to `use` in job order; `use` returns false to stop early (the remaining jobs are
// abandoned). A job that fails (its exception, or its worker process dying) goes to `failed`
// with the reason, in job order, and the others go on (a dead worker is replaced); without
// `failed` the first failure is thrown as stride::Error when its turn comes, after the earlier
// results were used. `name(i)` names job i when its worker dies.
using Failed = std::function<void(std::size_t, const std::string&)>;
void run_in_workers(std::size_t n, int jobs, const std::function<std::string(std::size_t)>& produce,
                    const std::function<bool(std::size_t, std::string&&)>& use,
                    const std::function<std::string(std::size_t)>& name, const Failed& failed = {});

// The default for --jobs: the machine's hardware threads (at least 1).
int default_jobs();

}  // namespace stride::experiments
