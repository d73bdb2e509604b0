#pragma once
// What the Ch. 4 figures show of a walk, one row per control frame of robot 0: reference and
// modified hip/ankle angles, torso inclination estimated and true, waist velocity planned and
// true, the CoP from the FSRs in the world frame, shoulder pitch, knee currents, IMU inputs, and
// where the torso, CoM and feet are. A reflected struct: its field list names the trace columns,
// the sweep keys `frame.<field>` and the recorder's CSV header. Read by observing a SimSession,
// never by replacing its controller, so a scene's timed changes still apply.
#include <optional>
#include <string>

#include "behaviours/walking/modules/walk_pattern_replay.hpp"
#include "console/session/sim_session.hpp"
#include "robot/framework/reflect.hpp"

namespace stride::console {

struct WalkFrame {
  double t = 0;          // s, simulation time
  double pattern_t = 0;  // s since the walking pattern started (negative while standing; NaN
                         // when robot 0 walks no pattern)
  double hip_pitch_ref_l = 0, hip_pitch_mod_l = 0, hip_roll_ref_l = 0, hip_roll_mod_l = 0;
  double hip_pitch_ref_r = 0, hip_pitch_mod_r = 0, hip_roll_ref_r = 0, hip_roll_mod_r = 0;
  double ankle_pitch_ref_l = 0, ankle_pitch_mod_l = 0, ankle_roll_ref_l = 0, ankle_roll_mod_l = 0;
  double ankle_pitch_ref_r = 0, ankle_pitch_mod_r = 0, ankle_roll_ref_r = 0, ankle_roll_mod_r = 0;
  double est_pitch = 0, est_roll = 0, est_pitch_rate = 0, est_roll_rate = 0;  // TorsoState
  double true_pitch = 0, true_roll = 0, true_pitch_rate = 0, true_roll_rate = 0;
  double imu_pitch = 0, imu_roll = 0, gyro_pitch = 0, gyro_roll = 0;  // raw IMU
  double waist_v_ref = 0, waist_v = 0;  // m/s forward: pattern and true torso
  double torso_x = 0, torso_y = 0, feet_x = 0;
  double cop_x = 0, cop_y = 0;          // m, world CoP from the FSRs (NaN when airborne)
  double zmp_ref_x = 0, zmp_ref_y = 0;  // m, the pattern's ZMP (Eq. 3.16)
  double shoulder_pitch_l = 0, shoulder_pitch_r = 0;  // rad, commanded
  double knee_current_l = 0, knee_current_r = 0;      // A
  double torso_z = 0, torso_yaw = 0, feet_y = 0;
  double com_x = 0, com_y = 0, com_z = 0;
  double fell = 0;  // 1 once the robot lies fallen

  static constexpr std::string_view kTypeName = "WalkFrame";
  static constexpr auto fields();
};

// The walking pattern robot 0's controller plays (behaviours/walking/modules/walk_pattern_replay).
using WalkPatternInfo = behaviours::WalkPatternInfo;
// nullopt when robot 0 has no controller or its WalkingJointRequest comes from elsewhere.
std::optional<WalkPatternInfo> walk_pattern_info(SimSession& session);

// Fills a WalkFrame at every control frame of robot 0 of `session` (it must outlive the
// observer). Entries a scene cannot give (no TorsoState, no pattern) are NaN.
class WalkFrameObserver {
 public:
  explicit WalkFrameObserver(SimSession& session);
  // With the pattern given: robot 0's controller runs elsewhere (a robot process on LoLA), so
  // the session cannot say which pattern it plays; the columns only it could give are NaN.
  WalkFrameObserver(SimSession& session, std::optional<WalkPatternInfo> pattern);
  ~WalkFrameObserver();
  WalkFrameObserver(const WalkFrameObserver&) = delete;
  WalkFrameObserver& operator=(const WalkFrameObserver&) = delete;

  const std::optional<WalkPatternInfo>& pattern() const { return info_; }
  // The row of the latest control frame (all zero before the first).
  const WalkFrame& frame() const { return frame_; }
  // Computes frame() for the control frame that just ended.
  void observe(const sim::SimulatedRobot& robot);

