#pragma once
// The 25 NAO joints in LoLA order (nao-facts.md): the index space of every hardware link.
#include <array>
#include <optional>
#include <string_view>

namespace stride::hal {

enum class JointId : int {
  HeadYaw,
  HeadPitch,
  LShoulderPitch,
  LShoulderRoll,
  LElbowYaw,
  LElbowRoll,
  LWristYaw,
  LHipYawPitch,
  LHipRoll,
  LHipPitch,
  LKneePitch,
  LAnklePitch,
  LAnkleRoll,
  RHipRoll,
  RHipPitch,
  RKneePitch,
  RAnklePitch,
  RAnkleRoll,
  RShoulderPitch,
  RShoulderRoll,
  RElbowYaw,
  RElbowRoll,
  RWristYaw,
  LHand,
  RHand
};

inline constexpr int kNumJoints = 25;

inline constexpr std::array<std::string_view, kNumJoints> kJointNames = {
    "HeadYaw",    "HeadPitch",   "LShoulderPitch", "LShoulderRoll",  "LElbowYaw",
    "LElbowRoll", "LWristYaw",   "LHipYawPitch",   "LHipRoll",       "LHipPitch",
    "LKneePitch", "LAnklePitch", "LAnkleRoll",     "RHipRoll",       "RHipPitch",
    "RKneePitch", "RAnklePitch", "RAnkleRoll",     "RShoulderPitch", "RShoulderRoll",
    "RElbowYaw",  "RElbowRoll",  "RWristYaw",      "LHand",          "RHand"};

constexpr int index(JointId j) {
  return static_cast<int>(j);
}
constexpr std::string_view name(JointId j) {
  return kJointNames[index(j)];
}

inline std::optional<JointId> joint_from_name(std::string_view n) {
  for (int i = 0; i < kNumJoints; ++i)
    if (kJointNames[i] == n) return static_cast<JointId>(i);
  return std::nullopt;
}

// FSR order of LoLA: left FL, FR, RL, RR, then right FL, FR, RL, RR.
inline constexpr int kNumFsr = 8;
inline constexpr std::array<std::string_view, kNumFsr> kFsrNames = {
    "LFsrFL", "LFsrFR", "LFsrRL", "LFsrRR", "RFsrFL", "RFsrFR", "RFsrRL", "RFsrRR"};

// Touch sensors in LoLA's order.
inline constexpr int kNumTouch = 14;
inline constexpr std::array<std::string_view, kNumTouch> kTouchNames = {
    "ChestButton",    "HeadFront",      "HeadMiddle",   "HeadRear",      "LFootBumperLeft",
    "LFootBumperRight", "LHandBack",    "LHandLeft",    "LHandRight",    "RFootBumperLeft",
    "RFootBumperRight", "RHandBack",    "RHandLeft",    "RHandRight"};

}  // namespace stride::hal
