#include "console/experiments/posture_tally.hpp"

#include <algorithm>
#include <cmath>

#include "console/experiments/experiment_options.hpp"

namespace stride::experiments {

void add_walk(PostureTally& t, const WalkSummary& s) {
  ++t.walks;
  t.fell += s.fell;
  const bool tipped = s.tipped != sim::Tip::None;
  if (tipped) ++t.tip_way[static_cast<int>(s.tipped) - 1];
  if (s.fell || tipped) return;
  ++t.kept;
  t.kept_distance_sum += s.distance;
  t.kept_fk_distance_sum += s.fk_distance;
  t.kept_max_pitch = std::max({t.kept_max_pitch, -s.pitch_min, s.pitch_max});
}

std::vector<std::string> tally_header() {
  return {"case", "walks",   "fell",  "tipped",    "lost",      "fwd/back/right/left",
          "kept", "dist[m]", "fk[m]", "thesis[m]", "max|pitch|"};
}

std::vector<std::string> tally_row(const std::string& name, const PostureTally& t,
                                   double thesis_distance) {
  const auto& w = t.tip_way;
  const bool any = t.kept > 0;
  return {name,
          std::to_string(t.walks),
          std::to_string(t.fell),
          std::to_string(t.tipped()),
          std::to_string(t.lost()) + "/" + std::to_string(t.walks),
          std::to_string(w[0]) + "/" + std::to_string(w[1]) + "/" + std::to_string(w[2]) + "/" +
              std::to_string(w[3]),
          std::to_string(t.kept),
          any ? fixed(t.kept_distance_sum / t.kept, 3) : "-",
          any ? fixed(t.kept_fk_distance_sum / t.kept, 3) : "-",
          std::isfinite(thesis_distance) ? fixed(thesis_distance, 3) : "-",
          any ? fixed(t.kept_max_pitch, 3) : "-"};
}

}  // namespace stride::experiments
