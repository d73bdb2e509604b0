// The Excitation module: holds the measured pose, moves to the base posture over start_delay,
// plays the motion, then holds the base posture until stopped. Every frame's targets go through
// the speed bound, so no joint is ever commanded faster than max_speed.
#include "behaviours/identify/excitation_module.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "behaviours/identify/excitation.hpp"
#include "robot/representations/frame_info.hpp"
#include "robot/representations/joint_request.hpp"
#include "robot/representations/joint_sensor_data.hpp"

namespace stride::behaviours {
namespace {

class Excitation final : public Module {
 public:
  explicit Excitation(ModuleContext& c)
      : frame_(c.require<FrameInfo>()),
        joints_(c.require<JointSensorData>()),
        params_(c.parameters<ExcitationParameters>()),
        request_(c.provide<JointRequest>()) {}

  void update() override {
    if (!started_) {
      start_ = joints_.position;
      commanded_ = start_;
      started_ = true;
    }
    elapsed_ += frame_.period;
    JointTargets target;
    if (elapsed_ < params_.start_delay) {
      const double s = elapsed_ / params_.start_delay;
      const double blend = 0.5 - 0.5 * std::cos(std::numbers::pi * s);
      const JointTargets base = excitation_base();
      for (int i = 0; i < hal::kNumJoints; ++i)
        target[i] = start_[i] + blend * (base[i] - start_[i]);
    } else {
      target = excitation_targets(params_, elapsed_ - params_.start_delay);
    }
    limit_rate(commanded_, target, params_.max_speed, frame_.period);
    for (int i = 0; i < hal::kNumJoints; ++i) {
      request_.mode[i] = hal::ServoMode::Position;
      request_.position[i] = commanded_[i];
      request_.stiffness[i] = params_.stiffness;
      request_.torque[i] = 0;
    }
  }

 private:
  const FrameInfo& frame_;
  const JointSensorData& joints_;
  const ExcitationParameters& params_;
  JointRequest& request_;
  bool started_ = false;
  double elapsed_ = 0;
  JointTargets start_{}, commanded_{};
};

}  // namespace

void register_excitation(ModuleRegistry& registry) {
  registry.add<Excitation>("Excitation");
}

}  // namespace stride::behaviours
