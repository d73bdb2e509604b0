#pragma once
// Many independent jobs whose results are bytes (an ensemble's members, a convergence study's
// settings), on the same executors as a sweep's runs: in this process or in forked workers, a
// dead worker's job retried once. Results are handed over in job order whatever the executor,
// so they equal those of running the jobs one by one.
#include <cstddef>
#include <functional>
#include <string>

namespace stride::sweep {

using JobFailed = std::function<void(std::size_t, const std::string&)>;

// Runs produce(i) for i in [0, n) with up to `jobs` workers (1: in this process) and hands each
// result to `use` in job order; `use` returns false to stop early (the remaining jobs are
// abandoned). A job that fails (its exception, or its worker dying twice) goes to `failed` with
// the reason, in job order, and the others go on; without `failed` the first failure is thrown
// as stride::Error when its turn comes, after the earlier results were used. `name(i)` names job
// i when its worker dies.
void run_jobs(std::size_t n, int jobs, const std::function<std::string(std::size_t)>& produce,
              const std::function<bool(std::size_t, std::string&&)>& use,
              const std::function<std::string(std::size_t)>& name, const JobFailed& failed = {});

}  // namespace stride::sweep
