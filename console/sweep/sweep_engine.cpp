#include "console/sweep/sweep_engine.hpp"

#include <signal.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <ostream>
#include <sstream>

#include "console/sweep/csv_line.hpp"
#include "console/sweep/sweep_output.hpp"
#include "console/sweep/sweep_plots.hpp"
#include "robot/core/error.hpp"

namespace stride::sweep {
namespace {

// Signal handlers can only set a flag; this is the one process-wide state the engine keeps.
volatile sig_atomic_t g_interrupted = 0;
struct sigaction g_old_int, g_old_term;

void on_interrupt(int) {
  g_interrupted = 1;
}

// The tallies, then the failed runs with their plan cells and reasons; `status` is the status
// column's index in a row.
void report(std::ostream& out, const SweepResult& r, const std::vector<TallyTable>& tallies,
            bool print, std::size_t status) {
  if (print)
    for (const TallyTable& t : tallies) {
      out << "\n";
      print_tally(out, t);
    }
  if (r.failed == 0) return;
  out << "\n" << r.failed << " run(s) failed (status 'failed' in runs.csv):\n";
  constexpr std::size_t kListed = 20;  // the rest are in runs.csv
  std::size_t listed = 0;
  for (const auto& cells : r.rows) {
    if (cells[status] == "ok") continue;
    if (++listed > kListed) break;
    out << "  run " << cells.front();
    for (std::size_t c = 1; c < status; ++c) out << " " << cells[c];
    out << ": " << cells.back() << "\n";
  }
  if (r.failed > kListed) out << "  ... and " << r.failed - kListed << " more\n";
}

}  // namespace

InterruptGuard::InterruptGuard() {
  g_interrupted = 0;
  struct sigaction sa = {};
  sa.sa_handler = on_interrupt;
  sa.sa_flags = SA_RESETHAND;  // a second Ctrl-C ends the process at once
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &g_old_int);
  sigaction(SIGTERM, &sa, &g_old_term);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &g_old_int, nullptr);
  sigaction(SIGTERM, &g_old_term, nullptr);
}

bool InterruptGuard::interrupted() {
  return g_interrupted != 0;
}

std::vector<std::size_t> select_runs(
    const Sweep& sweep, const std::vector<std::pair<std::string, std::vector<std::string>>>& only) {
  const Plan& plan = sweep.plan();
  std::vector<std::pair<std::size_t, const std::vector<std::string>*>> filters;
  for (const auto& [column, levels] : only) {
    const auto it = std::find(plan.columns.begin(), plan.columns.end(), column);
    if (it == plan.columns.end()) throw Error("--only " + column + ": no such column in the plan");
    const auto c = static_cast<std::size_t>(it - plan.columns.begin());
    for (const std::string& l : levels)
      if (std::none_of(plan.runs.begin(), plan.runs.end(),
                       [&](const RunPlan& r) { return r.cells[c] == l; }))
        throw Error("--only " + column + "=" + l + ": no run has it");
    filters.emplace_back(c, &levels);
  }
  std::vector<std::size_t> picked;
  for (std::size_t i = 0; i < plan.runs.size(); ++i)
    if (std::all_of(filters.begin(), filters.end(), [&](const auto& f) {
          return std::find(f.second->begin(), f.second->end(), plan.runs[i].cells[f.first]) !=
                 f.second->end();
        }))
      picked.push_back(i);
  return picked;
}

SweepResult run_sweep(const Sweep& sweep, const Tallies& tallies, Executor& executor,
                      const SweepOptions& o, std::ostream& out) {
  const std::vector<std::size_t> selected = select_runs(sweep, o.only);
  std::unique_ptr<SweepOutput> output;
  if (!o.out_dir.empty())
    output = std::make_unique<SweepOutput>(sweep, o.out_dir, o.resume, o.overwrite, o.command);
  SweepResult r;
  r.selected = selected.size();
  std::map<std::int64_t, std::vector<std::string>> rows;
  if (output)
    for (const auto& [id, cells] : output->rows()) rows[id] = cells;
  std::vector<std::size_t> todo;
  for (std::size_t i : selected)
    if (rows.count(static_cast<std::int64_t>(i)))
      ++r.resumed;
    else
      todo.push_back(i);
  const std::size_t status = sweep.plan().columns.size() + 1;
  for (const auto& [id, cells] : rows) r.failed += cells[status] != "ok";
  if (o.progress) o.progress(r.resumed, r.failed, r.selected);

  ExecutorEvents events;
  events.done = [&](RunRow&& row, int worker) {
    if (output) output->add(row, worker);
    r.failed += !row.ok;
    ++r.ran;
    rows[row.run] = sweep.csv_cells(row);
    if (o.progress) o.progress(r.resumed + r.ran, r.failed, r.selected);
  };
  events.stop = [&] { return o.stop && o.stop(); };
  events.idle = [&] {
    if (o.tick) o.tick();
  };
  executor.execute(
      todo, [&sweep](std::size_t i) { return sweep.run(i); }, events);

  r.complete = r.resumed + r.ran == r.selected;
  for (std::size_t i : selected)
    if (auto it = rows.find(static_cast<std::int64_t>(i)); it != rows.end())
      r.rows.push_back(it->second);
  if (output && r.complete) output->sort_rows();
  if (!r.complete) {
    out << "\nsweep '" << sweep.spec().name << "' stopped: " << r.resumed + r.ran << " of "
        << r.selected << " runs done"
        << (output ? "; continue with --resume (output: " + o.out_dir + ")" : "") << "\n";
    return r;
  }
  r.tallies = tallies.compute(r.rows);
  report(out, r, r.tallies, o.print_tallies, status);
  if (output) {
    std::ostringstream text;
    for (const TallyTable& t : r.tallies) {
      print_tally(text, t);
      text << "\n";
      output->write_file(t.name + ".csv", tally_csv(t));
    }
    output->write_file("tallies.txt", text.str());
    write_sweep_plots(sweep.spec(), r.tallies, *output, o.plots);
  }
  return r;
}

}  // namespace stride::sweep
