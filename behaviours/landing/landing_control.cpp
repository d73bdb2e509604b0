#include "behaviours/landing/landing_control.hpp"

#include <algorithm>

#include "behaviours/posture/posture_modules.hpp"
#include "behaviours/posture/posture_representations.hpp"
#include "behaviours/posture/walking_joint_request.hpp"
#include "robot/model/kinematics/nao_fk.hpp"
#include "robot/model/kinematics/nao_leg_ik.hpp"
#include "robot/representations/frame_info.hpp"
#include "robot/representations/fsr_sensor_data.hpp"
#include "robot/representations/joint_request.hpp"

namespace stride::behaviours {

model::LegAngles offset_sole(model::Side side, const model::LegAngles& q, double lift, double pitch,
                             double roll) {
  model::LegAngles out = q;
  if (lift != 0) {
    Eigen::Isometry3d sole = model::leg_fk(side, q);
    sole.translation().z() += lift;
    out = model::leg_ik_with_hip_yaw_pitch(side, sole, q[0]).q;
  }
  out[4] += pitch;
  out[5] += roll;
  return out;
}

Eigen::Vector2d sole_moments(double load, const Eigen::Vector2d& cop,
                             const Eigen::Vector2d& reference) {
  const Eigen::Vector2d r = cop - reference;
  return {-load * r.x(), load * r.y()};  // (r x F) about y and about x, F = (0, 0, load)
}

namespace {

constexpr model::Side kSides[2] = {model::Side::Left, model::Side::Right};

class LandingControl final : public Module {
 public:
  explicit LandingControl(ModuleContext& c)
      : frame_(c.require<FrameInfo>()),
        posture_(c.require<PostureCorrectedRequest>()),
        arms_(c.require<ArmSwingRequest>()),
        plan_(c.require<WalkingJointRequest>()),
        fsr_(c.require<FsrSensorData>()),
        params_(c.parameters<LandingControlParameters>()),
        out_(c.provide<JointRequest>()),
        state_(c.provide<LandingControlState>()) {}

  void update() override {
    position_ = posture_.position;
    stiffness_ = posture_.stiffness;
    if (frame_.period > 0) correct_landings();
    assemble_walking_request(position_, stiffness_, arms_, out_);
  }

 private:
  void correct_landings() {
    refresh_filters();
    const Eigen::Vector2d z = planned_sole_heights();
    const double height[2] = {z[0] - z[1], z[1] - z[0]};
    const double load[2] = {fsr_.total_left, fsr_.total_right};
    const Eigen::Vector2d cop[2] = {fsr_.cop_left, fsr_.cop_right};
    state_.excess_force = load[0] + load[1] - params_.weight;
    for (int f = 0; f < 2; ++f) {
      feet_[f] = advance_landing(feet_[f], params_.window(), frame_.time, height[f], load[f]);
      if (feet_[f].stage == LandingStage::landing) {
        sole_[f] = sole_filter_.step(sole_[f], state_.excess_force);
        const Eigen::Vector2d m = sole_moments(load[f], cop[f], params_.cop_reference);
        pitch_[f] = ankle_filter_.step(pitch_[f], m.x());
        roll_[f] = ankle_filter_.step(roll_[f], m.y());
      } else if (feet_[f].weight == 0) {
        sole_[f] = pitch_[f] = roll_[f] = {};
      }
      state_.stage[f] = feet_[f].stage;
      const double w = feet_[f].weight;
      state_.lift[f] = w * std::clamp(sole_[f].offset, -params_.max_drop, params_.max_lift);
      state_.pitch[f] = w * std::clamp(pitch_[f].offset, -params_.max_tilt, params_.max_tilt);
      state_.roll[f] = w * std::clamp(roll_[f].offset, -params_.max_tilt, params_.max_tilt);
      if (w > 0) apply(f);
    }
  }

  // Both soles' planned heights in the torso frame, from the pattern's leg targets.
  Eigen::Vector2d planned_sole_heights() const {
    Eigen::Vector2d z;
    for (int k = 0; k < 2; ++k) {
      model::LegAngles q{};
      model::gather_chain(model::leg_chain(kSides[k]), plan_.position, std::span<double>(q));
      z[k] = model::leg_fk(kSides[k], q).translation().z();
    }
    return z;
  }

  void apply(int f) {
    const auto chain = model::leg_chain(kSides[f]);
    model::LegAngles q{};
    model::gather_chain(chain, position_, std::span<double>(q));
    q = offset_sole(kSides[f], q, state_.lift[f], state_.pitch[f], state_.roll[f]);
    const auto ids = model::chain_joints(chain);
    for (std::size_t i = 1; i < ids.size(); ++i) {  // HipYawPitch stays the pattern's
      position_[hal::index(ids[i])] = q[i];
      stiffness_[hal::index(ids[i])] = params_.landing_stiffness;
    }
  }

  void refresh_filters() {
    const Admittance s = params_.sole(), a = params_.ankle();
    const auto same = [](const Admittance& x, const Admittance& y) {
      return x.mass == y.mass && x.damping == y.damping && x.stiffness == y.stiffness;
    };
    if (!same(sole_filter_.model(), s) || sole_filter_.period() != frame_.period)
      sole_filter_ = AdmittanceFilter(s, frame_.period);
    if (!same(ankle_filter_.model(), a) || ankle_filter_.period() != frame_.period)
      ankle_filter_ = AdmittanceFilter(a, frame_.period);
  }

  const FrameInfo& frame_;
  const PostureCorrectedRequest& posture_;
  const ArmSwingRequest& arms_;
  const WalkingJointRequest& plan_;
  const FsrSensorData& fsr_;
  const LandingControlParameters& params_;
  JointRequest& out_;
  LandingControlState& state_;
  std::array<double, hal::kNumJoints> position_{}, stiffness_{};
  AdmittanceFilter sole_filter_, ankle_filter_;
  FootLanding feet_[2];
  AdmittanceState sole_[2], pitch_[2], roll_[2];
};

}  // namespace

void register_landing_control(ModuleRegistry& registry) {
  registry.add<LandingControl>("LandingControl");
}

}  // namespace stride::behaviours
