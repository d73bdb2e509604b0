#include "behaviours/walking/modules/request_walk.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "behaviours/walking/modules/pattern_walk.hpp"
#include "behaviours/walking/modules/walk_odometry.hpp"
#include "behaviours/walking/modules/walk_plan.hpp"
#include "behaviours/walking/modules/walk_request.hpp"
#include "behaviours/walking/steps/pose_target.hpp"
#include "behaviours/walking/steps/walk_joints.hpp"
#include "robot/core/error.hpp"
#include "robot/representations/frame_info.hpp"
#include "robot/representations/joint_sensor_data.hpp"

namespace stride::behaviours {

namespace {
// The pattern's fields as PatternWalk's parameters hold them (the rest stay the preset's).
WalkParameters pattern_fields(const RequestWalkParameters& r) {
  WalkParameters w;
  w.preset = r.preset;
  w.T_stride = r.T_stride;
  w.tau_dsp = r.tau_dsp;
  w.A_l = r.A_l;
  w.z_min = r.z_min;
  w.z_max = r.z_max;
  w.d_0 = r.d_0;
  w.H_foot = r.H_foot;
  return w;
}
}  // namespace

walking::PatternParameters request_walk_pattern(const RequestWalkParameters& r) {
  return walk_pattern_parameters(pattern_fields(r));  // throws naming the parameter
}

walking::StepLimits request_walk_limits(const RequestWalkParameters& r) {
  return {r.max_forward,      r.max_backward,      r.max_sideways, r.max_turn,
          r.forward_per_step, r.sideways_per_step, r.turn_per_step};
}

namespace {

bool same_pattern_fields(const RequestWalkParameters& a, const RequestWalkParameters& b) {
  return a.early_share == b.early_share &&
         same_walk_parameters(pattern_fields(a), pattern_fields(b));
}

WalkPlan plan_of(const walking::WalkSample& s, const walking::OnlineWalk& walk) {
  WalkPlan p;
  p.t = s.t;
  p.zmp = {s.zmp.x(), s.zmp.y()};
  p.support = static_cast<std::int64_t>(s.support);  // kDouble 0, kLeft 1, kRight 2
  p.left_foot = {s.left.position.x(), s.left.position.y(), s.left.yaw};
  p.right_foot = {s.right.position.x(), s.right.position.y(), s.right.yaw};
  std::array<walking::Landing, kWalkPlanSteps> next;
  p.steps = walk.landings_after(s.t, next);
  for (int i = 0; i < p.steps; ++i) {
    p.step_x[i] = next[i].pose.position.x();
    p.step_y[i] = next[i].pose.position.y();
    p.step_yaw[i] = next[i].pose.yaw;
    p.step_foot[i] = next[i].foot == walking::Foot::kLeft ? 1 : 2;
  }
  return p;
}

class RequestWalk final : public Module {
 public:
  explicit RequestWalk(ModuleContext& c)
      : frame_(c.require<FrameInfo>()),
        joints_(c.require<JointSensorData>()),
        odometry_(c.require<WalkOdometry>()),
        wanted_(c.require<WalkRequest>()),
        params_(c.parameters<RequestWalkParameters>()),
        request_(c.provide<WalkingJointRequest>()),
        plan_(c.provide<WalkPlan>()),
        status_(c.provide<WalkStatus>()),
        say_(c.debug_request("walking:request")) {}

  void update() override {
    if (!first_time_) {
      first_time_ = frame_.time;
      start_pose_ = joints_.position;
    }
    const double elapsed = frame_.time - *first_time_;
    adopt_limits();
    double t = frame_.time - walk_start_;
    if (!walk_ || walk_->planned_steps() == 0 || walk_->ended(t)) {
      stand_ready(t);  // standing: the pattern parameters may change here
      walk_start_ = frame_.time;
      t = 0.0;
    }
    const bool walk = asked(t) && elapsed >= params_.start_delay;
    walk_->advance(t, walk, asked_, correction(t));
    const walking::WalkSample s = walk_->sample(t);
    const walking::LegJoints legs = walking::leg_joints(s).legs;
    request_ = walking_request(legs);
    if (legs.beyond_limits != 0) ++beyond_limit_frames_;
    request_.ik_beyond_limit_frames = beyond_limit_frames_;
    plan_ = plan_of(s, *walk_);
    write_status(s, t);
    if (elapsed < params_.interpolation_time)
      blend_from_pose(request_.position, start_pose_, elapsed, params_.interpolation_time);
  }

 private:
  // Whether the request asks to walk, and at which velocity (asked_): its own, or toward its
  // target from where the granted requests have put the walk frame.
  bool asked(double t) {
    if (wanted_.mode == WalkMode::target) {
      const auto& g = wanted_.target;
      const walking::TargetVelocity v =
          walking::velocity_toward(walk_->sample(t).reference, {g[0], g[1], g[2]}, limits_);
      asked_ = v.velocity;
      return !v.arrived;
    }
    asked_ = {wanted_.forward, wanted_.sideways, wanted_.turn};
    return wanted_.mode == WalkMode::walk;
  }

