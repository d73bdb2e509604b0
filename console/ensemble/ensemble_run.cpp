#include "console/ensemble/ensemble_run.hpp"

#include <chrono>

#include "console/session/sim_session.hpp"
#include "console/sweep/ordered_jobs.hpp"
#include "robot/core/error.hpp"
#include "robot/framework/binary.hpp"

namespace stride::ensemble {

MemberOutcome run_member(const EnsembleRequest& r, int k) {
  sim::SceneDescription scene = sim::parse_scene_file(r.scene, r.physics);
  sim::apply_start(scene, sim::ensemble_member(r.spec, k));
  console::SimSession session(std::move(scene));
  const auto t0 = std::chrono::steady_clock::now();
  session.simulation().run_for(r.seconds);
  MemberOutcome m;
  m.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  m.sim_seconds = session.simulation().time();
  if (session.simulation().robot_count() > 0)
    m.walk = session.simulation().walk_metrics(0).result();
  return m;
}

std::vector<std::vector<MemberOutcome>> run_ensembles(const std::vector<EnsembleRequest>& requests,
                                                      int jobs) {
  std::vector<std::pair<std::size_t, int>> members;  // request, member: one job each
  std::vector<std::vector<MemberOutcome>> results(requests.size());
  for (std::size_t i = 0; i < requests.size(); ++i) {
    results[i].resize(static_cast<std::size_t>(requests[i].spec.members));
    for (int k = 0; k < requests[i].spec.members; ++k) members.emplace_back(i, k);
  }
  sweep::run_jobs(
      members.size(), jobs,
      [&](std::size_t j) {
        return to_binary(run_member(requests[members[j].first], members[j].second));
      },
      [&](std::size_t j, std::string&& bytes) {
        from_binary(results[members[j].first][static_cast<std::size_t>(members[j].second)], bytes);
        return true;
      },
      [&](std::size_t j) {
        const auto& [i, k] = members[j];
        return requests[i].scene + " (member " + std::to_string(k + 1) + ", seed " +
               std::to_string(sim::ensemble_member(requests[i].spec, k).seed) + ")";
      });
  return results;
}

}  // namespace stride::ensemble
