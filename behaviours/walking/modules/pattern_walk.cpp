#include "behaviours/walking/modules/pattern_walk.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "behaviours/stand/stand.hpp"
#include "behaviours/walking/modules/request_walk.hpp"
#include "behaviours/walking/modules/walk_odometry.hpp"
#include "behaviours/walking/modules/walk_parameters.hpp"
#include "behaviours/walking/modules/walk_plan.hpp"
#include "behaviours/walking/steps/heading_hold.hpp"
#include "robot/representations/frame_info.hpp"
#include "robot/representations/fsr_sensor_data.hpp"
#include "robot/representations/joint_sensor_data.hpp"

namespace stride::behaviours {

WalkingJointRequest walking_request(const walking::LegJoints& legs) {
  const StandParameters stand;
  WalkingJointRequest r;
  r.position = stand_posture(stand);
  r.stiffness.fill(stand.stiffness);
  const auto left = model::chain_joints(model::NaoChain::LLeg);
  const auto right = model::chain_joints(model::NaoChain::RLeg);
  for (int i = 0; i < model::kLegJoints; ++i) {
    r.position[hal::index(left[i])] = legs.left[i];
    r.stiffness[hal::index(left[i])] = kWalkLegStiffness;
  }
  // The right chain starts with the shared LHipYawPitch, already set from the left leg.
  for (int i = 1; i < model::kLegJoints; ++i) {
    r.position[hal::index(right[i])] = legs.right[i];
    r.stiffness[hal::index(right[i])] = kWalkLegStiffness;
  }
  r.ik_beyond_limits = legs.beyond_limits;
  return r;
}

double pattern_time(double frame_time, double first_frame_time, double start_delay) {
  return frame_time - first_frame_time - start_delay;
}

void blend_from_pose(std::array<double, hal::kNumJoints>& request,
                     const std::array<double, hal::kNumJoints>& start_pose, double elapsed,
                     double interpolation_time) {
  const double blend = 0.5 - 0.5 * std::cos(std::numbers::pi * elapsed / interpolation_time);
  for (int i = 0; i < hal::kNumJoints; ++i)
    request[i] = start_pose[i] + blend * (request[i] - start_pose[i]);
}

namespace {

template <class Pattern>
class PatternPlayer final : public Module {
 public:
  explicit PatternPlayer(ModuleContext& c)
      : frame_(c.require<FrameInfo>()),
        joints_(c.require<JointSensorData>()),
        fsr_(c.require<FsrSensorData>()),
        odometry_(c.require<WalkOdometry>()),
        params_(c.parameters<WalkParameters>()),
        request_(c.provide<WalkingJointRequest>()),
        plan_(c.provide<WalkPlan>()),
        zmp_debug_(c.debug_request("walking:zmp")),
        refusal_(c.debug_request("walking:parameters")),
        name_(c.module_name()) {}

  void update() override {
    if (!first_time_) {
      first_time_ = frame_.time;
      start_pose_ = joints_.position;
    }
    if (!pattern_ || !same_walk_parameters(params_, built_from_))
      rebuild(pattern_time(frame_.time, *first_time_, built_from_.start_delay));
    const double t = pattern_time(frame_.time, *first_time_, built_from_.start_delay);
    const double t_clamped = std::clamp(t, 0.0, pattern_->duration());
    const walking::PatternSample sample = pattern_->sample(t_clamped);
    request_ = walking_request(legs(sample, t_clamped));
    plan_ = walking::walk_plan(sample, pattern_->footsteps(), t_clamped);
    if (request_.ik_beyond_limits != 0) ++beyond_limit_frames_;
    request_.ik_beyond_limit_frames = beyond_limit_frames_;
    show_zmp(sample);
    const double elapsed = frame_.time - *first_time_;
    if (t >= 0 || elapsed >= built_from_.interpolation_time) return;
    blend_from_pose(request_.position, start_pose_, elapsed, built_from_.interpolation_time);
  }

 private:
  // A new pattern before the walk starts; once it has started, the pattern is one whole walk
  // that cannot change on the way (the waist would jump): the change is refused, said once.
  void rebuild(double t) {
    if (!pattern_ || t < 0.0) {
      pattern_.emplace(walk_pattern_parameters(params_));  // throws naming the bad parameter
      built_from_ = params_;
      return;
    }
    if (refused_ && same_walk_parameters(params_, *refused_)) return;
    refused_ = params_;
    refusal_.say("refused: " + name_ +
                 " plays the walk it started with to its end; its parameters change before the "
                 "walk starts or after reset (RequestWalk changes speed while walking)");
  }

  // The pattern's legs, straight in the plan or turned back by the heading hold.
  walking::LegJoints legs(const walking::PatternSample& sample, double t) {
    if (!(built_from_.heading_gain > 0.0)) return walking::leg_joints(sample);
    const walking::HeadingHoldSettings settings{
        built_from_.heading_gain, built_from_.heading_per_step, 2.0 * pattern_->parameters().T_s()};
    return hold_.joints(sample, t, odometry_.yaw, settings).legs;
  }

  // The planned ZMP (Eq. 3.16) beside the measured CoP, both in the pattern's world frame; the
  // CoP is placed from the planned waist (an upright torso), so the gap also shows the lean.
  void show_zmp(const walking::PatternSample& s) const {
    if (!zmp_debug_.on() || !fsr_.cop_torso_valid) return;
    const Eigen::Vector2d cop = s.waist.head<2>() + fsr_.cop_torso.head<2>();
    zmp_debug_.show({{"zmp_x", s.zmp.x()},
                     {"zmp_y", s.zmp.y()},
                     {"cop_x", cop.x()},
                     {"cop_y", cop.y()},
                     {"error", (cop - s.zmp).norm()}});
  }

  const FrameInfo& frame_;
  const JointSensorData& joints_;
  const FsrSensorData& fsr_;
  const WalkOdometry& odometry_;
  const WalkParameters& params_;
  WalkingJointRequest& request_;
  WalkPlan& plan_;
  DebugRequest zmp_debug_;
  DebugRequest refusal_;
  std::string name_;
  std::optional<Pattern> pattern_;
  walking::HeadingHold hold_;
  WalkParameters built_from_;
  std::optional<WalkParameters> refused_;
  std::optional<double> first_time_;
  std::array<double, hal::kNumJoints> start_pose_{};
  std::int64_t beyond_limit_frames_ = 0;
};

}  // namespace

void register_walking_modules(ModuleRegistry& registry) {
  registry.add<PatternPlayer<walking::StretchedKneePattern>>("PatternWalk");
  registry.add<PatternPlayer<walking::ConventionalPattern>>("ConventionalWalk");
  register_request_walk_modules(registry);
  register_walk_odometry_modules(registry);
}

}  // namespace stride::behaviours
