#pragma once
// What a sole feels when it lands (thesis Ch. 6): for every touch-down of either foot while
// counting, the impulse the floor gave in the first 10 ms, the largest 10 ms mean of the true
// vertical load in the 100 ms after it, the largest FSR reading (the sensors' own frame mean,
// which saturates at 25 N per sensor) in that time, and whether the sole came free again
// (a rebound). Observed once per control frame from the per-step sole loads. A sweep reads the
// summary of the touch-downs after the walk's start as `landing.<field>`.
#include <array>
#include <string_view>
#include <utility>
#include <vector>

#include "robot/framework/reflect.hpp"
#include "simulator/simulated_robot.hpp"
#include "simulator/world/physics_world.hpp"

namespace stride::sim {

struct Touchdown {
  int foot = 0;            // 0 left, 1 right
  double time = 0;         // s, first physics step with load
  double impulse = 0;      // N s in the first 10 ms
  double peak_force = 0;   // N, largest 10 ms mean of the true load within 100 ms
  double peak_fsr = 0;     // N, largest FSR total of the foot within 100 ms
  bool rebounded = false;  // the load fell back below the contact threshold within 100 ms
};

struct LandingMetricsResult {
  STRIDE_FIELDS(LandingMetricsResult);
  STRIDE_FIELD(int, touchdowns) = 0;
  // over the touch-downs
  STRIDE_FIELD(double, mean_impulse, "N*s") = 0;
  STRIDE_FIELD(double, mean_peak_force, "N") = 0;
  STRIDE_FIELD(double, mean_peak_fsr, "N") = 0;
  STRIDE_FIELD(double, max_peak_force, "N") = 0;
  STRIDE_FIELD(double, max_peak_fsr, "N") = 0;
  STRIDE_FIELD(int, rebounds) = 0;

  static constexpr std::string_view kTypeName = "LandingMetricsResult";
};

// The means, maxima and rebound count of the touch-downs at or after time `from` (s).
LandingMetricsResult summarize_touchdowns(const std::vector<Touchdown>& touchdowns, double from);

// The floor's vertical force (N, world z, pushing up) on one link of one robot, summed over the
// solver's contacts of this step: the trace a single landing is read from.
double vertical_floor_force(const PhysicsWorld& world, int robot, int link);

// One landing read from a per-frame trace of the vertical floor force (a foot set down once, the
// Ch. 6 study): the same 10 ms impulse and 10 ms means as a touch-down above, looked at for 0.2 s.
struct LandingTraceSummary {
  double touchdown = -1;   // s, first sample above the contact load
  double impulse = 0;      // N s the floor gave in the 10 ms from touchdown
  double peak_force = 0;   // N, largest 10 ms mean of the force in the 0.2 s after it
  double peak_at = 0;      // s after touchdown (end of that 10 ms window)
  int lift_offs = 0;       // times the sole came free (< 0.1 N) after carrying load
  double final_force = 0;  // N, mean over the trace's last 0.1 s before `end`
};

// `trace`: (time s, force N) once per control frame of `period` s; `end`: the run's length.
LandingTraceSummary summarize_landing_trace(const std::vector<std::pair<double, double>>& trace,
                                            double period, double end);

class LandingMetrics {
 public:
  // `contact`: load (N) that means touching; a touch-down needs `airborne` s below it before.
  explicit LandingMetrics(double contact = 1.0, double airborne = 0.02)
      : contact_(contact), airborne_(airborne) {}
  // Once per control frame; touch-downs are recorded only while `counting`, but open ones finish.
  void observe(const SimulatedRobot& robot, bool counting = true);
  LandingMetricsResult result(double from = 0) const { return summarize_touchdowns(done_, from); }
  const std::vector<Touchdown>& touchdowns() const { return done_; }

 private:
  struct Foot {
    double unloaded = 1e9;  // s the load has been below contact
    bool open = false;      // a touch-down within its 100 ms window
    Touchdown current;
    std::vector<double> loads;  // per step since the touch-down
    bool loaded = false;        // has carried more than the rebound threshold since touch-down
  };
  void step(Foot& f, int foot, double t, double load, double dt, bool counting);
  void close(Foot& f);

  double contact_, airborne_;
  std::array<Foot, 2> feet_;
  std::vector<Touchdown> done_;
};

}  // namespace stride::sim
