#include "console/tune/tune_output.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "console/build_revision.hpp"
#include "console/sweep/csv_line.hpp"
#include "console/sweep/run_plan.hpp"
#include "console/sweep/sweep_output.hpp"
#include "robot/core/error.hpp"

namespace stride::tune {
namespace fs = std::filesystem;

TuneOutput::TuneOutput(const std::string& dir, const std::string& file_text, bool resume,
                       bool overwrite, const std::string& command)
    : dir_(dir) {
  sweep::create_output_dir(dir);
  const fs::path d(dir);
  std::error_code ec;
  const bool holds = fs::exists(d / "tune.xml", ec) || fs::exists(d / "generations", ec);
  if (resume && holds && sweep::read_whole_file((d / "tune.xml").string()) != file_text)
    throw Error("--resume: '" + dir + "' holds a search of another tuning file (tune.xml differs)");
  if (!resume && holds) {
    if (!overwrite)
      throw Error("--out: '" + dir + "' already holds a search (--resume continues it, " +
                  "--overwrite starts again)");
    for (const char* old : {"generations", "heldout", "search.csv", "results.txt"})
      fs::remove_all(d / old, ec);
  }
  write_file("tune.xml", file_text);
  write_file("manifest.txt", "command: " + command +
                                 "\nrevision: " + std::string(console::build_revision()) + "\n");
  fs::create_directories(d / "generations", ec);
  if (ec)
    throw Error("--out: cannot create '" + (d / "generations").string() + "': " + ec.message());
}

std::string TuneOutput::generation_dir(int generation) const {
  char name[32];
  std::snprintf(name, sizeof name, "gen-%04d", generation);
  return (fs::path(dir_) / "generations" / name).string();
}

std::string TuneOutput::heldout_dir() const {
  return (fs::path(dir_) / "heldout").string();
}

void TuneOutput::write_search(const TuneSpec& tune,
                              const std::vector<SearchRecord>& records) const {
  std::vector<std::string> header{"generation", "candidate"};
  for (const TuneParam& p : tune.params) header.push_back(p.name);
  for (const char* c : {"objective", "walks", "failed", "best_so_far"}) header.emplace_back(c);
  std::string text = sweep::csv_line(header);
  double best = 0;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const SearchRecord& r = records[i];
    if (i == 0 || r.score.objective > best) best = r.score.objective;
    std::vector<std::string> cells{std::to_string(r.generation), r.label};
    for (double v : r.values) cells.push_back(sweep::number_text(v));
    cells.push_back(sweep::number_text(r.score.objective));
    cells.push_back(std::to_string(r.score.walks));
    cells.push_back(std::to_string(r.score.failed));
    cells.push_back(sweep::number_text(best));
    text += sweep::csv_line(cells);
  }
  write_file("search.csv", text);
}

void TuneOutput::write_file(const std::string& name, const std::string& text) const {
  sweep::write_whole_file((fs::path(dir_) / name).string(), text);
}

}  // namespace stride::tune
