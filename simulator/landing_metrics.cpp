#include "simulator/landing_metrics.hpp"

#include <algorithm>

namespace stride::sim {

namespace {
constexpr double kWindow = 0.1;    // s after touch-down that is looked at
constexpr double kImpulse = 0.01;  // s of the impulse
constexpr double kMean = 0.01;     // s of the peak's moving mean
constexpr double kRebound = 5.0;   // N carried before a drop below contact counts as a rebound
}  // namespace

void LandingMetrics::observe(const SimulatedRobot& robot, bool counting) {
  const hal::SensorFrame& s = robot.latest_sensors();
  for (int f = 0; f < 2; ++f) {
    const std::vector<double>& loads = robot.sole_loads(f);
    if (loads.empty()) continue;
    const double dt = robot.period() / static_cast<double>(loads.size());
    const double frame_start = s.time - robot.period();
    for (std::size_t k = 0; k < loads.size(); ++k)
      step(feet_[f], f, frame_start + (k + 1) * dt, loads[k], dt, counting);
    if (feet_[f].open) {
      double fsr = 0;
      for (int i = 0; i < 4; ++i) fsr += s.fsr[f * 4 + i];
      feet_[f].current.peak_fsr = std::max(feet_[f].current.peak_fsr, fsr);
    }
  }
}

void LandingMetrics::step(Foot& f, int foot, double t, double load, double dt, bool counting) {
  if (f.open) {
    f.loads.push_back(load);
    const double since = t - f.current.time;
    if (since < kImpulse - 1e-9) f.current.impulse += load * dt;
    const auto n = static_cast<std::size_t>(kMean / dt + 0.5);
    if (f.loads.size() >= n) {
      double mean = 0;
      for (std::size_t i = f.loads.size() - n; i < f.loads.size(); ++i) mean += f.loads[i] / n;
      f.current.peak_force = std::max(f.current.peak_force, mean);
    }
    if (load > kRebound) f.loaded = true;
    if (f.loaded && load < contact_) f.current.rebounded = true;
    if (since >= kWindow - 1e-9) close(f);
  }
  if (load < contact_) {
    f.unloaded += dt;
    return;
  }
  if (!f.open && f.unloaded >= airborne_ && counting) {
    f.open = true;
    f.loaded = load > kRebound;
    f.current = Touchdown{foot, t, load * dt, 0, 0, false};
    f.loads.assign(1, load);
  }
  f.unloaded = 0;
}

void LandingMetrics::close(Foot& f) {
  done_.push_back(f.current);
  f.open = false;
  f.loads.clear();
}

LandingMetricsResult summarize_touchdowns(const std::vector<Touchdown>& touchdowns, double from) {
  LandingMetricsResult r;
  for (const Touchdown& t : touchdowns) {
    if (t.time < from) continue;
    ++r.touchdowns;
    r.mean_impulse += t.impulse;
    r.mean_peak_force += t.peak_force;
    r.mean_peak_fsr += t.peak_fsr;
    r.max_peak_force = std::max(r.max_peak_force, t.peak_force);
    r.max_peak_fsr = std::max(r.max_peak_fsr, t.peak_fsr);
    r.rebounds += t.rebounded;
  }
  if (r.touchdowns > 0) {
    const double n = r.touchdowns;
    r.mean_impulse /= n, r.mean_peak_force /= n, r.mean_peak_fsr /= n;
  }
  return r;
}

double vertical_floor_force(const PhysicsWorld& world, int robot, int link) {
  double f = 0;
  for (const ContactRecord& c : world.contacts()) {
    const bool is_a = c.a->robot == robot && c.a->link == link;
    const bool is_b = c.b->robot == robot && c.b->link == link;
    if (is_a == is_b) continue;
    f += is_a ? c.force_on_a.z() : c.force_on_b.z();
  }
  return f;
}

LandingTraceSummary summarize_landing_trace(const std::vector<std::pair<double, double>>& force,
                                            double period, double end) {
  // A rigid contact stops the sole within one step, so a single step's force is an impulse over
  // 1 ms; forces are compared as 10 ms means, the scale a sole's FSRs and filter see (Sec. 6.3).
  LandingTraceSummary out;
  bool touching = false;
  double last_sum = 0;
  int last_n = 0;
  for (size_t i = 0; i < force.size(); ++i) {
    const auto [t, f] = force[i];
    if (out.touchdown < 0 && f > 1.0) out.touchdown = t;
    if (out.touchdown >= 0) {
      const double since = t - out.touchdown;
      if (since < 0.01 - 1e-9) out.impulse += f * period;
      if (since <= 0.2 && i >= 9) {
        double mean = 0;
        for (size_t k = i - 9; k <= i; ++k) mean += force[k].second / 10;
        if (mean > out.peak_force) out.peak_force = mean, out.peak_at = since;
      }
      if (touching && f < 0.1) ++out.lift_offs;  // the sole came free after carrying load
      if (f > 1.0) touching = true;
      if (f < 0.1) touching = false;
    }
    if (t > end - 0.1) last_sum += f, ++last_n;
  }
  out.final_force = last_n ? last_sum / last_n : 0;
  return out;
}

}  // namespace stride::sim
