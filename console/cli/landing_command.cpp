// `stride landing [--scene f] [--speed m/s] [--depth m] [--seconds S] [--csv f]`: thesis Ch. 6 in
// simulation, the landing foot under position control and under the impedance law (Eq. 6.17).
#include <iomanip>
#include <ostream>

#include "console/cli/arguments.hpp"
#include "console/cli/exit_codes.hpp"
#include "console/cli/subcommand.hpp"
#include "console/experiments/landing_impact_study.hpp"
#include "console/output/output_paths.hpp"
#include "console/plot/gnuplot_plot.hpp"
#include "console/session/headless_run.hpp"
#include "robot/core/data_dir.hpp"
#include "robot/core/error.hpp"

namespace stride::cli {

int landing_main(Args args, std::ostream& out, std::ostream& err) {
  try {
    ArgumentReader a(args, "landing");
    experiments::LandingOptions o;
    o.scene = a.has("--scene") ? a.text("--scene") : data_file("scenes/landing/landing_nao.xml");
    o.speed = a.number_or("--speed", o.speed);
    o.depth = a.number_or("--depth", o.depth);
    o.duration = console::checked_run_seconds(a.number_or("--seconds", o.duration),
                                              "stride landing: --seconds");
    o.stiffness.z() = a.number_or("--kz", o.stiffness.z());
    o.damping.z() = a.number_or("--bz", o.damping.z());
    const std::string csv = a.text_or("--csv", "");
    a.finish();
    if (!csv.empty()) console::check_output_file("stride landing: --csv", csv);
    plot::Table table{{"t", "position_force", "impedance_force"}};
    out << "landing (Ch. 6): " << o.scene << ", sole planned down at " << o.speed << " m/s to "
        << o.depth * 1000 << " mm below the floor; impedance K_z " << o.stiffness.z()
        << " N/m, B_z " << o.damping.z() << " N s/m\n";
    out << "control     touchdown  impulse (10 ms)  peak 10 ms mean      lift-offs  final force  "
           "max |tau|\n";
    std::vector<experiments::LandingResult> runs;
    for (bool impedance : {false, true}) {
      o.impedance = impedance;
      const auto r = experiments::run_landing(o);
      out << std::left << std::setw(10) << (impedance ? "impedance" : "position") << std::right
          << std::fixed << std::setprecision(3) << std::setw(8) << r.touchdown << " s  "
          << std::setw(9) << r.impulse << " N s  " << std::setprecision(1) << std::setw(7)
          << r.peak_force << " N at " << std::setprecision(0) << std::setw(3) << r.peak_at * 1000
          << " ms  " << std::setw(7) << r.lift_offs << "  " << std::setprecision(1) << std::setw(9)
          << r.final_force << " N  " << std::setprecision(2) << r.max_torque << " N m\n";
      runs.push_back(r);
    }
    if (!csv.empty()) {
      for (size_t i = 0; i < runs[0].trace.size() && i < runs[1].trace.size(); ++i)
        table.add_row({runs[0].trace[i].first, runs[0].trace[i].second, runs[1].trace[i].second});
      plot::write_csv(csv, table);
      out << "wrote " << csv << "\n";
    }
    return 0;
  } catch (const Error& e) {
    return report_error(e, err);
  }
}

}  // namespace stride::cli
