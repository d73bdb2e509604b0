#pragma once
// Runs one scene as an ensemble of perturbed starts (sim::EnsembleSpec), optionally under a
// solver setting set over its <physics>, and keeps each member's walk figures (robot 0).
#include <string>
#include <string_view>
#include <vector>

#include "simulator/scene/scene_parser.hpp"
#include "simulator/scene/start_perturbation.hpp"
#include "simulator/walk_metrics.hpp"

namespace stride::ensemble {

struct EnsembleRequest {
  std::string scene;               // path
  sim::PhysicsAttributes physics;  // set over the scene's <physics> (empty: as written)
  sim::EnsembleSpec spec;
  double seconds = 10;  // simulated per member
};

struct MemberOutcome {
  STRIDE_FIELDS(MemberOutcome);
  STRIDE_FIELD(sim::WalkMetricsResult, walk);  // robot 0, over the whole run
  STRIDE_FIELD(double, sim_seconds, "s") = 0;
  STRIDE_FIELD(double, wall_seconds, "s") = 0;  // the member's own run, in its worker

  // Reflected: a member comes back from its worker in the framework's binary encoding.
  static constexpr std::string_view kTypeName = "MemberOutcome";
};

// Member k of `r`: the scene loaded with r.physics, start k applied, run with its controllers.
// Throws stride::Error naming the scene (file:line) or the setting.
MemberOutcome run_member(const EnsembleRequest& r, int k);

// Every member of every request, spread over up to `jobs` worker processes; results[i][k] is
// member k of requests[i], the same whatever `jobs` is.
std::vector<std::vector<MemberOutcome>> run_ensembles(const std::vector<EnsembleRequest>& requests,
                                                      int jobs);

}  // namespace stride::ensemble
