#include "console/experiments/walk_recording.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <variant>

#include "behaviours/posture/posture_representations.hpp"
#include "behaviours/posture/walking_joint_request.hpp"
#include "behaviours/walking/modules/pattern_walk.hpp"
#include "behaviours/walking/modules/walk_parameters.hpp"
#include "behaviours/walking/pattern/walking_pattern.hpp"
#include "console/session/sim_session.hpp"
#include "robot/core/error.hpp"
#include "robot/framework/text.hpp"
#include "robot/representations/joint_request.hpp"
#include "robot/runtime/nao_io_modules.hpp"

namespace stride::experiments {
namespace {

using hal::JointId;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using AnyPattern = std::variant<walking::StretchedKneePattern, walking::ConventionalPattern>;

bool on_blackboard(const Runtime& rt, const std::string& name) {
  const auto names = rt.representation_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

// Appends one row per control frame; reads the runtime's representations and the ground truth.
class TraceRecorder {
 public:
  TraceRecorder(Runtime& rt, const behaviours::WalkParameters& w, AnyPattern pattern,
                plot::Table& table)
      : rt_(rt), walk_(w), pattern_(std::move(pattern)), table_(table) {
    has_torso_state_ = on_blackboard(rt, "TorsoState");
  }

  void record(const sim::SimulatedRobot& robot) {
    const hal::SensorFrame& s = robot.latest_sensors();
    const sim::TorsoPose torso = robot.torso_pose();
    const auto& m = robot.model();
    const Eigen::Isometry3d lf = robot.body().link_pose(m.link_index("LFoot"));
    const Eigen::Isometry3d rf = robot.body().link_pose(m.link_index("RFoot"));
    const double feet_x = 0.5 * (lf.translation().x() + rf.translation().x());
    if (!first_time_) {
      first_time_ = s.time;
      origin_ = Eigen::Vector2d(feet_x, 0.5 * (lf.translation().y() + rf.translation().y()));
    }
    const double t_pattern = behaviours::pattern_time(s.time, *first_time_, walk_.start_delay);
    const walking::PatternSample plan =
        std::visit([&](const auto& p) { return p.sample(std::max(t_pattern, 0.0)); }, pattern_);

    const auto& ref = rt_.representation<WalkingJointRequest>().position;
    const auto& mod = rt_.representation<JointRequest>().position;
    std::vector<double> row(static_cast<std::size_t>(Trace::count), kNaN);
    auto put = [&](Trace c, double v) { row[col(c)] = v; };
    auto pair = [&](Trace c, JointId j) {
      put(c, ref[index(j)]);
      row[col(c) + 1] = mod[index(j)];
    };
    put(Trace::t, s.time);
    put(Trace::pattern_t, t_pattern);
    pair(Trace::hip_pitch_ref_l, JointId::LHipPitch);
    pair(Trace::hip_roll_ref_l, JointId::LHipRoll);
    pair(Trace::hip_pitch_ref_r, JointId::RHipPitch);
    pair(Trace::hip_roll_ref_r, JointId::RHipRoll);
    pair(Trace::ankle_pitch_ref_l, JointId::LAnklePitch);
    pair(Trace::ankle_roll_ref_l, JointId::LAnkleRoll);
    pair(Trace::ankle_pitch_ref_r, JointId::RAnklePitch);
    pair(Trace::ankle_roll_ref_r, JointId::RAnkleRoll);
    if (has_torso_state_) {
      const auto& e = rt_.representation<TorsoState>();
      put(Trace::est_pitch, e.pitch);
      put(Trace::est_roll, e.roll);
      put(Trace::est_pitch_rate, e.pitch_rate);
      put(Trace::est_roll_rate, e.roll_rate);
    }
    const double dt = previous_ ? s.time - previous_->t : 0;
    put(Trace::true_pitch, torso.pitch);
    put(Trace::true_roll, torso.roll);
    put(Trace::true_pitch_rate, dt > 0 ? (torso.pitch - previous_->pitch) / dt : 0);
    put(Trace::true_roll_rate, dt > 0 ? (torso.roll - previous_->roll) / dt : 0);
    put(Trace::imu_pitch, s.angles[1]);
    put(Trace::imu_roll, s.angles[0]);
    put(Trace::gyro_pitch, s.gyroscope[1]);
    put(Trace::gyro_roll, s.gyroscope[0]);
    put(Trace::waist_v_ref, t_pattern >= 0 ? plan.waist_velocity.x() : 0);
    put(Trace::waist_v, dt > 0 ? (torso.x - previous_->x) / dt : 0);
    put(Trace::torso_x, torso.x);
    put(Trace::torso_y, torso.y);
    put(Trace::feet_x, feet_x);
    const FsrSensorData fsr = fsr_sensor_data(s, 2.0);
    if (fsr.cop_torso_valid && fsr.total_left + fsr.total_right > 5.0) {
      const Eigen::Matrix3d r = (Eigen::AngleAxisd(torso.yaw, Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(torso.pitch, Eigen::Vector3d::UnitY()) *
                                 Eigen::AngleAxisd(torso.roll, Eigen::Vector3d::UnitX()))
                                    .toRotationMatrix();
      const Eigen::Vector3d cop = Eigen::Vector3d(torso.x, torso.y, torso.z) + r * fsr.cop_torso;
      put(Trace::cop_x, cop.x());
      put(Trace::cop_y, cop.y());
    }
    put(Trace::zmp_ref_x, origin_.x() + plan.zmp.x());
    put(Trace::zmp_ref_y, origin_.y() + plan.zmp.y());
    put(Trace::shoulder_pitch_l, mod[index(JointId::LShoulderPitch)]);
    put(Trace::shoulder_pitch_r, mod[index(JointId::RShoulderPitch)]);
    put(Trace::knee_current_l, s.current[index(JointId::LKneePitch)]);
    put(Trace::knee_current_r, s.current[index(JointId::RKneePitch)]);
    table_.add_row(std::move(row));
    previous_ = Previous{s.time, torso.x, torso.pitch, torso.roll};
  }

 private:
  struct Previous {
    double t, x, pitch, roll;
  };
  Runtime& rt_;
  behaviours::WalkParameters walk_;
  AnyPattern pattern_;
  plot::Table& table_;
  bool has_torso_state_ = false;
  std::optional<double> first_time_;
  std::optional<Previous> previous_;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
};

}  // namespace

const std::vector<std::string>& trace_columns() {
  static const std::vector<std::string> names = {"t",
                                                 "pattern_t",
                                                 "hip_pitch_ref_l",
                                                 "hip_pitch_mod_l",
                                                 "hip_roll_ref_l",
                                                 "hip_roll_mod_l",
                                                 "hip_pitch_ref_r",
                                                 "hip_pitch_mod_r",
                                                 "hip_roll_ref_r",
                                                 "hip_roll_mod_r",
                                                 "ankle_pitch_ref_l",
                                                 "ankle_pitch_mod_l",
                                                 "ankle_roll_ref_l",
                                                 "ankle_roll_mod_l",
                                                 "ankle_pitch_ref_r",
                                                 "ankle_pitch_mod_r",
                                                 "ankle_roll_ref_r",
                                                 "ankle_roll_mod_r",
                                                 "est_pitch",
                                                 "est_roll",
                                                 "est_pitch_rate",
                                                 "est_roll_rate",
                                                 "true_pitch",
                                                 "true_roll",
                                                 "true_pitch_rate",
                                                 "true_roll_rate",
                                                 "imu_pitch",
                                                 "imu_roll",
                                                 "gyro_pitch",
                                                 "gyro_roll",
                                                 "waist_v_ref",
                                                 "waist_v",
                                                 "torso_x",
                                                 "torso_y",
                                                 "feet_x",
                                                 "cop_x",
                                                 "cop_y",
                                                 "zmp_ref_x",
                                                 "zmp_ref_y",
                                                 "shoulder_pitch_l",
                                                 "shoulder_pitch_r",
                                                 "knee_current_l",
                                                 "knee_current_r"};
  return names;
}

WalkRecording record_walk(const WalkSetup& setup) {
  static_assert(static_cast<int>(Trace::count) == 43);
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

  WalkRecording r;
  r.walk_module = rt->provider_of("WalkingJointRequest");
  if (r.walk_module != "PatternWalk" && r.walk_module != "ConventionalWalk")
    throw Error("experiment scene '" + setup.scene +
                "': WalkingJointRequest must come from PatternWalk or ConventionalWalk, not '" +
                r.walk_module + "'");
  behaviours::WalkParameters w;
  update_from_text(w, rt->get("module:" + r.walk_module));
  const walking::PatternParameters p = behaviours::walk_pattern_parameters(w);
  AnyPattern pattern = r.walk_module == "PatternWalk" ? AnyPattern(walking::StretchedKneePattern(p))
                                                      : AnyPattern(walking::ConventionalPattern(p));
  r.walk_duration = std::visit([](const auto& x) { return x.duration(); }, pattern);
  r.period = session.simulation().robot(0).period();
  r.trace.columns = trace_columns();

  TraceRecorder recorder(*rt, w, std::move(pattern), r.trace);
  session.simulation().set_controller(0, [rt, &recorder](sim::SimulatedRobot& robot) {
    rt->step();
    recorder.record(robot);
  });
  // Steps are counted up to the last landing: after the stop the robot rocks and unloads a foot,
  // which the FSR step count would take for steps; a fall is looked for until the end.
  const double last_landing = 0.05;
  session.simulation().run_for(w.start_delay + r.walk_duration + last_landing);
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
  const auto& rows = r.trace.rows;
  bool first = true;
  double x0 = 0, x1 = 0;
  for (const auto& row : rows) {
    const double tp = row[col(Trace::pattern_t)];
    if (tp < 0) continue;
    const double pitch = row[col(Trace::true_pitch)], roll = row[col(Trace::true_roll)];
    if (first) {
      x0 = row[col(Trace::feet_x)];
      s.pitch_min = s.pitch_max = pitch;
      s.roll_min = s.roll_max = roll;
      first = false;
    }
    x1 = row[col(Trace::feet_x)];
    s.pitch_min = std::min(s.pitch_min, pitch), s.pitch_max = std::max(s.pitch_max, pitch);
    s.roll_min = std::min(s.roll_min, roll), s.roll_max = std::max(s.roll_max, roll);
  }
  s.distance = x1 - x0;
  if (r.walk_duration > 0) s.speed = s.distance / r.walk_duration;
  if (s.steps > 0) s.step_length = s.distance / s.steps;
  return s;
}

}  // namespace stride::experiments
