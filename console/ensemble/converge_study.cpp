#include "console/ensemble/converge_study.hpp"

#include <cmath>
#include <ostream>

#include "console/ensemble/ensemble_run.hpp"
#include "robot/core/error.hpp"
#include "robot/core/output_file.hpp"

namespace stride::ensemble {
namespace {

using experiments::fixed;

bool any_kept(const std::vector<EnsembleSummary>& s) {
  for (const EnsembleSummary& e : s)
    if (e.true_distance.n > 0) return true;
  return false;
}

void write_files(const ConvergeOptions& o, const std::vector<EnsembleSummary>& s) {
  if (!experiments::prepare_out_dir(o.files)) return;
  // With no kept walk the distance curve has no point to draw: its table is still written.
  experiments::ExperimentOptions distance_files = o.files;
  distance_files.plots = distance_files.plots && any_kept(s);
  plot::Table t{{"setting", "members", "fell", "lost", "distance_mean", "distance_sd",
                 "distance_min", "distance_max", "fk_distance_mean", "steps_mean", "steps_sd",
                 "slip_net_x_mean", "edge_time_mean", "real_time_factor", "wall_per_member"}};
  for (std::size_t i = 0; i < s.size(); ++i) {
    const EnsembleSummary& e = s[i];
    const auto mean = [](const Spread& x) { return x.n ? x.mean : std::nan(""); };
    t.add_row({double(i + 1), double(e.members), double(e.fell), double(e.lost),
               mean(e.true_distance), e.true_distance.sd,
               e.true_distance.n ? e.true_distance.min : std::nan(""),
               e.true_distance.n ? e.true_distance.max : std::nan(""), mean(e.fk_distance),
               mean(e.steps), e.steps.sd, mean(e.foot_slip_net_x), mean(e.foot_tilted_time),
               e.real_time_factor, e.wall_per_member});
  }
  const std::string x = "setting, numbered in converge_settings.txt [-]";
  experiments::write_plot(distance_files, t, "converge_distance",
                          o.scene + ": kept walks' true distance", "setting",
                          {{"distance_mean", "mean", ""},
                           {"distance_min", "min", ""},
                           {"distance_max", "max", ""},
                           {"fk_distance_mean", "FK mean", ""}},
                          x, "distance [m]", "linespoints");
  experiments::write_plot(o.files, t, "converge_outcome", o.scene + ": walks lost and steps",
                          "setting",
                          {{"lost", "lost (fell or tipped)", ""},
                           {"fell", "fell", ""},
                           {"steps_mean", "steps (kept, mean)", ""}},
                          x, "walks or steps [-]", "linespoints");
  std::string names;
  for (std::size_t i = 0; i < o.settings.size(); ++i)
    names += std::to_string(i + 1) + " " + o.settings[i] + "\n";
  write_file(o.files.out_dir + "/converge_settings.txt", names);
}

}  // namespace

std::vector<std::string> default_settings() {
  return {"iterations=10",         "iterations=20",         "iterations=40",
          "iterations=80",         "iterations=20,sor=1.0", "iterations=40,sor=1.0",
          "iterations=80,sor=1.0", "solver=exact",          "solver=exact,step=0.5ms"};
}

int run_convergence_study(const ConvergeOptions& o, std::ostream& out) {
  if (o.settings.empty()) throw Error("stride converge: no settings to compare");
  const int reference = o.reference < 0 ? static_cast<int>(o.settings.size()) - 1 : o.reference;
  std::vector<EnsembleRequest> requests;
  for (const std::string& setting : o.settings)
    requests.push_back(
        {o.scene,
         setting == "scene" ? sim::PhysicsAttributes{} : sim::parse_physics_setting(setting),
         o.spec, o.seconds});
  const auto results = run_ensembles(requests, o.jobs);
  std::vector<EnsembleSummary> summaries;
  for (const auto& r : results) summaries.push_back(summarize_ensemble(r));

  out << o.scene << ": " << o.spec.members << " starts (seeds " << o.spec.first_seed << "-"
      << o.spec.first_seed + o.spec.members - 1 << ", heading ±" << o.spec.heading_spread
      << " rad, position ±" << o.spec.position_spread << " m), " << o.seconds
      << " s each; reference " << o.settings[reference] << ", agreement: lost within "
      << o.tolerance.lost << ", kept walks' mean distance and steps within "
      << fixed(100 * o.tolerance.distance, 1) << " %\n";
  std::vector<std::string> header{"setting"};
  for (const std::string& h : summary_header()) header.push_back(h);
  header.push_back("agrees");
  std::vector<std::vector<std::string>> rows;
  std::string why;
  for (std::size_t i = 0; i < summaries.size(); ++i) {
    std::vector<std::string> row{o.settings[i]};
    for (std::string& c : summary_cells(summaries[i])) row.push_back(std::move(c));
    row.push_back(agrees(summaries[i], summaries[reference], o.tolerance, why) ? "yes"
                                                                               : "no: " + why);
    rows.push_back(std::move(row));
  }
  experiments::print_table(out, header, rows);
  const int best = cheapest_agreeing(summaries, reference, o.tolerance);
  if (!any_kept(summaries))
    out << "no setting kept the walk upright in " << o.spec.members
        << " starts: every walk fell or tipped, so there is no distance to compare\n";
  else if (best < 0)
    out << "no setting agrees with the reference\n";
  else
    out << "cheapest agreeing setting: " << o.settings[best] << " ("
        << fixed(summaries[best].real_time_factor, 2) << "x real time, "
        << fixed(summaries[best].wall_per_member, 1) << " s per walk)\n";
  write_files(o, summaries);
  return best;
}

}  // namespace stride::ensemble
