#pragma once
// A sweep as plain data: which runs (scenes, factors and their levels, seeds), how long each runs,
// what each run records, and the tallies over groups of runs. Built by the sweep-file parser or
// directly by code (a tuning loop, a convergence study); the engine only reads it.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace stride::sweep {

// One assignment a run makes. Targets:
//   "scene"                     the scene file (relative to the sweep's scene directory)
//   "seed"                      the scene seed
//   "Module.field"              a module parameter (as `set module:Module field=value`)
//   "provider:Representation"   the module providing it (as `mr`)
//   "scene:<element path>@attr" an attribute of the scene XML, e.g. "scene:uneven@height",
//                               "scene:robot/motor[name=pitch]@gain", "scene:push[2]@force"
struct Setting {
  std::string target;
  std::string value;
};

struct Level {
  std::string label;                                         // the factor column's text
  std::vector<Setting> settings;                             // what choosing it sets
  std::vector<std::pair<std::string, std::string>> columns;  // constants shown with it
};

struct Factor {
  std::string name;  // its column
  std::vector<Level> levels;
  int line = 0;  // where the sweep file states it (0: built in code)
};

// Factors combined as a full grid (the first factor outermost), or `count` points drawn from
// continuous ranges: independently uniform, or a Latin hypercube (each range cut into `count`
// strata, each stratum used once per factor).
struct Block {
  enum class Kind { Grid, Random, LatinHypercube } kind = Kind::Grid;
  std::vector<Factor> factors;  // Grid
  struct Range {
    std::string name;
    std::vector<std::string> targets;
    double min = 0, max = 1;
    std::string format = "{}";  // the value's text, {} replaced by the number
    int line = 0;
  };
  std::vector<Range> ranges;  // Random, LatinHypercube
  int count = 0;
  std::uint64_t seed = 1;
  std::vector<Setting> settings;  // applied to every run of the block, before the factors
  std::vector<std::pair<std::string, std::string>> columns;  // constants shown with its runs
};

// A time within a run: a mark plus an offset. Marks: "start" (0), "end" (the run's end),
// "walk_start" and "walk_end" (the walking pattern's start and end on robot 0).
struct TimePoint {
  std::string mark = "start";
  double offset = 0;  // s
};

// A number or text read at one time (default: the end of the run).
struct ValueSpec {
  std::string name, key;
  TimePoint at{"end", 0};
  int line = 0;
};

// One number per run from a per-frame key over a window: frames with from <= t (and t < to, or
// t <= through), stopping before the first frame where `until` (an expression over per-frame
// keys) holds.
struct SummarySpec {
  enum class Stat {
    Min,
    Max,
    Mean,
    Rms,
    Sd,
    First,
    Final,
    Change,
    Sum,
    Integral,
    Count,
    FirstPast
  };
  std::string name, key;
  Stat stat = Stat::Mean;
  TimePoint from{"start", 0}, to{"end", 0};
  bool to_inclusive = true;  // `through` (t <= to) or `to` (t < to)
  std::string until;         // empty: no stop condition
  double threshold = 0;      // FirstPast: the first time |value| > threshold, -1 if never
  int line = 0;
};

// A column computed from the run's other columns once the run ended.
struct DerivedSpec {
  std::string name, expression;
  int line = 0;
};

// Per-frame keys of runs matching `where` written to <out>/traces/<run>.csv.
struct TraceSpec {
  std::string where;  // over the plan's columns (factors, seed); empty: every run
  std::vector<std::pair<std::string, std::string>> columns;  // name, key
  TimePoint from{"start", 0};
  int line = 0;
};

struct RecordSpec {
  std::vector<ValueSpec> values;
  std::vector<SummarySpec> summaries;
  std::vector<DerivedSpec> derived;  // in order; each may use the ones before
  std::vector<TraceSpec> traces;
};

// One column of a tally: an aggregate of the group's rows, or an expression over the tally's own
// columns, or a text with {column} placeholders.
struct TallyColumn {
  enum class Kind { Count, Sum, Mean, Min, Max, First, Last, Expr, Text } kind = Kind::Count;
  std::string name;
  std::string of;        // aggregates: an expression over the row
  std::string where;     // aggregates: which rows count (empty: all)
  bool with_sd = false;  // Mean: also the population standard deviation
  int decimals = -1;     // printed digits after the point (-1: shortest exact)
  bool hidden = false;   // in the CSV, not in the printed table (a helper for texts)
  int line = 0;
};

struct TallySpec {
  std::string name, title;
  std::vector<std::string> by;  // grouping columns, groups in order of first appearance
  std::string where;            // which rows enter (empty: all that ran)
  std::vector<TallyColumn> columns;
  int line = 0;
};

// A picture of a tally: `y` columns against `x`, one line per value of `series` (optional),
// over the tally rows `where` picks (an expression over the tally's columns; empty: all).
struct PlotSpec {
  std::string tally, x, series, title, x_label, y_label;
  std::vector<std::string> y;
  int line = 0;
  std::string where;
};

// How robot 0's controller reaches its simulated robot in every run: as the scene says (in
// process), in process through LoLA's packets at LoLA's 12 ms (`stride run --lola-packets`), or
// as a started `stride-robot` over a LoLA socket in lockstep (`stride run --lola`).
enum class RobotLink { InProcess, Packets, Lola };

struct SweepSpec {
  std::string name;
  std::string file;               // the sweep file ("" when built in code)
  std::string scene_dir;          // scene paths resolve against it
  std::vector<Setting> settings;  // applied to every run, before blocks and factors
  std::vector<Block> blocks;
  std::vector<std::uint64_t> seeds{1};  // the innermost factor of every block
  // <seeds heading_spread position_spread>: run with seed s starts perturbed as the ensemble
  // member of seed s (simulator/scene/start_perturbation.hpp, what `stride run --ensemble` and
  // `stride converge` draw): heading and x/y offsets uniform within the spreads. Both 0: a seed
  // changes the sensor noise (and ODE's iterative row order) only, so with the exact solver an
  // uncontrolled walk is the same walk under every seed.
  double start_heading_spread = 0;   // rad
  double start_position_spread = 0;  // m
  // <seeds><range .../></seeds>: each range drawn once per seed, uniform in [min, max) from the
  // seed alone (not from the level), so run s of every level gets the same value: a quantity
  // such as a push's gait phase that should vary over the seeds as the start does.
  std::vector<Block::Range> seed_draws;
  RobotLink robot_link = RobotLink::InProcess;
  TimePoint until{"end", 0};  // the run's length, as a time point (mark "end" invalid)
  RecordSpec record;
  std::vector<TallySpec> tallies;
  std::vector<PlotSpec> plots;
};

}  // namespace stride::sweep