 private:
  struct Previous {
    double t, x, pitch, roll;
  };
  void joints(WalkFrame& f) const;
  void pattern_columns(WalkFrame& f, double t);

  Runtime* rt_ = nullptr;
  std::optional<WalkPatternInfo> info_;
  std::optional<behaviours::WalkPatternReplay> pattern_;
  bool has_torso_state_ = false, has_walking_request_ = false;
  int lfoot_ = -1, rfoot_ = -1;
  std::optional<double> first_time_;
  std::optional<Previous> previous_;
  double origin_x_ = 0, origin_y_ = 0;
  WalkFrame frame_;
};

constexpr auto WalkFrame::fields() {
  using F = WalkFrame;
  return std::make_tuple(
      field("t", &F::t, "s"), field("pattern_t", &F::pattern_t, "s"),
      field("hip_pitch_ref_l", &F::hip_pitch_ref_l, "rad"),
      field("hip_pitch_mod_l", &F::hip_pitch_mod_l, "rad"),
      field("hip_roll_ref_l", &F::hip_roll_ref_l, "rad"),
      field("hip_roll_mod_l", &F::hip_roll_mod_l, "rad"),
      field("hip_pitch_ref_r", &F::hip_pitch_ref_r, "rad"),
      field("hip_pitch_mod_r", &F::hip_pitch_mod_r, "rad"),
      field("hip_roll_ref_r", &F::hip_roll_ref_r, "rad"),
      field("hip_roll_mod_r", &F::hip_roll_mod_r, "rad"),
      field("ankle_pitch_ref_l", &F::ankle_pitch_ref_l, "rad"),
      field("ankle_pitch_mod_l", &F::ankle_pitch_mod_l, "rad"),
      field("ankle_roll_ref_l", &F::ankle_roll_ref_l, "rad"),
      field("ankle_roll_mod_l", &F::ankle_roll_mod_l, "rad"),
      field("ankle_pitch_ref_r", &F::ankle_pitch_ref_r, "rad"),
      field("ankle_pitch_mod_r", &F::ankle_pitch_mod_r, "rad"),
      field("ankle_roll_ref_r", &F::ankle_roll_ref_r, "rad"),
      field("ankle_roll_mod_r", &F::ankle_roll_mod_r, "rad"),
      field("est_pitch", &F::est_pitch, "rad"), field("est_roll", &F::est_roll, "rad"),
      field("est_pitch_rate", &F::est_pitch_rate, "rad/s"),
      field("est_roll_rate", &F::est_roll_rate, "rad/s"),
      field("true_pitch", &F::true_pitch, "rad"), field("true_roll", &F::true_roll, "rad"),
      field("true_pitch_rate", &F::true_pitch_rate, "rad/s"),
      field("true_roll_rate", &F::true_roll_rate, "rad/s"),
      field("imu_pitch", &F::imu_pitch, "rad"), field("imu_roll", &F::imu_roll, "rad"),
      field("gyro_pitch", &F::gyro_pitch, "rad/s"), field("gyro_roll", &F::gyro_roll, "rad/s"),
      field("waist_v_ref", &F::waist_v_ref, "m/s"), field("waist_v", &F::waist_v, "m/s"),
      field("torso_x", &F::torso_x, "m"), field("torso_y", &F::torso_y, "m"),
      field("feet_x", &F::feet_x, "m"), field("cop_x", &F::cop_x, "m"),
      field("cop_y", &F::cop_y, "m"), field("zmp_ref_x", &F::zmp_ref_x, "m"),
      field("zmp_ref_y", &F::zmp_ref_y, "m"),
      field("shoulder_pitch_l", &F::shoulder_pitch_l, "rad"),
      field("shoulder_pitch_r", &F::shoulder_pitch_r, "rad"),
      field("knee_current_l", &F::knee_current_l, "A"),
      field("knee_current_r", &F::knee_current_r, "A"), field("torso_z", &F::torso_z, "m"),
      field("torso_yaw", &F::torso_yaw, "rad"), field("feet_y", &F::feet_y, "m"),
      field("com_x", &F::com_x, "m"), field("com_y", &F::com_y, "m"),
      field("com_z", &F::com_z, "m"), field("fell", &F::fell));
}

}  // namespace stride::console
