#include "behaviours/push_recovery/push_recovery_walk.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "behaviours/balance/combined_strategy.hpp"
#include "behaviours/balance/modules/balance_representations.hpp"
#include "behaviours/balance/modules/hat_excursion.hpp"
#include "behaviours/posture/walking_joint_request.hpp"
#include "behaviours/walking/modules/pattern_walk.hpp"
#include "behaviours/walking/modules/walk_plan.hpp"
#include "behaviours/walking/pattern/adjusted_pattern.hpp"
#include "behaviours/walking/pattern/pattern_joints.hpp"
#include "robot/nao/nao_dimensions.hpp"
#include "robot/representations/frame_info.hpp"
#include "robot/representations/joint_sensor_data.hpp"

namespace stride::behaviours {

namespace {

using hal::index;
using hal::JointId;

// The stance sole's extent from its ankle along y (the left sole reaches further out, +y).
std::pair<double, double> sole_y_extent(bool left) {
  const double c = left ? nao::kSoleCentreYLeft : -nao::kSoleCentreYLeft;
  return {c - nao::kSoleWidth / 2, c + nao::kSoleWidth / 2};
}

class PushRecoveryWalk final : public Module {
 public:
  explicit PushRecoveryWalk(ModuleContext& c)
      : frame_(c.require<FrameInfo>()),
        joints_(c.require<JointSensorData>()),
        com_(c.require<ComState>()),
        model_(c.require<BalanceModel>()),
        params_(c.parameters<PushRecoveryWalkParameters>()),
        request_(c.provide<WalkingJointRequest>()),
        state_(c.provide<PushRecoveryState>()),
        plan_(c.provide<WalkPlan>()) {}

  void update() override {
    if (!pattern_ || !same_walk_parameters(params_.walk, built_from_)) {
      pattern_.emplace(walk_pattern_parameters(params_.walk));  // throws naming the parameter
      built_from_ = params_.walk;
    }
    if (!first_time_) {
      first_time_ = frame_.time;
      start_pose_ = joints_.position;
    }
    const double t = pattern_time(frame_.time, *first_time_, params_.walk.start_delay);
    const double tc = std::clamp(t, 0.0, pattern_->duration());
    const walking::PatternSample s = pattern_->sample(tc);
    const auto& p = pattern_->base().parameters();
    state_.gait_phase = std::fmod(tc, p.T_stride) / p.T_stride;
    if (t < 0) learn_com_offset(s);
    const bool walking = t >= 0 && t < pattern_->duration();
    if (params_.recovery.enabled && walking && com_.valid && model_.valid) respond(tc, s);
    request_ = walking_request(walking::leg_joints(s));
    plan_ = walking::walk_plan(s, *pattern_, tc);  // with the steps a response has moved
    if (request_.ik_beyond_limits != 0) ++beyond_limit_frames_;
    request_.ik_beyond_limit_frames = beyond_limit_frames_;
    apply_offsets(s.support);
    const double elapsed = frame_.time - *first_time_;
    if (t < 0 && elapsed < params_.walk.interpolation_time)
      blend_from_pose(request_.position, start_pose_, elapsed, params_.walk.interpolation_time);
  }

 private:
  // Standing before the walk: where the measured CoM lies from the planned waist, averaged.
  void learn_com_offset(const walking::PatternSample& s) {
    if (!com_.valid || com_.origin == GroundOrigin::between_feet) return;
    const Eigen::Vector2d plan = s.waist.head<2>() - stance_foot(s);
    const Eigen::Vector2d seen = com_.measured_com.head<2>() - plan;
    const double a = std::min(1.0, frame_.period / params_.recovery.com_offset_time);
    com_offset_ = com_offset_ ? (1 - a) * *com_offset_ + a * seen : seen;
  }

  Eigen::Vector2d stance_foot(const walking::PatternSample& s) const {
    return (com_.origin == GroundOrigin::right_sole ? s.right_foot : s.left_foot).head<2>();
  }

  void respond(double t, const walking::PatternSample& s) {
    const PushRecoveryParameters& r = params_.recovery;
    // The commanded waist (the plan as far as the changes have blended in), seen from the stance
    // sole the estimate uses: a step just decided moves the plan as fast as the robot can follow.
    const walking::PatternSample base = pattern_->base().sample(t);
    const Eigen::Vector2d foot = stance_foot(s);
    const Eigen::Vector2d plan_com =
        s.waist.head<2>() + com_offset_.value_or(Eigen::Vector2d::Zero()) - foot;
    const Eigen::Vector2d dev(com_.x - plan_com.x(), com_.y - plan_com.y());
    const Eigen::Vector2d rate(com_.xdot - base.waist_velocity.x(),
                               com_.ydot - base.waist_velocity.y());
    balance::BalanceParams robot = balance_params(model_, r.tau_forward, r.tau_backward);
    robot.z_cm = std::max(com_.com_height, 0.1);
    const Eigen::Vector2d xi = capture_deviation(dev, rate, robot.g, robot.z_cm);
    const Eigen::Vector2d zmp = s.zmp - foot;
    const bool left = com_.origin != GroundOrigin::right_sole;
    const auto [y_min, y_max] = sole_y_extent(left);
    const auto px = deviation_model(robot, model_.zmp_min, model_.zmp_max, zmp.x());
    const auto py = deviation_model(robot, y_min, y_max, zmp.y());
    state_.sagittal = classify_deviation(px, {dev.x(), rate.x()}, r.threshold, r.hip);
    state_.lateral = classify_deviation(py, {dev.y(), rate.y()}, r.lateral_threshold, false);
    state_.deviation = dev;
    state_.deviation_rate = rate;
    state_.capture_deviation = xi;
    state_.planned_zmp = zmp;
    const bool pushed =
        state_.sagittal != PushResponse::none || state_.lateral != PushResponse::none;
    if (pushed && state_.first_detection < 0) state_.first_detection = frame_.time;
    if (!pushed) step_armed_ = true;  // back within the walk's own deviation: the next push
    state_.ankle_offset = ankle_response(xi, {r.ankle_threshold, r.ankle_lateral_threshold},
                                         {r.ankle_pitch_gain, r.ankle_roll_gain}, r.max_ankle);
    start_hat_excursion(px, {dev.x(), rate.x()});
    if (state_.sagittal == PushResponse::step || state_.lateral == PushResponse::step)
      step(t, {state_.sagittal == PushResponse::step ? xi.x() : 0.0,
               state_.lateral == PushResponse::step ? xi.y() : 0.0});
  }

