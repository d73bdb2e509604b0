#include "robot/model/kinematics/nao_chains.hpp"

namespace stride::model {

using hal::JointId;

namespace {
constexpr std::array kHead = {JointId::HeadYaw, JointId::HeadPitch};
constexpr std::array kLArm = {JointId::LShoulderPitch, JointId::LShoulderRoll, JointId::LElbowYaw,
                              JointId::LElbowRoll, JointId::LWristYaw};
constexpr std::array kRArm = {JointId::RShoulderPitch, JointId::RShoulderRoll, JointId::RElbowYaw,
                              JointId::RElbowRoll, JointId::RWristYaw};
constexpr std::array kLLeg = {JointId::LHipYawPitch, JointId::LHipRoll,    JointId::LHipPitch,
                              JointId::LKneePitch,   JointId::LAnklePitch, JointId::LAnkleRoll};
constexpr std::array kRLeg = {JointId::LHipYawPitch, JointId::RHipRoll,    JointId::RHipPitch,
                              JointId::RKneePitch,   JointId::RAnklePitch, JointId::RAnkleRoll};
constexpr std::array<std::string_view, 5> kNames = {"head", "larm", "rarm", "lleg", "rleg"};
}  // namespace

std::span<const JointId> chain_joints(NaoChain chain) {
  switch (chain) {
    case NaoChain::Head:
      return kHead;
    case NaoChain::LArm:
      return kLArm;
    case NaoChain::RArm:
      return kRArm;
    case NaoChain::LLeg:
      return kLLeg;
    case NaoChain::RLeg:
      return kRLeg;
  }
  return {};
}

std::string_view chain_name(NaoChain chain) {
  return kNames[static_cast<size_t>(chain)];
}

std::optional<NaoChain> chain_from_name(std::string_view name) {
  for (size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == name) return static_cast<NaoChain>(i);
  return std::nullopt;
}

}  // namespace stride::model
