#include "console/experiments/fastest_search.hpp"

#include <algorithm>
#include <ostream>
#include <sstream>

#include "console/experiments/experiment_options.hpp"
#include "robot/core/error.hpp"

namespace stride::experiments {
namespace {

// The levels of a plan column in plan order, each once.
std::vector<std::string> levels_of(const sweep::Sweep& s, std::size_t column) {
  std::vector<std::string> out;
  for (const sweep::RunPlan& r : s.plan().runs)
    if (std::find(out.begin(), out.end(), r.cells[column]) == out.end())
      out.push_back(r.cells[column]);
  return out;
}

struct Columns {
  std::vector<std::string> header;
  std::size_t at(const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) throw Error("fastest: the sweep has no column '" + name + "'");
    return static_cast<std::size_t>(it - header.begin());
  }
};

double number(const std::string& text) {
  return text.empty() ? 0.0 : std::stod(text);
}

// One step of the search: the runs of one floor, target and setting, added to the one output.
sweep::SweepOptions step_options(const sweep::SweepRequest& request, const std::string& floor,
                                 const std::string& target, const std::string& setting,
                                 bool first_step) {
  sweep::SweepOptions o;
  o.print_tallies = o.plots = false;
  o.only = {{"floor", {floor}}, {"target", {target}}, {"setting", {setting}}};
  o.stop = [] { return sweep::InterruptGuard::interrupted(); };
  // Every step adds its runs to the one output, so --resume skips the steps already made.
  o.out_dir = request.options.out_dir;
  o.resume = !first_step || request.options.resume;
  o.overwrite = first_step && request.options.overwrite;
  o.command = request.options.command;
  return o;
}

}  // namespace

int run_fastest_search(const sweep::SweepRequest& request, std::ostream& out) {
  const sweep::Sweep sweep = sweep::checked_sweep(request);
  const sweep::Tallies tallies(sweep);
  const Columns c{sweep.csv_header()};
  const std::size_t floor_c = c.at("floor") - 1, target_c = c.at("target") - 1,
                    setting_c = c.at("setting") - 1;  // plan columns follow "run"
  const std::size_t status = c.at("status"), stable = c.at("stable"), speed = c.at("speed"),
                    distance = c.at("distance"), step = c.at("step_length"),
                    strategy = c.at("strategy"), t_stride = c.at("T_stride"), z = c.at("z"),
                    h_foot = c.at("H_foot"), gains = c.at("gains");
  const int jobs = request.jobs > 0 ? request.jobs : sweep::hardware_jobs();
  auto executor = jobs == 1 ? sweep::in_process_executor() : sweep::worker_process_executor(jobs);
  const std::size_t seeds = sweep.spec().seeds.size();
  sweep::InterruptGuard guard;
  std::vector<std::vector<std::string>> best_rows;
  bool first_step = true;
  for (const std::string& floor : levels_of(sweep, floor_c)) {
    std::vector<std::string> best;
    double best_speed = -1;
    for (const std::string& target : levels_of(sweep, target_c)) {
      bool found = false;
      for (const std::string& setting : levels_of(sweep, setting_c)) {
        const sweep::SweepOptions o = step_options(request, floor, target, setting, first_step);
        first_step = false;
        std::ostringstream quiet;
        const sweep::SweepResult r = sweep::run_sweep(sweep, tallies, *executor, o, quiet);
        if (!r.complete) return 130;
        std::size_t ok = 0;
        double v = 0, dist = 0, step_length = 0;  // means over the seeds
        for (const auto& row : r.rows) {
          if (row[status] != "ok") {
            out << "  " << floor << " target " << target << " setting " << setting << ": "
                << row.back() << "\n";
            continue;
          }
          ok += row[stable] == "1";
          v += number(row[speed]) / seeds, dist += number(row[distance]) / seeds;
          step_length += number(row[step]) / seeds;
        }
        out << "  " << floor << " target " << fixed(number(target), 2) << " setting " << setting
            << ": " << ok << "/" << seeds << " stable\n";
        if (ok != seeds) continue;
        found = true;
        if (v > best_speed) {
          const auto& first = r.rows.front();
          best_speed = v;
          best = {floor,
                  fixed(number(target), 2),
                  fixed(v, 4),
                  fixed(dist, 3),
                  fixed(step_length, 4),
                  first[t_stride],
                  first[z],
                  first[h_foot],
                  first[strategy],
                  first[gains],
                  "1",
                  std::to_string(seeds)};
        }
        break;
      }
      if (!found) break;
    }
    if (!best.empty()) best_rows.push_back(best);
  }
  out << "Fastest stable walk (A_l = 0.5 mm; v = mean over the seeds); thesis: 0.24 m/s on the "
         "real NAO\n";
  print_table(out,
              {"floor", "target", "v [m/s]", "dist [m]", "step [m]", "T_stride", "z_min/z_max",
               "H_foot", "strategy", "Kp/Kd", "arm swing", "seeds"},
              best_rows);
  return 0;
}

}  // namespace stride::experiments
