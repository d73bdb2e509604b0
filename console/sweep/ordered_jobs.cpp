#include "console/sweep/ordered_jobs.hpp"

#include <exception>
#include <map>
#include <numeric>
#include <optional>
#include <vector>

#include "console/sweep/executor.hpp"
#include "robot/core/error.hpp"

namespace stride::sweep {

void run_jobs(std::size_t n, int jobs, const std::function<std::string(std::size_t)>& produce,
              const std::function<bool(std::size_t, std::string&&)>& use,
              const std::function<std::string(std::size_t)>& name, const JobFailed& failed) {
  auto executor = jobs > 1 && n > 1 ? worker_process_executor(jobs) : in_process_executor();
  std::vector<std::size_t> todo(n);
  std::iota(todo.begin(), todo.end(), std::size_t{0});
  // A job's bytes travel as the one cell of a RunRow, the engine's encoded envelope.
  const RunFunction run = [&](std::size_t i) {
    RunRow row;
    row.run = static_cast<std::int64_t>(i);
    try {
      row.cells.push_back(produce(i));
      row.ok = true;
    } catch (const std::exception& e) {  // Error, bad_alloc: the job fails, not the run
      row.reason = e.what();
    }
    return row;
  };
  std::map<std::size_t, RunRow> waiting;  // finished out of order
  std::size_t next = 0;
  bool stop = false;
  std::optional<std::string> thrown;
  ExecutorEvents events;
  events.done = [&](RunRow&& row, int) {
    waiting.emplace(static_cast<std::size_t>(row.run), std::move(row));
    for (auto it = waiting.find(next); !stop && it != waiting.end(); it = waiting.find(++next)) {
      RunRow r = std::move(it->second);
      waiting.erase(it);
      if (r.ok) {
        stop = !use(next, std::move(r.cells.front()));
        continue;
      }
      if (r.attempts > 1) r.reason = name(next) + ": " + r.reason;  // its worker died
      if (failed) {
        failed(next, r.reason);
        continue;
      }
      thrown = r.reason;
      stop = true;
    }
  };
  events.stop = [&] { return stop; };
  executor->execute(todo, run, events);
  if (thrown) throw Error(*thrown);
}

}  // namespace stride::sweep
