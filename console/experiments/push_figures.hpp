#pragma once
// Figures of the issue-31 push studies, drawn from a sweep's output directory (runs.csv and
// traces/), so that a finished or resumed study redraws them:
//   position-push  phase_<control>.png: seed 1's estimated CoM state (x, xdot) from just before
//                  the push, one curve per impulse (recovered or not), against the Ch. 7
//                  boundaries: each strategy's capture interval [lo, hi] as the two lines
//                  xdot = omega (lo - x) and xdot = omega (hi - x) (Eq. 7.13,
//                  Eq. 7.30 and Eq. 7.37).
//   push-recovery  push_map_<direction>.png: walks lost of the seeds by push and gait phase,
//                  posture control alone beside push recovery.
#include <string>
#include <vector>

#include "console/experiments/study_output.hpp"

namespace stride::experiments {

// One cell of the push map: walks lost of the walks made.
struct MapCell {
  std::string control, direction;
  double push = 0, phase = 0;
  int walks = 0, lost = 0;
};
// The cells of runs.csv (columns control, dir, N, phase, lost), in order of first appearance;
// the unpushed walks (dir none) are left out.
std::vector<MapCell> push_map_cells(const RunsCsv& runs);

// Both throw stride::Error when a file or column is missing or gnuplot fails; nothing is drawn
// without `png` or gnuplot (the CSVs are written still).
void write_phase_portraits(const std::string& out_dir, bool png);
void write_push_map(const std::string& out_dir, bool png);

}  // namespace stride::experiments
