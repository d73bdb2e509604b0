// `stride run <scene> --seconds S [--seed N] [--report out.json] [--log file]`: a headless run.
#include <chrono>
#include <fstream>
#include <optional>
#include <ostream>

#include "console/cli/arguments.hpp"
#include "console/cli/subcommand.hpp"
#include "console/session/sim_session.hpp"
#include "robot/core/error.hpp"
#include "simulator/run_report.hpp"

namespace stride::cli {

int run_main(Args args, std::ostream& out, std::ostream& err) {
  try {
    ArgumentReader a(args, "run");
    const std::string scene = a.positional("scene");
    const double seconds = a.number_or("--seconds", 10.0);
    if (!(seconds >= 0)) throw Error("stride run: --seconds: expected a time >= 0");
    const std::optional<std::uint64_t> seed =
        a.has("--seed") ? std::optional<std::uint64_t>(a.unsigned_integer("--seed")) : std::nullopt;
    const std::string report = a.text_or("--report", "");

    const std::string log = a.text_or("--log", "");
    a.finish();

    console::SimSession session(scene, seed);
    auto& sim = session.simulation();
    if (!log.empty()) {
      if (!session.runtime(0)) throw Error("stride run: --log: robot 0 has no <controller>");
      session.runtime(0)->start_log(log);
    }
    const auto t0 = std::chrono::steady_clock::now();
    sim.run_for(seconds);
    sim::RunTiming timing;
    timing.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    out << sim::run_report_text(sim, timing);
    if (!report.empty()) {
      std::ofstream f(report);
      if (!f) throw Error("stride run: --report: cannot write '" + report + "'");
      f << sim::run_report_json(sim, timing);
    }
    return 0;
  } catch (const Error& e) {
    err << e.what() << "\n";
    return 1;
  }
}

}  // namespace stride::cli
