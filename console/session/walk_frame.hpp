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
  STRIDE_FIELDS(WalkFrame);
  STRIDE_FIELD(double, t, "s") = 0;  // s, simulation time
  // s since the walking pattern started (negative while standing; NaN when robot 0 walks no
  // pattern)
  STRIDE_FIELD(double, pattern_t, "s") = 0;
  STRIDE_FIELD(double, hip_pitch_ref_l, "rad") = 0;
  STRIDE_FIELD(double, hip_pitch_mod_l, "rad") = 0;
  STRIDE_FIELD(double, hip_roll_ref_l, "rad") = 0;
  STRIDE_FIELD(double, hip_roll_mod_l, "rad") = 0;
  STRIDE_FIELD(double, hip_pitch_ref_r, "rad") = 0;
  STRIDE_FIELD(double, hip_pitch_mod_r, "rad") = 0;
  STRIDE_FIELD(double, hip_roll_ref_r, "rad") = 0;
  STRIDE_FIELD(double, hip_roll_mod_r, "rad") = 0;
  STRIDE_FIELD(double, ankle_pitch_ref_l, "rad") = 0;
  STRIDE_FIELD(double, ankle_pitch_mod_l, "rad") = 0;
  STRIDE_FIELD(double, ankle_roll_ref_l, "rad") = 0;
  STRIDE_FIELD(double, ankle_roll_mod_l, "rad") = 0;
  STRIDE_FIELD(double, ankle_pitch_ref_r, "rad") = 0;
  STRIDE_FIELD(double, ankle_pitch_mod_r, "rad") = 0;
  STRIDE_FIELD(double, ankle_roll_ref_r, "rad") = 0;
  STRIDE_FIELD(double, ankle_roll_mod_r, "rad") = 0;
  // TorsoState
  STRIDE_FIELD(double, est_pitch, "rad") = 0;
  STRIDE_FIELD(double, est_roll, "rad") = 0;
  STRIDE_FIELD(double, est_pitch_rate, "rad/s") = 0;
  STRIDE_FIELD(double, est_roll_rate, "rad/s") = 0;
  STRIDE_FIELD(double, true_pitch, "rad") = 0;
  STRIDE_FIELD(double, true_roll, "rad") = 0;
  STRIDE_FIELD(double, true_pitch_rate, "rad/s") = 0;
  STRIDE_FIELD(double, true_roll_rate, "rad/s") = 0;
  // raw IMU
  STRIDE_FIELD(double, imu_pitch, "rad") = 0;
  STRIDE_FIELD(double, imu_roll, "rad") = 0;
  STRIDE_FIELD(double, gyro_pitch, "rad/s") = 0;
  STRIDE_FIELD(double, gyro_roll, "rad/s") = 0;
  // m/s forward: pattern and true torso
  STRIDE_FIELD(double, waist_v_ref, "m/s") = 0;
  STRIDE_FIELD(double, waist_v, "m/s") = 0;
  STRIDE_FIELD(double, torso_x, "m") = 0;
  STRIDE_FIELD(double, torso_y, "m") = 0;
  STRIDE_FIELD(double, feet_x, "m") = 0;
  // m, world CoP from the FSRs (NaN when airborne)
  STRIDE_FIELD(double, cop_x, "m") = 0;
  STRIDE_FIELD(double, cop_y, "m") = 0;
  // m, the pattern's ZMP (Eq. 3.16)
  STRIDE_FIELD(double, zmp_ref_x, "m") = 0;
  STRIDE_FIELD(double, zmp_ref_y, "m") = 0;
  // rad, commanded
  STRIDE_FIELD(double, shoulder_pitch_l, "rad") = 0;
  STRIDE_FIELD(double, shoulder_pitch_r, "rad") = 0;
  STRIDE_FIELD(double, knee_current_l, "A") = 0;
  STRIDE_FIELD(double, knee_current_r, "A") = 0;
  STRIDE_FIELD(double, torso_z, "m") = 0;
  STRIDE_FIELD(double, torso_yaw, "rad") = 0;
  STRIDE_FIELD(double, feet_y, "m") = 0;
  STRIDE_FIELD(double, com_x, "m") = 0;
  STRIDE_FIELD(double, com_y, "m") = 0;
  STRIDE_FIELD(double, com_z, "m") = 0;
  STRIDE_FIELD(double, fell) = 0;  // 1 once the robot lies fallen

  static constexpr std::string_view kTypeName = "WalkFrame";
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

}  // namespace stride::console
