// `stride identify <log> [--robot <urdf>] [--params gain,torque,gyro_bias] [--joints a,b]
// [--out robot-id.xml] [--csv traces.csv] [--jobs N] [--iterations N]`: fits a robot's servo
// parameters and gyro bias to its log (console/identify/), writes the robot override file.
#include <ostream>

#include "console/cli/arguments.hpp"
#include "console/cli/exit_codes.hpp"
#include "console/cli/subcommand.hpp"
#include "console/identify/identify_output.hpp"
#include "robot/core/error.hpp"
#include "robot/core/output_file.hpp"

namespace stride::cli {

std::string_view identify_summary() {
  return "identify <log> [--robot <urdf>] [--params gain,torque,gyro_bias] [--joints "
         "LKneePitch,...] [--out robot-id.xml] [--csv traces.csv] [--jobs N] [--iterations N]: "
         "fits the leg servos' gain and torque limit and the gyro bias to a "
         "robot's log (`stride robot --log` of an excitation motion, docs/identify.md) by "
         "replaying its commands in simulation; writes a robot override file a scene includes";
}

int identify_main(Args args, std::ostream& out, std::ostream& err) {
  try {
    ArgumentReader a(args, "identify");
    identify::IdentifyRequest r;
    r.choice = identify::parse_param_list(a.text_or("--params", "gain,gyro_bias"));
    r.joints = identify::parse_joint_list(a.text_or("--joints", ""));
    if (a.has("--jobs")) {
      const std::uint64_t n = a.unsigned_integer("--jobs");
      if (n < 1 || n > 1024) throw UsageError("stride identify: --jobs: expected 1..1024");
      r.jobs = static_cast<int>(n);
    }
    if (a.has("--iterations")) {
      const std::uint64_t n = a.unsigned_integer("--iterations");
      if (n > 100) throw UsageError("stride identify: --iterations: expected 0..100");
      r.iterations = static_cast<int>(n);
    }
    const std::string robot = a.text_or("--robot", "");
    const std::string out_path = a.text_or("--out", "robot-id.xml");
    const std::string csv = a.text_or("--csv", "");
    const std::string log_path = a.positional("log file");
    a.finish();
    const auto files = identify::robot_files(robot);
    const auto log = identify::read_identify_log(log_path);
    out << log_path << ": " << log.frames.size() << " frames of " << log.period * 1e3
        << " ms, robot " << (log.held ? "held in the air" : "standing") << std::endl;
    const auto result = identify::identify(log, files, r);
    for (const auto& line : identify::report_lines(result)) out << line << "\n";
    // Both outputs are complete before either replaces a file: nothing is written half.
    const std::string text = identify::override_text(result, log_path);
    const std::string traces = csv.empty() ? "" : identify::traces_csv(log, result);
    write_file(out_path, text);
    out << "wrote " << out_path << "\n";
    if (!csv.empty()) {
      write_file(csv, traces);
      out << "wrote " << csv << "\n";
    }
    return 0;
  } catch (const Error& e) {
    return report_error(e, err);
  }
}

}  // namespace stride::cli