  // The hip's profile (Eq. 7.24, bounded by Eq. 7.30) or the combined one (Eq. 7.35, bounded
  // by Eq. 7.37; also behind a step) from the deviation.
  void start_hat_excursion(const balance::BalanceParams& p, const balance::ComState& dev) {
    const PushResponse x = state_.sagittal;
    if (excursion_ || !params_.recovery.hip) return;
    if (x == PushResponse::hip)
      excursion_ = HatExcursion{p, dev, balance::plan_hip(p, dev), frame_.time};
    else if (x == PushResponse::combined || x == PushResponse::step)
      excursion_ = HatExcursion{p, dev, balance::plan_combined(p, dev), frame_.time};
  }

  // The swing foot lands nearer the capture point; the rest of the walk moves with it.
  void step(double t, const Eigen::Vector2d& xi) {
    const PushRecoveryParameters& r = params_.recovery;
    const auto swing = pattern_->swing_to_adjust(t, r.min_swing_time);
    if (!swing) return;
    if (!step_armed_ && *swing != moved_swing_) return;  // one recovery step per push
    const bool left_swings = walking::Footsteps::swing_foot(*swing) == walking::Foot::kLeft;
    const Eigen::Vector2d want = capture_step(xi, r.step_gain, r.limits(), left_swings);
    // What this swing has already been moved counts against its limits.
    const Eigen::Vector2d done = moved_swing_ == *swing ? moved_ : Eigen::Vector2d::Zero();
    const Eigen::Vector2d total = capture_step(done + want, 1.0, r.limits(), left_swings);
    const Eigen::Vector2d more = total - done;
    if (more.norm() < r.step_tolerance) return;
    const auto a = pattern_->adjust_step(t, more, r.min_swing_time);
    if (!a) return;
    moved_swing_ = a->swing;
    step_armed_ = false;
    moved_ = total;
    ++state_.steps_moved;
    state_.walk_offset = a->total;
    if (r.lower > 0)
      pattern_->lower_waist(t, r.lower, std::max(a->landing - t, 0.02), r.lower_hold,
                            r.lower_return);
  }

  // The balance response's joint offsets on the pattern's targets.
  void apply_offsets(walking::SupportPhase support) {
    state_.hat_angle = 0;
    if (excursion_) {
      const auto theta = excursion_->theta(frame_.time, params_.recovery.hat_hold_time,
                                           params_.recovery.hat_return_time);
      if (theta) {
        state_.hat_angle = std::clamp(*theta, -params_.recovery.max_hat, params_.recovery.max_hat);
      } else {
        excursion_.reset();
      }
    }
    for (JointId j : {JointId::LHipPitch, JointId::RHipPitch})
      request_.position[index(j)] -= state_.hat_angle;  // trunk forward is hip flexion
    const bool left = support != walking::SupportPhase::kRight;
    const bool right = support != walking::SupportPhase::kLeft;
    if (left) {
      request_.position[index(JointId::LAnklePitch)] += state_.ankle_offset.x();
      request_.position[index(JointId::LAnkleRoll)] += state_.ankle_offset.y();
    }
    if (right) {
      request_.position[index(JointId::RAnklePitch)] += state_.ankle_offset.x();
      request_.position[index(JointId::RAnkleRoll)] += state_.ankle_offset.y();
    }
  }

  const FrameInfo& frame_;
  const JointSensorData& joints_;
  const ComState& com_;
  const BalanceModel& model_;
  const PushRecoveryWalkParameters& params_;
  WalkingJointRequest& request_;
  PushRecoveryState& state_;
  WalkPlan& plan_;
  std::optional<walking::AdjustedPattern> pattern_;
  WalkParameters built_from_;
  std::optional<double> first_time_;
  std::array<double, hal::kNumJoints> start_pose_{};
  std::optional<Eigen::Vector2d> com_offset_;
  std::optional<HatExcursion> excursion_;
  std::int64_t beyond_limit_frames_ = 0;
  int moved_swing_ = -1;
  bool step_armed_ = true;  // a push may move a landing (once, until the deviation settles)
  Eigen::Vector2d moved_ = Eigen::Vector2d::Zero();
};

}  // namespace

void register_push_recovery_modules(ModuleRegistry& registry) {
  registry.add<PushRecoveryWalk>("PushRecoveryWalk");
}

}  // namespace stride::behaviours
