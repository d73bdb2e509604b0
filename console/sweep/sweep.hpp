#pragma once
// A sweep ready to run: the spec checked (every key, mark, expression and setting target), its
// plan expanded, its record columns named. run() makes one run in this process and never throws:
// whatever goes wrong (a bad scene, a diverging simulation, an exception) is a failed row.
#include <memory>
#include <string>
#include <vector>

#include "console/sweep/run_plan.hpp"
#include "console/sweep/run_row.hpp"
#include "console/sweep/sweep_spec.hpp"

namespace stride::sweep {

struct RecordColumn {
  std::string name;
  bool text = false;
};

class Sweep {
 public:
  // Throws stride::Error ("file:line: ..." for specs from a file) and builds nothing on error.
  // `check_scenes` also loads each scene once with its first run's settings, so a bad key or
  // setting is found before any run (a scene that does not load, see check_scenes).
  explicit Sweep(SweepSpec spec, bool check_scenes = true);
  ~Sweep();
  Sweep(Sweep&&) noexcept;

  const SweepSpec& spec() const { return spec_; }
  const Plan& plan() const { return plan_; }
  const std::vector<RecordColumn>& record_columns() const { return record_; }
  // run, the plan columns, status, the record columns, reason.
  std::vector<std::string> csv_header() const;
  // A run's CSV row: its id, plan cells, status, record cells (empty when it failed), reason.
  std::vector<std::string> csv_cells(const RunRow& row) const;
  // Whether the header column `name` holds texts (plan columns holding numbers count as numbers).
  bool column_is_text(const std::string& name) const;

  // The scene check of the constructor for the plan indices `runs` only (a filtered sweep needs
  // only its own scenes). Returns one line per scene that does not load ("run N: file:line:
  // ..."): its runs will be failed rows. Throws when no scene loads, or a key does not bind.
  const std::vector<std::string>& check_scenes(const std::vector<std::size_t>& runs);
  // What the last check returned.
  const std::vector<std::string>& unloadable_scenes() const { return unloadable_; }

  // Runs plan().runs[index].
  RunRow run(std::size_t index) const;

  struct Compiled;

 private:
  SweepSpec spec_;
  Plan plan_;
  std::vector<RecordColumn> record_;
  std::unique_ptr<Compiled> compiled_;
  std::vector<std::string> unloadable_;
};

// The scene file a run loads: its last "scene" setting against the sweep's scene directory.
std::string scene_path_of(const SweepSpec& spec, const RunPlan& run);

}  // namespace stride::sweep
