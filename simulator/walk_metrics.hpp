#pragma once
// What a walking experiment reports, observed every control frame of one robot: steps, distance
// and speed both as the thesis measured them on the robot (forward kinematics between the feet in
// each double support, from the measured joint angles) and from the simulator's ground truth,
// average step length, torso pitch/roll extremes, whether it fell, and how the feet behaved while
// they carried load (sliding, tilting on an edge): the ground truth behind a distance.
#include <array>
#include <string>

#include "robot/framework/reflect.hpp"
#include "simulator/simulated_robot.hpp"

namespace stride::sim {

// Which way the torso first passed kTipAngle (pitch > 0 leans forward, roll > 0 leans right).
enum class Tip { None, Forward, Backward, Right, Left };
const char* tip_name(Tip t);  // "none", "forward", ...
}  // namespace stride::sim

template <>
struct stride::EnumNames<stride::sim::Tip> {
  static constexpr std::string_view type_name = "Tip";
  static constexpr std::array<std::string_view, 5> names{"none", "forward", "backward", "right",
                                                         "left"};
};

namespace stride::sim {

// The torso tilt the Ch. 4 experiments count as lost balance even without a fall (teams use
// 0.4-0.6 rad as a fall threshold on the real NAO).
inline constexpr double kTipAngle = 0.4;

struct WalkMetricsResult {
  STRIDE_FIELDS(WalkMetricsResult);
  // double supports entered after a single support
  STRIDE_FIELD(int, steps) = 0;
  // m, sum of FK step lengths (thesis' method)
  STRIDE_FIELD(double, fk_distance, "m") = 0;
  // m, ground-truth advance of the feet's midpoint
  STRIDE_FIELD(double, true_distance, "m") = 0;
  STRIDE_FIELD(double, torso_distance, "m") = 0;  // m, ground-truth torso advance
  STRIDE_FIELD(double, duration, "s") = 0;        // s, observed time
  STRIDE_FIELD(double, fk_speed, "m/s") = 0;
  STRIDE_FIELD(double, true_speed, "m/s") = 0;
  STRIDE_FIELD(double, mean_step_length, "m") = 0;  // m, ground truth
  // rad, torso
  STRIDE_FIELD(double, pitch_min, "rad") = 0;
  STRIDE_FIELD(double, pitch_max, "rad") = 0;
  STRIDE_FIELD(double, roll_min, "rad") = 0;
  STRIDE_FIELD(double, roll_max, "rad") = 0;
  // rad, torso heading (unwrapped) relative to the first frame
  STRIDE_FIELD(double, yaw_min, "rad") = 0;
  STRIDE_FIELD(double, yaw_max, "rad") = 0;
  STRIDE_FIELD(bool, fell) = false;
  STRIDE_FIELD(double, fell_at, "s") = -1;
  STRIDE_FIELD(Tip, tipped) = Tip::None;  // the first pass of kTipAngle in pitch or roll
  STRIDE_FIELD(double, tipped_at, "s") = -1;
  // m, summed horizontal displacement of each foot per stance
  STRIDE_FIELD(double, foot_slip, "m") = 0;
  // m, signed forward part of it (negative: feet slid back)
  STRIDE_FIELD(double, foot_slip_net_x, "m") = 0;
  // rad, largest sole tilt from the vertical while loaded
  STRIDE_FIELD(double, foot_tilt_max, "rad") = 0;
  // s, time a loaded foot was tilted by more than kTiltedFoot
  STRIDE_FIELD(double, foot_tilted_time, "s") = 0;
  // rad, summed |net yaw turn| of each foot per stance (Sec. 4.4)
  STRIDE_FIELD(double, foot_spin, "rad") = 0;
  // rad, the largest turn of one foot in one stance
  STRIDE_FIELD(double, foot_spin_max, "rad") = 0;

  // The list that names a run report's walk fields and a sweep's `walk.<field>` keys.
  static constexpr std::string_view kTypeName = "WalkMetricsResult";
};

// A loaded sole tilted beyond this rocks on an edge rather than standing flat (1.15 deg; the
// default uneven floor's tiles tilt up to 1 deg).
inline constexpr double kTiltedFoot = 0.02;

class WalkMetrics {
 public:
  explicit WalkMetrics(double load_threshold = 5.0) : threshold_(load_threshold) {}
  void observe(const SimulatedRobot& robot);  // once per control frame
  WalkMetricsResult result() const;

 private:
  struct Stance {  // one foot's current loaded interval
    bool active = false;
    Eigen::Vector2d start = Eigen::Vector2d::Zero(), last = Eigen::Vector2d::Zero();
    double yaw = 0;     // rad, the foot's heading at the last loaded frame
    double turned = 0;  // rad, unwrapped net yaw change since loading
  };
  void observe_feet(const SimulatedRobot& robot, double left_load, double right_load, double frame);
  static void close_stance(const Stance& s, WalkMetricsResult& r);

  double threshold_;
  int lfoot_ = -2, rfoot_ = -2;  // link indices, looked up on the first frame (-1: no such link)
  bool started_ = false;
  double t0_ = 0, t_ = 0;
  double x0_mid_ = 0, x0_torso_ = 0, x_mid_ = 0, x_torso_ = 0;
  bool in_single_support_ = false;
  Stance stance_[2];
  double torso_yaw_ = 0, torso_turned_ = 0;  // last heading; unwrapped change since the start
  WalkMetricsResult r_;
};

std::string walk_metrics_text(const WalkMetricsResult& r);

}  // namespace stride::sim
