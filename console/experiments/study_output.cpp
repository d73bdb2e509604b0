#include "console/experiments/study_output.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "console/sweep/csv_line.hpp"
#include "robot/core/error.hpp"
#include "robot/core/number_text.hpp"

namespace stride::experiments {
namespace {

namespace fs = std::filesystem;

std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot be read");
  std::vector<std::vector<std::string>> lines;
  for (std::string line; std::getline(in, line);) {
    auto cells = sweep::parse_csv_line(line);
    if (!cells)
      throw Error(path + ":" + std::to_string(lines.size() + 1) + ": a quoted field not closed");
    lines.push_back(std::move(*cells));
  }
  if (lines.empty()) throw Error(path + ": empty (expected a header line)");
  return lines;
}

std::size_t index_of(const std::vector<std::string>& header, const std::string& name,
                     const std::string& path) {
  const auto it = std::find(header.begin(), header.end(), name);
  if (it == header.end()) throw Error(path + ": no column '" + name + "'");
  return static_cast<std::size_t>(it - header.begin());
}

}  // namespace

std::size_t RunsCsv::column(const std::string& name) const {
  return index_of(header, name, path);
}

double RunsCsv::number(const std::vector<std::string>& row, const std::string& name) const {
  return parse_number(row.at(column(name)), path + ": column " + name);
}

RunsCsv read_runs_csv(const std::string& out_dir) {
  RunsCsv runs;
  runs.path = (fs::path(out_dir) / "runs.csv").string();
  auto lines = read_csv(runs.path);
  runs.header = std::move(lines.front());
  const std::size_t status = runs.column("status");
  for (std::size_t i = 1; i < lines.size(); ++i)
    if (lines[i].size() == runs.header.size() && lines[i][status] == "ok")
      runs.rows.push_back(std::move(lines[i]));
  return runs;
}

std::string trace_path(const std::string& out_dir, const RunsCsv& runs,
                       const std::vector<std::string>& row) {
  return (fs::path(out_dir) / "traces" / ("run-" + row.at(runs.column("run")) + ".csv")).string();
}

std::vector<std::vector<double>> read_trace(const std::string& path,
                                            const std::vector<std::string>& columns) {
  const auto lines = read_csv(path);
  std::vector<std::size_t> cols;
  for (const std::string& c : columns) cols.push_back(index_of(lines.front(), c, path));
  std::vector<std::vector<double>> rows;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::vector<double> row;
    for (std::size_t k = 0; k < cols.size(); ++k)
      row.push_back(parse_number(lines[i].at(cols[k]), path + ": column " + columns[k]));
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace stride::experiments
