#pragma once
// Every run a sweep makes, in order: what each sets and the plan columns (factor levels, their
// constants, the seed) its CSV row starts with. Run ids are positions in this order, so the same
// sweep gives the same ids whatever runs, resumes or executor.
#include <cstdint>
#include <string>
#include <vector>

#include "console/sweep/sweep_spec.hpp"

namespace stride::sweep {

struct RunPlan {
  std::int64_t id = 0;
  std::vector<Setting> settings;   // in the order they apply (later ones win)
  std::vector<std::string> cells;  // one per Plan::columns entry ("" where a block has none)
};

struct Plan {
  std::vector<std::string> columns;  // "scene", factor and constant columns, "seed" last
  std::vector<RunPlan> runs;
};

// Throws stride::Error when the sweep has no runs or more than `max_runs` (by default a million:
// days of computing even at a second a run, so more is a typing mistake).
Plan expand(const SweepSpec& spec, std::size_t max_runs = 1'000'000);

// The number in a level or range's value text: "{}" in `format` replaced by the shortest text
// that reads back to `v`.
std::string format_value(const std::string& format, double v);
// Shortest text that reads back to the same double ("nan", "inf", "-inf" for the others).
std::string number_text(double v);

}  // namespace stride::sweep
