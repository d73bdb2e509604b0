#pragma once
// An ensemble of perturbed starts of one scene: member k runs with its own seed (sensor noise,
// the solver's row order, seeded floors) and every robot placed a little off, turned by a small
// heading and shifted on the floor, so a walk figure comes with the spread of nearby starts.
#include <cstdint>

#include <Eigen/Core>

#include "simulator/scene/scene_description.hpp"

namespace stride::sim {

struct EnsembleSpec {
  int members = 1;
  std::uint64_t first_seed = 1;    // member k runs with seed first_seed + k
  double heading_spread = 0.003;   // rad: heading offsets uniform in [-spread, spread]
  double position_spread = 0.002;  // m: x and y offsets uniform in [-spread, spread]
};

struct StartPerturbation {
  std::uint64_t seed = 1;
  double heading = 0;                                // rad, added to every robot's yaw
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();  // m, added to every robot's x, y
};

// Member k (0-based) of `spec`: drawn from the member's seed alone, so a member is the same
// whatever the ensemble's size.
StartPerturbation ensemble_member(const EnsembleSpec& spec, int k);

// The scene with `p` applied: its seed, every robot's heading and position.
void apply_start(SceneDescription& scene, const StartPerturbation& p);

}  // namespace stride::sim
