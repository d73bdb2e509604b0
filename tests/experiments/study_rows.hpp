#pragma once
// A thesis study's sweep file run in this process on some of its runs, each row as column -> text,
// so a test checks a study with the study's own record and criteria.
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "console/sweep/sweep_engine.hpp"
#include "console/sweep/sweep_request.hpp"

namespace stride::experiments::test {

using Row = std::map<std::string, std::string>;

// scenes/experiments/<name>.sweep.xml (scenes from `scenes`, "" for the file's own), the runs
// `only` picks, seed 1.
inline std::vector<Row> study_rows(
    const std::string& name, const std::string& scenes,
    std::vector<std::pair<std::string, std::vector<std::string>>> only) {
  sweep::SweepRequest r;
  r.file = std::string(STRIDE_SOURCE_DIR) + "/scenes/experiments/" + name + ".sweep.xml";
  r.seeds = 1;
  if (!scenes.empty())
    r.scenes_dir = std::string(STRIDE_SOURCE_DIR) + "/scenes/experiments/" + scenes;
  r.options.only = std::move(only);
  r.options.print_tallies = r.options.plots = false;
  const sweep::Sweep s = sweep::checked_sweep(r);
  const auto executor = sweep::in_process_executor();
  std::ostringstream text;
  const sweep::SweepResult result =
      sweep::run_sweep(s, sweep::Tallies(s), *executor, r.options, text);
  const std::vector<std::string> header = s.csv_header();
  std::vector<Row> rows;
  for (const auto& cells : result.rows) {
    Row row;
    for (std::size_t i = 0; i < header.size(); ++i) row[header[i]] = cells.at(i);
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace stride::experiments::test
