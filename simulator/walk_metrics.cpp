#include "simulator/walk_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "robot/framework/enum_names.hpp"
#include "robot/model/kinematics/nao_fk.hpp"

namespace stride::sim {
namespace {

double heading(const Eigen::Matrix3d& r) {
  return std::atan2(r(1, 0), r(0, 0));
}

double wrapped(double a) {  // to (-pi, pi]
  return std::remainder(a, 2 * M_PI);
}

double sole_x_from_fk(const hal::SensorFrame& s, model::Side side) {
  model::LegAngles q{};
  model::gather_chain(model::leg_chain(side), s.position, q);
  return model::leg_fk(side, q).translation().x();
}

Tip tip_of(double pitch, double roll) {
  if (std::max(std::abs(pitch), std::abs(roll)) <= kTipAngle) return Tip::None;
  if (std::abs(pitch) >= std::abs(roll)) return pitch > 0 ? Tip::Forward : Tip::Backward;
  return roll > 0 ? Tip::Right : Tip::Left;
}

}  // namespace

const char* tip_name(Tip t) {
  return enum_name(t).data();  // the names are literals: NUL-terminated
}

void WalkMetrics::observe(const SimulatedRobot& robot) {
  const hal::SensorFrame& s = robot.latest_sensors();
  const TorsoPose torso = robot.torso_pose();
  if (lfoot_ == -2) {
    lfoot_ = robot.model().link_index("LFoot");
    rfoot_ = robot.model().link_index("RFoot");
  }
  if (lfoot_ < 0 || rfoot_ < 0) return;  // walking figures only for robots with NAO feet
  const double xl = robot.body().link_pose(lfoot_).translation().x();
  const double xr = robot.body().link_pose(rfoot_).translation().x();
  const double frame = started_ ? s.time - t_ : 0.0;
  t_ = s.time;
  x_mid_ = 0.5 * (xl + xr);
  x_torso_ = torso.x;
  if (!started_) {
    started_ = true;
    t0_ = s.time;
    x0_mid_ = x_mid_;
    x0_torso_ = torso.x;
    r_.pitch_min = r_.pitch_max = torso.pitch;
    r_.roll_min = r_.roll_max = torso.roll;
    torso_yaw_ = torso.yaw;
  }
  torso_turned_ += wrapped(torso.yaw - torso_yaw_);
  torso_yaw_ = torso.yaw;
  r_.yaw_min = std::min(r_.yaw_min, torso_turned_);
  r_.yaw_max = std::max(r_.yaw_max, torso_turned_);
  r_.pitch_min = std::min(r_.pitch_min, torso.pitch);
  r_.pitch_max = std::max(r_.pitch_max, torso.pitch);
  r_.roll_min = std::min(r_.roll_min, torso.roll);
  r_.roll_max = std::max(r_.roll_max, torso.roll);
  if (r_.tipped == Tip::None) {
    r_.tipped = tip_of(torso.pitch, torso.roll);
    if (r_.tipped != Tip::None) r_.tipped_at = s.time;
  }
  if (!r_.fell && robot.fallen()) {
    r_.fell = true;
    r_.fell_at = s.time;
  }
  const double left = s.fsr[0] + s.fsr[1] + s.fsr[2] + s.fsr[3];
  const double right = s.fsr[4] + s.fsr[5] + s.fsr[6] + s.fsr[7];
  observe_feet(robot, left, right, frame);
  const bool both = left > threshold_ && right > threshold_;
  const bool one = (left > threshold_) != (right > threshold_);
  if (one) in_single_support_ = true;
  // A new double support: one step completed (a robot on the floor makes no more steps).
  if (both && in_single_support_ && !r_.fell) {
    in_single_support_ = false;
    ++r_.steps;
    r_.fk_distance +=
        std::abs(sole_x_from_fk(s, model::Side::Left) - sole_x_from_fk(s, model::Side::Right));
  }
}

void WalkMetrics::observe_feet(const SimulatedRobot& robot, double left_load, double right_load,
                               double frame) {
  const int links[2] = {lfoot_, rfoot_};
  const double loads[2] = {left_load, right_load};
  for (int f = 0; f < 2; ++f) {
    const Eigen::Isometry3d sole = robot.body().link_pose(links[f]);
    const Eigen::Vector2d xy = sole.translation().head<2>();
    const bool loaded = loads[f] > threshold_;
    const double yaw = heading(sole.linear());
    // Per stance, from loading to unloading: net displacement and turn, so that contact jitter of
    // a few micrometres per frame does not add up.
    Stance& st = stance_[f];
    if (loaded && !st.active) st = {true, xy, xy, yaw, 0.0};
    if (loaded) {
      st.last = xy;
      st.turned += wrapped(yaw - st.yaw);
      st.yaw = yaw;
      const double tilt = std::acos(std::clamp(sole.linear()(2, 2), -1.0, 1.0));
      r_.foot_tilt_max = std::max(r_.foot_tilt_max, tilt);
      if (tilt > kTiltedFoot) r_.foot_tilted_time += frame;
    } else if (st.active) {
      close_stance(st, r_);
      st.active = false;
    }
  }
}

void WalkMetrics::close_stance(const Stance& s, WalkMetricsResult& r) {
  r.foot_slip += (s.last - s.start).norm();
  r.foot_slip_net_x += s.last.x() - s.start.x();
  r.foot_spin += std::abs(s.turned);
  r.foot_spin_max = std::max(r.foot_spin_max, std::abs(s.turned));
}

WalkMetricsResult WalkMetrics::result() const {
  WalkMetricsResult r = r_;
  for (const Stance& s : stance_)
    if (s.active) close_stance(s, r);  // a stance still going on counts up to now
  r.duration = t_ - t0_;
  r.true_distance = x_mid_ - x0_mid_;
  r.torso_distance = x_torso_ - x0_torso_;
  if (r.duration > 0) {
    r.fk_speed = r.fk_distance / r.duration;
    r.true_speed = r.true_distance / r.duration;
  }
  r.mean_step_length = r.steps > 0 ? r.true_distance / r.steps : 0;
  return r;
}

std::string walk_metrics_text(const WalkMetricsResult& r) {
  std::ostringstream o;
  o.setf(std::ios::fixed);
  o.precision(4);
  o << "steps " << r.steps << "  distance fk " << r.fk_distance << " m, true " << r.true_distance
    << " m (torso " << r.torso_distance << " m) in " << r.duration << " s  speed fk " << r.fk_speed
    << " m/s, true " << r.true_speed << " m/s  step " << r.mean_step_length << " m  pitch ["
    << r.pitch_min << ", " << r.pitch_max << "] roll [" << r.roll_min << ", " << r.roll_max
    << "] yaw [" << r.yaw_min << ", " << r.yaw_max << "] rad  feet: slip " << r.foot_slip
    << " m (net x " << r.foot_slip_net_x << " m), tilt max " << r.foot_tilt_max << " rad, tilted "
    << r.foot_tilted_time << " s, spin " << r.foot_spin << " rad (max " << r.foot_spin_max << ")  "
    << (r.fell ? "FELL" : "did not fall");
  if (r.fell) o << " at " << r.fell_at << " s";
  if (r.tipped != Tip::None)
    o << ", tipped " << tip_name(r.tipped) << " past " << kTipAngle << " rad at " << r.tipped_at
      << " s";
  return o.str();
}

}  // namespace stride::sim
