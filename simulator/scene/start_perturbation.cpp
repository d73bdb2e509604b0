#include "simulator/scene/start_perturbation.hpp"

#include "simulator/scene/noise_source.hpp"

namespace stride::sim {

StartPerturbation ensemble_member(const EnsembleSpec& spec, int k) {
  StartPerturbation p;
  p.seed = spec.first_seed + static_cast<std::uint64_t>(k);
  NoiseSource draw = NoiseSource::for_stream(p.seed, "ensemble/start");
  p.heading = draw.uniform(-spec.heading_spread, spec.heading_spread);
  p.offset.x() = draw.uniform(-spec.position_spread, spec.position_spread);
  p.offset.y() = draw.uniform(-spec.position_spread, spec.position_spread);
  return p;
}

void apply_start(SceneDescription& scene, const StartPerturbation& p) {
  scene.physics.seed = p.seed;
  for (RobotPlacement& r : scene.robots) {
    r.rpy.z() += p.heading;
    r.xyz.x() += p.offset.x();
    r.xyz.y() += p.offset.y();
  }
}

}  // namespace stride::sim
