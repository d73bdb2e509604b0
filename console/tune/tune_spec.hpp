#pragma once
// A tuning file as plain data: what is held fixed, the parameters searched within their bounds
// (with the thesis' value of each), the floors, the training and held-out walks, what each walk
// records, the objective over a walk's record, and the search's size and seed. Every generation's
// sweep and the held-out sweep are built from it (tune_sweeps.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include "console/sweep/sweep_spec.hpp"

namespace stride::tune {

struct TuneParam {
  std::string name;                  // its column
  std::vector<std::string> targets;  // setting targets it sets (Module.field, scene:...@attr)
  double min = 0, max = 1;           // bounds of the search
  double thesis = 0;                 // the thesis' value: the baseline of the held-out comparison
  std::string format = "{}";         // the value's text, {} replaced by the number
  int line = 0;
};

// A named floor: scene settings (e.g. scene:uneven@seed) a walk on it applies.
struct TuneFloor {
  std::string name;
  std::vector<sweep::Setting> settings;
  int line = 0;
};

// Which walks judge a candidate: every floor named here x every seed.
struct WalkSet {
  std::vector<std::string> floors;
  std::vector<std::uint64_t> seeds;
  double heading_spread = 0, position_spread = 0;  // perturbed starts, as a sweep's <seeds>
  int line = 0;
};

struct TuneSpec {
  std::string name, file, scene_dir;
  std::vector<sweep::Setting> settings;  // held fixed in every walk, in file order
  std::vector<TuneParam> params;
  std::vector<TuneFloor> floors;
  WalkSet train, heldout;
  sweep::TimePoint until{"end", 0};
  sweep::RecordSpec record;
  std::string objective;    // an expression over a walk's record (larger is better)
  double failed_value = 0;  // a failed walk's objective
  int objective_line = 0;
  int population = 0, generations = 0;  // candidates per generation; generations after the first
  std::uint64_t seed = 1;               // the optimiser's
  int search_line = 0;
};

}  // namespace stride::tune
