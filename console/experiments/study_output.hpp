#pragma once
// A finished (or stopped) sweep's output read back for figures: runs.csv and the per-run traces,
// so that `--resume` on a study's output redraws its figures without running a walk.
#include <string>
#include <vector>

namespace stride::experiments {

// runs.csv of a sweep's output: the header and the rows that ran (status ok).
struct RunsCsv {
  std::string path;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  // The column's index; throws stride::Error naming the file and the column.
  std::size_t column(const std::string& name) const;
  // A row's cell as a number; throws stride::Error naming the file and the column.
  double number(const std::vector<std::string>& row, const std::string& name) const;
};
RunsCsv read_runs_csv(const std::string& out_dir);

// <out_dir>/traces/run-<id>.csv of a row (it may not exist: only some runs are traced).
std::string trace_path(const std::string& out_dir, const RunsCsv& runs,
                       const std::vector<std::string>& row);

// The named columns of a trace CSV, one vector per line in the order asked; throws
// stride::Error naming the file and a missing column or a cell that is no number.
std::vector<std::vector<double>> read_trace(const std::string& path,
                                            const std::vector<std::string>& columns);

}  // namespace stride::experiments
