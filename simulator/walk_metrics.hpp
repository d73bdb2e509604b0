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
  int steps = 0;                        // double supports entered after a single support
  double fk_distance = 0;               // m, sum of FK step lengths (thesis' method)
  double true_distance = 0;             // m, ground-truth advance of the feet's midpoint
  double torso_distance = 0;            // m, ground-truth torso advance
  double duration = 0;                  // s, observed time
  double fk_speed = 0, true_speed = 0;  // m/s
  double mean_step_length = 0;          // m, ground truth
  double pitch_min = 0, pitch_max = 0, roll_min = 0, roll_max = 0;  // rad, torso
  double yaw_min = 0, yaw_max = 0;  // rad, torso heading (unwrapped) relative to the first frame
  bool fell = false;
  double fell_at = -1;          // s
  Tip tipped = Tip::None;       // the first pass of kTipAngle in pitch or roll
  double tipped_at = -1;        // s
  double foot_slip = 0;         // m, summed horizontal displacement of each foot per stance
  double foot_slip_net_x = 0;   // m, signed forward part of it (negative: feet slid back)
  double foot_tilt_max = 0;     // rad, largest sole tilt from the vertical while loaded
  double foot_tilted_time = 0;  // s, time a loaded foot was tilted by more than kTiltedFoot
  double foot_spin = 0;         // rad, summed |net yaw turn| of each foot per stance (Sec. 4.4)
  double foot_spin_max = 0;     // rad, the largest turn of one foot in one stance

  // The list that names a run report's walk fields and a sweep's `walk.<field>` keys.
  static constexpr std::string_view kTypeName = "WalkMetricsResult";
  static constexpr auto fields() {
    using W = WalkMetricsResult;
    return std::make_tuple(
        field("steps", &W::steps), field("fk_distance", &W::fk_distance, "m"),
        field("true_distance", &W::true_distance, "m"),
        field("torso_distance", &W::torso_distance, "m"), field("duration", &W::duration, "s"),
        field("fk_speed", &W::fk_speed, "m/s"), field("true_speed", &W::true_speed, "m/s"),
        field("mean_step_length", &W::mean_step_length, "m"),
        field("pitch_min", &W::pitch_min, "rad"), field("pitch_max", &W::pitch_max, "rad"),
        field("roll_min", &W::roll_min, "rad"), field("roll_max", &W::roll_max, "rad"),
        field("yaw_min", &W::yaw_min, "rad"), field("yaw_max", &W::yaw_max, "rad"),
        field("fell", &W::fell), field("fell_at", &W::fell_at, "s"), field("tipped", &W::tipped),
        field("tipped_at", &W::tipped_at, "s"), field("foot_slip", &W::foot_slip, "m"),
        field("foot_slip_net_x", &W::foot_slip_net_x, "m"),
        field("foot_tilt_max", &W::foot_tilt_max, "rad"),
        field("foot_tilted_time", &W::foot_tilted_time, "s"),
        field("foot_spin", &W::foot_spin, "rad"), field("foot_spin_max", &W::foot_spin_max, "rad"));
  }
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
