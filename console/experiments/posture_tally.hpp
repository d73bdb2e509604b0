#pragma once
// The Sec. 4.3.4.2 criterion counted over the seeds of one posture case: how many walks fell or
// tilted past sim::kTipAngle, which way they first tilted, and how the others walked.
#include <array>
#include <string>
#include <vector>

#include "console/experiments/walk_recording.hpp"

namespace stride::experiments {

struct PostureTally {
  int walks = 0;
  int fell = 0;
  std::array<int, 4> tip_way{};     // forward, backward, right, left: the first pass of kTipAngle
  int kept = 0;                     // neither fell nor tipped
  double kept_distance_sum = 0;     // m, ground truth
  double kept_fk_distance_sum = 0;  // m, the thesis' FK measure
  double kept_max_pitch = 0;        // rad, the largest |pitch| of a kept walk

  int tipped() const { return tip_way[0] + tip_way[1] + tip_way[2] + tip_way[3]; }
  int lost() const { return walks - kept; }  // fell or tipped
};

void add_walk(PostureTally& t, const WalkSummary& s);

// `case walks fell tipped lost fwd/back/right/left kept-mean-distance kept-mean-fk-distance
// thesis-distance kept-max-pitch`, as text; `thesis_distance` is the case's printed figure (m),
// NaN where the thesis prints none.
std::vector<std::string> tally_row(const std::string& name, const PostureTally& t,
                                   double thesis_distance);
std::vector<std::string> tally_header();

}  // namespace stride::experiments
