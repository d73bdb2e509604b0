// One run of a sweep: build its world, watch every control frame of robot 0 (after its
// controller, so the scene's timed changes still apply), stop at the marks where values are
// read, and turn what was seen into the record columns.
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "console/session/walk_frame.hpp"
#include "console/sweep/run_keys.hpp"
#include "console/sweep/run_session.hpp"
#include "console/sweep/run_world.hpp"
#include "console/sweep/summary_stat.hpp"
#include "console/sweep/sweep_compiled.hpp"
#include "robot/core/error.hpp"

namespace stride::sweep {
namespace {

// Where the marks fall in this run (s of simulation time; walk marks as the pattern plans them).
struct Marks {
  std::optional<console::WalkPatternInfo> walk;
  double end = 0;

  double absolute(const TimePoint& p) const {
    if (p.mark == "start") return p.offset;
    if (p.mark == "end") return end + p.offset;
    const console::WalkPatternInfo& w = pattern(p.mark);
    return w.start_delay + (p.mark == "walk_end" ? w.duration : 0.0) + p.offset;
  }
  const console::WalkPatternInfo& pattern(const std::string& mark) const {
    if (!walk)
      throw Error(mark +
                  ": robot 0 walks no pattern (WalkingJointRequest from PatternWalk or "
                  "ConventionalWalk)");
    return *walk;
  }
};

WindowBound bound_of(const TimePoint& p, const Marks& m) {
  if (p.mark == "walk_start" || p.mark == "walk_end")
    return {true, (p.mark == "walk_end" ? m.pattern(p.mark).duration : 0.0) + p.offset};
  return {false, m.absolute(p)};
}

std::string cell_text(const Cell& c) {
  if (const double* d = std::get_if<double>(&c)) return number_text(*d);
  return std::get<std::string>(c);
}

void append_trace_row(std::string& csv, const std::vector<int>& keys, const std::vector<Cell>& v) {
  for (std::size_t i = 0; i < keys.size(); ++i)
    csv += (i ? "," : "") + cell_text(v[static_cast<std::size_t>(keys[i])]);
  csv += '\n';
}

// The first trace whose `where` takes this run (its header written to `csv`) and when it starts.
std::pair<const Sweep::Compiled::Trace*, std::optional<WindowBound>> run_trace(
    const SweepSpec& spec, const Sweep::Compiled& c, const std::vector<Cell>& plan_values,
    const Marks& marks, std::string& csv) {
  for (std::size_t i = 0; i < c.traces.size(); ++i)
    if (!c.traces[i].where || c.traces[i].where->truth(plan_values)) {
      for (std::size_t k = 0; k < spec.record.traces[i].columns.size(); ++k)
        csv += (k ? "," : "") + spec.record.traces[i].columns[k].first;
      csv += '\n';
      return {&c.traces[i], bound_of(spec.record.traces[i].from, marks)};
    }
  return {nullptr, std::nullopt};
}

// Physics step -> the values read there; the run's last step is always a key.
std::map<std::int64_t, std::vector<std::size_t>> value_reads(const SweepSpec& spec,
                                                             const Marks& marks, double step) {
  std::map<std::int64_t, std::vector<std::size_t>> reads;
  const auto step_of = [&](double t) { return static_cast<std::int64_t>(std::llround(t / step)); };
  const std::int64_t end_step = step_of(marks.end);
  for (std::size_t i = 0; i < spec.record.values.size(); ++i) {
    const std::int64_t at = step_of(marks.absolute(spec.record.values[i].at));
    if (at < 0 || at > end_step)
      throw Error("value '" + spec.record.values[i].name + "' is read at " +
                  number_text(at * step) + " s, outside the run (0 to " + number_text(marks.end) +
                  " s)");
    reads[at].push_back(i);
  }
  reads[end_step];
  return reads;
}

// The run's record columns: values, summaries, then derived columns (which see the plan's).
std::vector<std::string> record_cells(const Sweep::Compiled& c,
                                      const std::vector<Cell>& plan_values,
                                      const std::vector<Cell>& values,
                                      const std::vector<WindowedStat>& summaries, double period) {
  std::vector<Cell> row = plan_values;
  row.insert(row.end(), values.begin(), values.end());
  for (const WindowedStat& s : summaries) row.push_back(s.result(period));
  for (const Expression& e : c.derived) row.push_back(e.evaluate(row));
  std::vector<std::string> cells;
  for (std::size_t i = plan_values.size(); i < row.size(); ++i) cells.push_back(cell_text(row[i]));
  return cells;
}

}  // namespace

std::vector<std::string> execute_run(const Sweep& sweep, const Sweep::Compiled& c,
                                     const RunPlan& run, std::string& trace_csv) {
  const SweepSpec& spec = sweep.spec();
  RunWorld world(spec, run);
  console::SimSession* session = &world.session();
  auto& sim = session->simulation();
  if (sim.robot_count() == 0) throw Error(scene_path_of(spec, run) + ": the scene has no robot");
  std::optional<console::WalkFrameObserver> walk;
  // Through LoLA the observer always runs: only it knows the pattern robot 0 plays elsewhere.
  if (c.walk_frame || world.through_lola()) walk.emplace(*session, world.walk());
  Marks marks;
  marks.walk = world.walk();
  if (spec.until.mark == "end") throw Error("the run's length cannot be relative to its end");
  // The run ends on the physics step nearest its mark, and a summary through the end includes that
  // step's frame: an end of 2 + 10.799999999999999 + 1 s is step 13800, whose frame is at 13.8 s.
  const double step = sim.scene().physics.step;
  marks.end = static_cast<double>(std::llround(marks.absolute(spec.until) / step)) * step;

  std::vector<WindowedStat> summaries;
  for (const SummarySpec& s : spec.record.summaries)
    summaries.emplace_back(bound_of(s.from, marks), bound_of(s.to, marks), s.to_inclusive,
                           SummaryStat(s.stat, s.threshold));
  const std::vector<Cell> plan_values = plan_cells(run);
  const auto traced = run_trace(spec, c, plan_values, marks, trace_csv);
  const Sweep::Compiled::Trace* trace = traced.first;
  const std::optional<WindowBound> trace_from = traced.second;
  // A trace's keys are bound only in the runs it traces (through LoLA a controller's
  // representation cannot be read, and an untraced run need not read it).
  std::vector<bool> needed(c.frame_keys.size());
  for (std::size_t k = 0; k < needed.size(); ++k) needed[k] = !c.trace_only[k];
  if (trace)
    for (const int k : trace->keys) needed[static_cast<std::size_t>(k)] = true;
  FrameKeys keys(*session, walk ? &*walk : nullptr, c.frame_keys, needed);

  world.set_frame_observer([&](sim::SimulatedRobot& robot) {
    if (walk) walk->observe(robot);
    keys.sample();
    const double t = robot.latest_sensors().time;
    const double pattern_t = walk ? walk->frame().pattern_t : 0.0;
    for (std::size_t i = 0; i < summaries.size(); ++i) {
      WindowedStat& s = summaries[i];
      if (!s.admits(t, pattern_t)) continue;
      if (c.summaries[i].until && c.summaries[i].until->truth(keys.values())) {
        s.stop();
        continue;
      }
      s.add(t, std::get<double>(keys.values()[static_cast<std::size_t>(c.summaries[i].key)]));
    }
    if (trace && trace_from->of(t, pattern_t) >= trace_from->value)
      append_trace_row(trace_csv, trace->keys, keys.values());
  });

  // Run to each time a value is read, then to the end.
  std::vector<Cell> values(spec.record.values.size());
  for (const auto& [at, which] : value_reads(spec, marks, step)) {
    while (static_cast<std::int64_t>(sim.steps()) < at) sim.step();
    for (std::size_t i : which)
      values[i] = read_key(*session, walk ? &*walk : nullptr, spec.record.values[i].key);
  }

  world.finish();
  return record_cells(c, plan_values, values, summaries, sim.robot(0).period());
}

}  // namespace stride::sweep