  // The heading and place loops: the reference path's yaw against the measured one, and the
  // torso's place on it (the plan's sway carried over) against the measured, in its axes.
  walking::StepVelocity correction(double t) const {
    const walking::WalkSample s = walk_->sample(t);
    const walking::Pose2& r = s.reference;
    const double turn = params_.heading_gain * walking::wrap_angle(r.yaw - odometry_.yaw);
    const Eigen::Vector2d sway =
        walking::rotated(r.yaw - s.frame.yaw, s.waist.x() - s.frame.x, s.waist.y() - s.frame.y);
    const Eigen::Vector2d behind =
        walking::rotated(-r.yaw, r.x + sway.x() - odometry_.x, r.y + sway.y() - odometry_.y);
    return {params_.place_gain * behind.x(), params_.place_gain * behind.y(),
            std::clamp(turn, -params_.max_turn, params_.max_turn)};
  }

  // A fresh walk standing where the last one ended, with the parameters as they are now.
  void stand_ready(double t) {
    const bool changed = !walk_ || !same_pattern_fields(params_, built_from_);
    if (walk_ && walk_->planned_steps() == 0 && !changed) return;
    const walking::WalkSample here = walk_ ? walk_->sample(t) : walking::WalkSample{};
    walking::PatternParameters p = walk_ ? walk_->parameters() : walking::PatternParameters{};
    try {
      p = request_walk_pattern(params_);
    } catch (const Error& e) {
      if (!walk_) throw;  // nothing to walk with yet: the module fails naming the parameter
      say_once(std::string("RequestWalk keeps its pattern: ") + e.what());
    }
    built_from_ = params_;
    if (walk_) shortened_before_ += walk_->shortened();
    walk_.emplace(p, limits_, here.frame, here.reference, params_.early_share);
    steps_before_ += planned_;
    planned_ = 0;
  }

  void adopt_limits() {
    const walking::StepLimits l = request_walk_limits(params_);
    const std::string e = walking::limits_error(l);
    if (e.empty()) {
      limits_ = l;
      if (walk_) walk_->set_limits(l);
    } else {
      say_once("RequestWalk keeps its limits: " + e);
    }
  }

  void write_status(const walking::WalkSample& s, double t) {
    planned_ = walk_->planned_steps();
    WalkStatus& w = status_;
    w.state = planned_ == 0 || walk_->ended(t) ? WalkState::standing
              : walk_->stopping()              ? WalkState::stopping
                                               : WalkState::walking;
    const walking::StepVelocity& g = walk_->granted();
    w.granted_forward = g.forward;
    w.granted_sideways = g.sideways;
    w.granted_turn = g.turn;
    const bool walking_asked = wanted_.mode != WalkMode::stand;
    w.limited = walking_asked && !(walking::within_range(asked_, limits_) == asked_);
    w.ramping = walking_asked && !(g == walking::within_range(asked_, limits_));
    w.step = s.step;
    w.steps = steps_before_ + planned_;
    w.odometry = {s.reference.x, s.reference.y, s.reference.yaw};
    w.plan = {s.frame.x, s.frame.y, s.frame.yaw};
    w.measured_yaw = odometry_.yaw;
    w.ik_beyond_limit_frames = beyond_limit_frames_;
    w.shortened_steps = shortened_before_ + walk_->shortened();
    w.parameters_pending = !same_pattern_fields(params_, built_from_);
  }

  void say_once(const std::string& line) {
    if (line == last_said_) return;
    say_.say(line);
    last_said_ = line;
  }

  const FrameInfo& frame_;
  const JointSensorData& joints_;
  const WalkOdometry& odometry_;
  const WalkRequest& wanted_;
  const RequestWalkParameters& params_;
  WalkingJointRequest& request_;
  WalkPlan& plan_;
  WalkStatus& status_;
  DebugRequest say_;
  std::optional<walking::OnlineWalk> walk_;
  RequestWalkParameters built_from_;
  walking::StepLimits limits_;
  walking::StepVelocity asked_;
  std::optional<double> first_time_;
  double walk_start_ = 0.0;
  std::array<double, hal::kNumJoints> start_pose_{};
  std::int64_t beyond_limit_frames_ = 0, steps_before_ = 0, planned_ = 0, shortened_before_ = 0;
  std::string last_said_;
};

// The WalkRequest from this module's parameters, field by field.
class ScriptedWalkRequest final : public Module {
 public:
  explicit ScriptedWalkRequest(ModuleContext& c)
      : params_(c.parameters<ScriptedWalkRequestParameters>()), out_(c.provide<WalkRequest>()) {}
  void update() override {
    out_ = {params_.mode, params_.forward, params_.sideways, params_.turn, params_.target};
  }

 private:
  const ScriptedWalkRequestParameters& params_;
  WalkRequest& out_;
};

}  // namespace

void register_request_walk_modules(ModuleRegistry& registry) {
  registry.add<RequestWalk>("RequestWalk");
  registry.add<ScriptedWalkRequest>("ScriptedWalkRequest");
}

}  // namespace stride::behaviours
