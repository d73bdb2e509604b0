#include "console/experiments/experiment_list.hpp"

#include <algorithm>
#include <array>
#include <filesystem>
#include <ostream>

#include "console/experiments/fastest_search.hpp"
#include "console/experiments/figure_index.hpp"
#include "console/experiments/kalman_experiment.hpp"
#include "console/experiments/landing_figures.hpp"
#include "console/experiments/posture_figures.hpp"
#include "console/experiments/push_figures.hpp"
#include "console/sweep/sweep_request.hpp"
#include "robot/core/data_dir.hpp"
#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"

namespace stride::experiments {
namespace {

constexpr std::array kSweeps = {"posture",       "knee-energy",   "fastest",
                                "arm-swing",     "gains",         "push",
                                "position-push", "push-recovery", "landing-control"};

}  // namespace

std::vector<std::string> posture_case_levels(const sweep::Sweep& s,
                                             const std::vector<std::string>& cases) {
  std::vector<std::string> levels;
  const auto& columns = s.plan().columns;
  const auto c =
      static_cast<std::size_t>(std::find(columns.begin(), columns.end(), "case") - columns.begin());
  for (const std::string& want : cases) {
    bool found = false;
    for (const sweep::RunPlan& r : s.plan().runs) {
      if (c >= r.cells.size()) break;
      const std::string& l = r.cells[c];
      if (l != want && l.rfind(want + "_", 0) != 0) continue;
      found = true;
      if (std::find(levels.begin(), levels.end(), l) == levels.end()) levels.push_back(l);
    }
    if (!found)
      throw UsageError("stride experiment posture: --cases: unknown case '" + want +
                       "' (expected none, hip, ankle or <strategy>_<slow|medium|fast>)");
  }
  return levels;
}

namespace {

int run_sweep_experiment(const std::string& name, const ExperimentOptions& o, std::ostream& out,
                         std::ostream& err) {
  // A relative directory not under the working directory is the data directory's (data_dir.hpp).
  const std::string scenes = o.scenes_dir.empty() ? "" : find_input(o.scenes_dir);
  std::error_code ec;  // a name the system refuses (too long) is not found either
  if (!scenes.empty() && !std::filesystem::is_directory(scenes, ec))
    throw InputError("stride experiment " + name + ": --scenes: directory '" + o.scenes_dir +
                     "' not found");
  sweep::SweepRequest r;
  r.file = experiment_sweep_file(name, o.sweeps_dir);
  r.jobs = o.jobs;
  r.seeds = o.seeds;
  r.scenes_dir = scenes;
  r.quiet = o.quiet;
  for (const auto& [module, text] : o.parameters) {
    const std::size_t eq = text.find('=');
    r.settings.push_back({module + "." + text.substr(0, eq), text.substr(eq + 1)});
  }
  r.settings.insert(r.settings.end(), o.physics.begin(), o.physics.end());
  r.options.out_dir = o.out_dir;
  r.options.resume = o.resume;
  r.options.plots = o.plots;
  r.options.command = o.command;
  r.options.only = o.only;
  r.link = o.link;
  if (!o.cases.empty()) {
    r.options.only.push_back(
        {"case", posture_case_levels(sweep::Sweep(sweep::request_spec(r), false), o.cases)});
  }
  if (name == "fastest") return run_fastest_search(r, out);
  const auto result = sweep::run_sweep_request(r, out, err);
  if (!result) return 0;  // an MPI worker rank
  if (!result->complete) return 130;
  if (name == "posture" && !o.out_dir.empty()) write_posture_figures(o.out_dir, *result, o.plots);
  if (name == "position-push" && !o.out_dir.empty()) write_phase_portraits(o.out_dir, o.plots);
  if (name == "push-recovery" && !o.out_dir.empty()) write_push_map(o.out_dir, o.plots);
  if (name == "landing-control" && !o.out_dir.empty()) write_landing_figure(o.out_dir, o.plots);
  if (!o.out_dir.empty() && o.plots) print_figure_index(o.out_dir, name, out);
  if (result->failed == 0) return 0;
  err << "stride experiment " << name << ": " << result->failed
      << " walk(s) failed (listed with their reasons above)\n";
  return 1;
}

}  // namespace

std::string experiment_names() {
  std::string names;
  for (const char* n : kSweeps) names += (names.empty() ? "" : ", ") + std::string(n);
  return names + ", kalman";
}

std::string experiment_sweep_file(const std::string& name, const std::string& sweeps_dir) {
  if (name == "kalman") return "";
  if (std::find(kSweeps.begin(), kSweeps.end(), name) == kSweeps.end())
    // A pasted screenful is quoted short; the list of names then stays out of the one line too.
    throw UsageError("stride experiment: unknown experiment " + quote(name) +
                     (name.size() > 40 ? " (`stride experiment --help` lists them)"
                                       : " (expected one of " + experiment_names() + ")"));
  const std::filesystem::path p =
      std::filesystem::path(find_input(sweeps_dir)) / (name + ".sweep.xml");
  std::error_code ec;
  if (!std::filesystem::exists(p, ec))
    throw InputError("experiment sweep file " + quote(p.string()) +
                     " not found (--sweeps <dir> chooses another)");
  return p.string();
}

int run_experiment(const std::string& name, const ExperimentOptions& o, std::ostream& out,
                   std::ostream& err) {
  if (experiment_sweep_file(name, o.sweeps_dir).empty()) return run_kalman_experiment(o, out);
  return run_sweep_experiment(name, o, out, err);
}

}  // namespace stride::experiments
