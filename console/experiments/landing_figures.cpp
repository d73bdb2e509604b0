#include "console/experiments/landing_figures.hpp"

#include <filesystem>

#include "console/experiments/study_output.hpp"
#include "console/plot/figure_folder.hpp"
#include "console/plot/gnuplot_plot.hpp"
#include "console/plot/run_figures.hpp"

namespace stride::experiments {

namespace {
constexpr double kWindow = 1.0;  // s of walking drawn: four touch-downs of the medium walk
}  // namespace

void write_landing_figure(const std::string& out_dir, bool png) {
  const RunsCsv runs = read_runs_csv(out_dir);
  plot::RunSet set{{"t", "fsr_left", "fsr_right"}, {}};
  for (const auto& row : runs.rows) {
    const std::string trace = trace_path(out_dir, runs, row);
    if (!std::filesystem::exists(trace)) continue;
    plot::Run run{"landing " + row.at(runs.column("landing")) + ", " +
                      row.at(runs.column("speed")) + ", " + row.at(runs.column("floor_mm")) + " mm",
                  read_trace(trace, set.columns)};
    if (run.rows.empty()) continue;
    const double t0 = run.rows.front()[0];
    std::erase_if(run.rows, [&](const std::vector<double>& r) { return r[0] > t0 + kWindow; });
    set.runs.push_back(std::move(run));
  }
  if (set.runs.empty()) return;
  plot::write_long_csv(set, (std::filesystem::path(out_dir) / "fsr_touchdown_runs.csv").string());
  if (!png || plot::png_terminal().empty()) return;
  plot::Figure f;
  f.stem = "landing_off_and_on";
  f.title = "FSR totals around touch-down, landing control off and on (seed 1)";
  f.x_label = "t [s]";
  f.panels = {{"left sole FSR total [N]", {"fsr_left"}, {}},
              {"right sole FSR total [N]", {"fsr_right"}, {}}};
  plot::write_figure(set, f, plot::figure_dir(out_dir, "fsr_touchdown"));
}

}  // namespace stride::experiments
