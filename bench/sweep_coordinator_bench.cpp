// The sweep coordinator's own cost per run, the figure that bounds how many workers one
// coordinator can feed (docs/performance.md "Sweeps: scaling and throughput"). The runs take no time, so all that is
// timed is what the coordinator does for each: hand the run out, take its row back (over a socket
// from a forked worker, as a rank's row comes back over MPI), append it to runs.csv and
// timing.csv, and at the end sort the rows and compute the tallies. A row has the posture study's
// columns, each a full-precision number. The counters are per run in the coordinating process's
// CPU time (what saturates it); the Time column is the wall time of the 900 runs.
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <filesystem>
#include <sstream>

#include "console/sweep/executor.hpp"
#include "console/sweep/sweep_engine.hpp"
#include "console/sweep/sweep_parser.hpp"

namespace {

using namespace stride::sweep;

// The posture study with seeds 1..100: 900 runs, so a sweep's fork of its workers is spread thin.
const Sweep& posture() {
  static const Sweep s = [] {
    SweepSpec spec = parse_sweep_file(STRIDE_SOURCE_DIR "/scenes/experiments/posture.sweep.xml");
    spec.seeds.clear();
    for (std::uint64_t k = 1; k <= 100; ++k) spec.seeds.push_back(k);
    spec.record.traces.clear();  // no per-frame traces: a row as most sweeps send it
    return Sweep(std::move(spec), false);
  }();
  return s;
}

// A finished posture run as a worker sends it: every record column holds a full-precision number.
RunRow posture_row(std::size_t i) {
  RunRow row;
  row.run = static_cast<std::int64_t>(i);
  row.ok = true;
  row.cells.assign(posture().record_columns().size(), "0.12345678901234567");
  row.seconds = 6.5;
  return row;
}

// The engine's executor with the walk replaced by posture_row.
class InstantRuns final : public Executor {
 public:
  explicit InstantRuns(std::unique_ptr<Executor> inner) : inner_(std::move(inner)) {}
  std::string describe() const override { return inner_->describe(); }
  int workers() const override { return inner_->workers(); }
  void execute(const std::vector<std::size_t>& todo, const RunFunction&,
               const ExecutorEvents& events) override {
    inner_->execute(todo, posture_row, events);
  }

 private:
  std::unique_ptr<Executor> inner_;
};

void BM_CoordinatorPerRun(benchmark::State& state) {
  const int workers = static_cast<int>(state.range(0));
  const auto dir = std::filesystem::temp_directory_path() /
                   ("stride_coordinator_bench_" + std::to_string(::getpid()));
  const Tallies tallies(posture());
  SweepOptions options;
  options.out_dir = dir.string();
  options.overwrite = true;
  options.print_tallies = options.plots = false;
  std::size_t runs = 0;
  for (auto _ : state) {
    InstantRuns executor(workers == 0 ? in_process_executor() : worker_process_executor(workers));
    std::ostringstream text;
    const SweepResult r = run_sweep(posture(), tallies, executor, options, text);
    if (!r.complete) state.SkipWithError("the sweep did not complete");
    runs += r.ran;
  }
  std::filesystem::remove_all(dir);
  state.counters["runs/s"] =
      benchmark::Counter(static_cast<double>(runs), benchmark::Counter::kIsRate);
  state.counters["s/run"] = benchmark::Counter(
      static_cast<double>(runs), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
// 0: in process (rows, files and tallies only); 1, 2: forked workers, rows back over sockets.
BENCHMARK(BM_CoordinatorPerRun)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
