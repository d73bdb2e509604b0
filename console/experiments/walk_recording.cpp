#include "console/experiments/walk_recording.hpp"

#include <algorithm>

#include "console/session/sim_session.hpp"
#include "robot/core/error.hpp"

namespace stride::experiments {

plot::Table trace_table(const WalkRecording& r) {
  plot::Table t;
  for_each_field<console::WalkFrame>([&](const auto& f) { t.columns.emplace_back(f.name); });
  for (const console::WalkFrame& frame : r.frames) {
    std::vector<double> row;
    for_each_field<console::WalkFrame>([&](const auto& f) { row.push_back(frame.*(f.member)); });
    t.add_row(std::move(row));
  }
  return t;
}

WalkRecording record_walk(const WalkSetup& setup) {
  console::SimSession session(setup.scene, setup.seed);
  Runtime* rt = session.runtime(0);
  if (!rt) throw Error("experiment scene '" + setup.scene + "': robot 0 has no <controller>");
  for (const auto& [representation, module] : setup.providers)
    rt->swap_provider(representation, module);
  for (const auto& [module, text] : setup.parameters) {
    try {
      rt->set_parameters(module, text);
    } catch (const Error& e) {
      throw Error(setup.scene + ": parameters " + module + " '" + text + "': " + e.what());
    }
  }
  console::WalkFrameObserver observer(session);
  if (!observer.pattern())
    throw Error("experiment scene '" + setup.scene +
                "': WalkingJointRequest must come from PatternWalk or ConventionalWalk, not '" +
                rt->provider_of("WalkingJointRequest") + "'");
  WalkRecording r;
  r.walk_module = observer.pattern()->module;
  r.walk_duration = observer.pattern()->duration;
  r.period = session.simulation().robot(0).period();
  session.set_frame_observer(0, [&](sim::SimulatedRobot& robot) {
    observer.observe(robot);
    r.frames.push_back(observer.frame());
  });
  // Steps are counted up to the last landing: after the stop the robot rocks and unloads a foot,
  // which the FSR step count would take for steps; a fall is looked for until the end.
  const double last_landing = 0.05;
  session.simulation().run_for(observer.pattern()->start_delay + r.walk_duration + last_landing);
  r.metrics = session.simulation().walk_metrics(0).result();
  session.simulation().run_for(std::max(setup.settle_seconds - last_landing, 0.0));
  const sim::WalkMetricsResult end = session.simulation().walk_metrics(0).result();
  r.metrics.fell = end.fell;
  r.metrics.fell_at = end.fell_at;
  r.metrics.tipped = end.tipped;
  r.metrics.tipped_at = end.tipped_at;
  return r;
}

WalkSummary summarize(const WalkRecording& r) {
  WalkSummary s;
  s.steps = r.metrics.steps;
  s.fk_distance = r.metrics.fk_distance;
  s.fell = r.metrics.fell;
  s.tipped = r.metrics.tipped;
  s.tipped_at = r.metrics.tipped_at;
  bool first = true;
  double x0 = 0, x1 = 0;
  for (const console::WalkFrame& f : r.frames) {
    if (f.pattern_t < 0) continue;
    if (first) {
      x0 = f.feet_x;
      s.pitch_min = s.pitch_max = f.true_pitch;
      s.roll_min = s.roll_max = f.true_roll;
      first = false;
    }
    x1 = f.feet_x;
    s.pitch_min = std::min(s.pitch_min, f.true_pitch),
    s.pitch_max = std::max(s.pitch_max, f.true_pitch);
    s.roll_min = std::min(s.roll_min, f.true_roll), s.roll_max = std::max(s.roll_max, f.true_roll);
  }
  s.distance = x1 - x0;
  if (r.walk_duration > 0) s.speed = s.distance / r.walk_duration;
  if (s.steps > 0) s.step_length = s.distance / s.steps;
  return s;
}

}  // namespace stride::experiments
