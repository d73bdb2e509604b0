#include "console/ensemble/ensemble_report.hpp"

#include <ostream>

#include "console/ensemble/ensemble_summary.hpp"
#include "console/experiments/experiment_options.hpp"

namespace stride::ensemble {

using experiments::fixed;

void print_ensemble(const EnsembleRequest& r, const std::vector<MemberOutcome>& members,
                    std::ostream& out) {
  out << r.scene << ": ensemble of " << members.size() << " perturbed starts, " << r.seconds
      << " s each (robot 0)\n";
  std::vector<std::vector<std::string>> rows;
  for (std::size_t k = 0; k < members.size(); ++k) {
    const sim::StartPerturbation p = sim::ensemble_member(r.spec, static_cast<int>(k));
    const sim::WalkMetricsResult& w = members[k].walk;
    std::string outcome = w.fell ? "fell " + fixed(w.fell_at, 2) : "upright";
    if (w.tipped != sim::Tip::None)
      outcome += ", tipped " + std::string(sim::tip_name(w.tipped)) + " " + fixed(w.tipped_at, 2);
    rows.push_back({std::to_string(k + 1), std::to_string(p.seed), fixed(p.heading * 1e3, 2),
                    fixed(p.offset.x() * 1e3, 2), fixed(p.offset.y() * 1e3, 2),
                    std::to_string(w.steps), fixed(w.true_distance, 3), fixed(w.fk_distance, 3),
                    outcome});
  }
  experiments::print_table(out,
                           {"member", "seed", "heading [mrad]", "dx [mm]", "dy [mm]", "steps",
                            "true distance [m]", "fk distance [m]", "outcome"},
                           rows);
  const EnsembleSummary s = summarize_ensemble(members);
  out << "\nspread (mean ± sd [min, max]); distances, steps and feet over the kept walks\n";
  experiments::print_table(out, summary_header(), {summary_cells(s)});
}

}  // namespace stride::ensemble
