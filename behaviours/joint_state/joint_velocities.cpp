#include "behaviours/joint_state/joint_velocities.hpp"

#include "robot/representations/frame_info.hpp"
#include "robot/representations/joint_sensor_data.hpp"

namespace stride::behaviours {

std::array<double, hal::kNumJoints> backward_difference(
    const std::array<double, hal::kNumJoints>& before,
    const std::array<double, hal::kNumJoints>& now, double period) {
  std::array<double, hal::kNumJoints> v{};
  for (int i = 0; i < hal::kNumJoints; ++i) v[i] = (now[i] - before[i]) / period;
  return v;
}

namespace {

class JointVelocityEstimator final : public Module {
 public:
  explicit JointVelocityEstimator(ModuleContext& c)
      : frame_(c.require<FrameInfo>()),
        joints_(c.require<JointSensorData>()),
        out_(c.provide<JointVelocities>()) {}

  void update() override {
    if (started_ && frame_.period > 0)
      out_.velocity = backward_difference(before_, joints_.position, frame_.period);
    else
      out_.velocity.fill(0);
    before_ = joints_.position;
    started_ = true;
  }

 private:
  const FrameInfo& frame_;
  const JointSensorData& joints_;
  JointVelocities& out_;
  std::array<double, hal::kNumJoints> before_{};
  bool started_ = false;
};

}  // namespace

void register_joint_state_modules(ModuleRegistry& registry) {
  registry.add<JointVelocityEstimator>("JointVelocityEstimator");
}

}  // namespace stride::behaviours
