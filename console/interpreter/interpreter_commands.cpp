// The commands of Interpreter that need more than one line: help, get, mr, dr, watch, plot, log,
// report, video, expect, wait until.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

#include "console/interpreter/command_table.hpp"
#include "console/interpreter/console_plot.hpp"
#include "console/interpreter/interpreter.hpp"
#include "console/interpreter/key_units.hpp"
#include "console/interpreter/values.hpp"
#include "robot/core/error.hpp"
#include "robot/core/output_file.hpp"
#include "robot/runtime/world_pose.hpp"
#include "simulator/render/movie_file.hpp"
#include "simulator/render/snapshot.hpp"

namespace stride::console {

void Interpreter::help(const std::vector<std::string>& a) {
  out_ << help_text(a.empty() ? "" : a[0]);
}

void Interpreter::get(const std::vector<std::string>& a) {
  if (a.size() == 2) {
    const std::string text = describe_text(target().type_of(a[0]));
    out_ << text << (text.ends_with('\n') ? "" : "\n");
    return;
  }
  out_ << value(a[0]) << "\n";
}

void Interpreter::module_request(const std::vector<std::string>& a) {
  RobotTarget& robot = target();
  auto line = [&](const std::string& rep) {
    const std::string by = robot.provider_of(rep);
    out_ << rep << ": " << (by.empty() ? "(built in)" : by);
    const auto options = robot.providers_available(rep);
    if (!options.empty()) {
      out_ << "  available:";
      for (const auto& m : options) out_ << " " << m;
    }
    out_ << "\n";
  };
  if (a[0] == "?") {
    for (const auto& rep : robot.representations()) line(rep);
    return;
  }
  if (a.size() == 1 || a[1] == "?") return line(a[0]);
  robot.swap_provider(a[0], a[1]);
  out_ << a[0] << " <- " << robot.provider_of(a[0]) << "\n";
}

void Interpreter::debug_request(const std::vector<std::string>& a) {
  if (a[0] == "?") {
    const auto all = target().debug_requests();
    if (all.empty()) out_ << "(no debug requests)\n";
    for (const auto& [name, state] : all) out_ << name << " " << debug_switch_name(state) << "\n";
    return;
  }
  target().set_debug_request(a[0], parse_debug_switch(a[1]));
}

void Interpreter::watch(const std::vector<std::string>& a) {
  if (a.size() == 1 && a[0] == "off") {
    watch_keys_.clear();
    return;
  }
  std::vector<std::string> keys(a.begin(), a.end());
  std::uint64_t every = 1;
  if (a.size() >= 2 && a[a.size() - 2] == "every") {
    every = static_cast<std::uint64_t>(parse_integer(a.back(), "every", 1, 1000000000));
    keys.resize(keys.size() - 2);
  }
  for (const auto& k : keys) value(k);  // unknown keys fail now, not while running
  watch_keys_ = std::move(keys);
  // Control frames, locally as on a robot: a simulation steps its physics several times a frame.
  watch_every_ = every * (remote_ ? 1 : local_.steps_per_frame());
  steps_since_watch_ = 0;
}

void Interpreter::plot(const std::vector<std::string>& a) {
  if (a.size() == 1 && (a[0] == "stop" || a[0] == "off")) {
    if (plot_keys_.empty()) throw Error("plot: nothing is being recorded");
    finish();
    return;
  }
  std::vector<std::string> keys(a.begin(), a.end());
  std::string file = "plot.csv";
  if (a.size() >= 2 && a[a.size() - 2] == "to") {
    file = a.back();
    keys.resize(keys.size() - 2);
  }
  for (const auto& k : keys) value(k);
  finish();
  plot_keys_ = std::move(keys);
  plot_file_ = file;
  plot_table_ = plot::Table{};
  plot_live_ = {};
  plot_table_.columns.push_back("t");
  for (const auto& k : plot_keys_) plot_table_.columns.push_back(k);
  out_ << "recording " << plot_keys_.size() << " value(s) to " << plot_file_
       << " while running (plot stop writes it)\n";
}

void Interpreter::finish() {
  if (plot_keys_.empty()) return;
  const std::vector<std::string> keys = std::move(plot_keys_);
  plot_keys_.clear();
  plot::write_csv(plot_file_, plot_table_);
  out_ << "wrote " << plot_table_.rows.size() << " rows to " << plot_file_ << "\n";
  if (plot::png_terminal().empty()) {
    out_ << "gnuplot not found: no PNG\n";
    return;
  }
  plot::PlotSpec spec;
  spec.x_column = "t";
  spec.key = "outside below";  // long key names take rows, not the graph's width
  std::vector<std::string> units;
  // One panel per unit, in the order the keys first name them: no axis mixes units.
  for (const auto& k : keys) {
    const std::string unit = unit_of_key(target(), k);
    units.push_back(unit);
    const std::string label = "[" + (unit.empty() ? std::string("-") : unit) + "]";
    auto panel = std::find_if(spec.panels.begin(), spec.panels.end(),
                              [&](const plot::Panel& p) { return p.y_label == label; });
    if (panel == spec.panels.end())
      panel = spec.panels.insert(spec.panels.end(), {label, {}, {}, ""});
    panel->series.push_back({k, legend_label(k), ""});
  }
  spec.title = plot_file_;
  spec.x_label = "t [s]";
  const auto dot = plot_file_.rfind('.');
  const std::string base = dot == std::string::npos ? plot_file_ : plot_file_.substr(0, dot);
  spec.png_path = base + ".png";
  // What is drawn: angles unwrapped, at most ~4000 rows (the CSV above keeps every row).
  plot::Table drawn = std::move(plot_table_);
  unwrap_angles(drawn, units);
  spec.csv_path = base + ".drawn.csv";
  plot::write_csv(spec.csv_path, decimated(drawn, 4000));
  plot::render_png(spec);
  std::remove(spec.csv_path.c_str());
  out_ << "wrote " << spec.png_path << "\n";
}

void Interpreter::log(const std::vector<std::string>& a) {
  const std::string& what = a[0];
  if (what == "start") {
    target().log_start(a[1]);
    log_path_ = a[1];
    log_target_ = &target();
    out_ << "logging to " << a[1] << "\n";
  } else if (what == "stop") {
    target().log_stop();
  } else if (what == "load") {  // the console's own log player, whatever the target
    out_ << a[1] << ": " << local_.log_load(resolve(a[1])) << "\n";
    log_path_ = resolve(a[1]);
    log_target_ = nullptr;
  } else if (what == "save") {
    if (log_path_.empty()) throw Error("log save: no log recorded or loaded yet");
    out_ << (log_target_ ? *log_target_ : local_).log_save(log_path_, a[1]) << "\n";
  } else if (what == "goto") {
    const auto skipped =
        simulation("log goto")
            .log_goto(static_cast<std::size_t>(parse_integer(a[1], "frame", 0, 1000000000000LL)));
    out_ << "frame " << a[1] << " on the blackboard";
    if (!skipped.empty()) out_ << " (" << skipped.size() << " representation(s) skipped)";
    out_ << (local_.shown_pose_logged()
                 ? ", the robot where the log puts it (robot.torso.*, snapshot)\n"
                 : "; this log holds no world pose (a robot's, or recorded before " +
                       std::string(kWorldPoseSince) +
                       "): snapshot stands the robot on its lowest point, tilted as its IMU "
                       "measured\n");
  } else if (what == "export") {
    std::vector<std::string> keys;  // the keys `get` takes: representation:X.path, or X.path
    for (auto k = a.begin() + 2; k != a.end(); ++k) {
      if (k->starts_with("module:"))
        throw Error("log export: " + *k + ": a log holds representations, not parameters");
      keys.push_back(k->starts_with("representation:") ? k->substr(15) : *k);
    }
    local_.log_export(a[1], keys);
    out_ << "wrote " << a[1] << "\n";
  } else if (what == "info") {
    for (const auto& line : local_.log_info()) out_ << line << "\n";
  } else if (what == "replay") {
    // The console's own log player: it replays through this console's simulated controllers.
    if (!local_.loaded())
      throw Error(
          "log replay: runs the log through a simulated NAO's controllers here, with the providers "
          "and parameters the log recorded: load a scene first (e.g. load "
          "nao_stand_controlled.xml)");
    const ReplaySummary r = local_.log_replay();
    out_ << "replayed " << r.frames << " frames, compared " << r.compared
         << " representations: " << r.mismatch_count << " mismatch(es)";
    if (r.stopped) out_ << " (stopped before damaged frame " << r.stopped_at << ")";
    out_ << "\n";
    for (const auto& m : r.mismatches) out_ << "  " << m << "\n";
    if (r.first_frame != 0 && r.mismatch_count > 0)
      out_ << "note: the log starts at controller frame " << r.first_frame
           << ", not at the controller's start: the modules' state before it is not in the log, so "
              "the replay cannot match it (stride robot --log records from the first frame)\n";
  }
}

void Interpreter::report(const std::vector<std::string>& a) {
  if (a.empty()) {
    out_ << target().report_text();
    return;
  }
  write_file(a[0], target().report_json());
  out_ << "wrote " << a[0] << "\n";
}

void Interpreter::video(const std::vector<std::string>& a) {
  if (a[0] == "stop") {
    out_ << "video: " << simulation("video").video_stop() << " frames\n";
    return;
  }
  const VideoStart v = parse_video_start(a);
  SimulationTarget& sim = simulation("video");
  const double steps = 1.0 / (static_cast<double>(v.fps) * local_.step_seconds());
  sim.video_start(v.dir, v.view, std::max<std::uint64_t>(1, std::llround(steps)));
  if (render::is_movie_path(v.dir))
    out_ << "video: movie " << v.dir << " at " << v.fps << " fps while running\n";
  else
    out_ << "video: frames to " << v.dir << "/ at " << v.fps << " fps while running\n";
}

namespace {
double tolerance_of(const std::vector<std::string>& a, std::size_t at, Op op) {
  if (a.size() > at) return parse_number(a[at], "tolerance");
  return op == Op::Near ? 1e-3 : 1e-12;  // ~= without tolerance: millimetre/milliradian level
}
}  // namespace

void Interpreter::expect(const std::vector<std::string>& a) {
  const Op op = parse_op(a[1]);
  const std::string actual = value(a[0]);
  if (!compare(actual, op, a[2], tolerance_of(a, 3, op)))
    throw Error("expect " + a[0] + " " + a[1] + " " + a[2] + " failed: actual " + actual);
  out_ << "ok " << a[0] << " = " << actual << "\n";
}

void Interpreter::wait_until(const std::vector<std::string>& a) {
  const Op op = parse_op(a[2]);
  const double timeout = a.size() == 6 ? parse_number(a[5], "timeout") : 10.0;
  const double tolerance = op == Op::Near ? 1e-3 : 1e-12;
  auto holds = [&] { return compare(value(a[1]), op, a[3], tolerance); };
  if (holds() || advance(steps_for(timeout), holds, {a[1]})) {
    out_ << "reached at t=" << target().time_text() << "\n";
    return;
  }
  const std::string limit = a.size() == 6 ? a[5] : "10";
  throw Error("wait: " + a[1] + " " + a[2] + " " + a[3] + " not reached within " + limit +
              " s (value " + value(a[1]) + ")");
}

}  // namespace stride::console
