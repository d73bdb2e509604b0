#include <thread>

#include "console/sweep/executor.hpp"
#include "console/sweep/forked_workers.hpp"

namespace stride::sweep {
namespace {

class InProcess final : public Executor {
 public:
  std::string describe() const override { return "1 process"; }
  int workers() const override { return 1; }
  void execute(const std::vector<std::size_t>& todo, const RunFunction& run,
               const ExecutorEvents& events) override {
    for (std::size_t index : todo) {
      if (events.stop && events.stop()) return;
      events.done(run(index), 0);
    }
  }
};

class WorkerProcesses final : public Executor {
 public:
  explicit WorkerProcesses(int n) : n_(n) {}
  std::string describe() const override {
    return std::to_string(n_) + " worker process" + (n_ == 1 ? "" : "es");
  }
  int workers() const override { return n_; }
  void execute(const std::vector<std::size_t>& todo, const RunFunction& run,
               const ExecutorEvents& events) override {
    // No more workers than runs: each fork costs a copy-on-write image of this process.
    const int n =
        static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(n_), todo.size()));
    if (n == 0) return;
    ForkedWorkers slots(n, run);
    dispatch(slots, todo, events);
  }

 private:
  int n_;
};

}  // namespace

std::unique_ptr<Executor> in_process_executor() {
  return std::make_unique<InProcess>();
}

std::unique_ptr<Executor> worker_process_executor(int workers) {
  return std::make_unique<WorkerProcesses>(workers < 1 ? 1 : workers);
}

int hardware_jobs() {
  const unsigned n = std::thread::hardware_concurrency();
  return n > 0 ? static_cast<int>(n) : 1;
}

}  // namespace stride::sweep
