#pragma once
// The five NAO kinematic chains (thesis App. B): joint lists in LoLA ids and chain-order angles.
#include <array>
#include <optional>
#include <span>
#include <string_view>

#include "robot/hal/joint_id.hpp"

namespace stride::model {

enum class NaoChain { Head, LArm, RArm, LLeg, RLeg };
enum class Side { Left, Right };

inline constexpr int kLegJoints = 6;
using LegAngles =
    std::array<double, kLegJoints>;  // HipYawPitch, HipRoll, HipPitch, Knee, AnklePitch, AnkleRoll

// The chain's joints from the torso outwards. The right leg starts with LHipYawPitch: one motor
// drives both hip yaw-pitch joints and LoLA only knows the left one.
std::span<const hal::JointId> chain_joints(NaoChain chain);
std::string_view chain_name(NaoChain chain);  // "head", "larm", ...
std::optional<NaoChain> chain_from_name(std::string_view name);
inline NaoChain leg_chain(Side side) {
  return side == Side::Left ? NaoChain::LLeg : NaoChain::RLeg;
}

// Gathers the chain's angles (chain order) from a LoLA-ordered joint array.
template <typename Array>
void gather_chain(NaoChain chain, const Array& all, std::span<double> out) {
  const auto ids = chain_joints(chain);
  for (size_t i = 0; i < ids.size(); ++i) out[i] = all[hal::index(ids[i])];
}

}  // namespace stride::model
