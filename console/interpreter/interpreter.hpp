#pragma once
// Executes parsed console commands. Robot-side commands act on the current RobotTarget: the local
// simulation's selected robot, or a robot reached with `connect`; simulation-only commands act on
// the local simulation and say so in one line while a remote robot is current. The interpreter
// keeps only console-side state (targets, watches, plot recording, realtime pacing, the script
// stack), so the same commands and scripts work locally and remotely.
#include <atomic>
#include <chrono>
#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "console/interpreter/command_parser.hpp"
#include "console/interpreter/sweep_command.hpp"
#include "console/interpreter/tune_command.hpp"
#include "console/plot/gnuplot_plot.hpp"
#include "console/target/local_target.hpp"
#include "console/target/remote_target.hpp"

namespace stride::view {
class ViewBridge;
}

namespace stride::console {

class Interpreter {
 public:
  Interpreter(LocalTarget& local, std::ostream& out);
  ~Interpreter();

  // One line; on failure throws stride::Error with a one-line message (nothing half-applied).
  void execute(std::string_view line);
  // Like execute, but prints "error: ..." and returns false instead of throwing (REPL use).
  bool execute_reporting(std::string_view line);
  // Every line of a script in order; the first failure throws "file:line: message".
  void run_script(const std::string& path);
  // Commands separated by ';' (for `stride -c`); the first failure throws "-c:N: message".
  void run_inline(std::string_view commands);

  // Writes a pending plot (also done by `plot stop` and the destructor).
  void finish();
  bool quit_requested() const { return quit_; }
  // Interactive sessions: `run` without a duration runs in the background (the REPL calls
  // run_slice() between reading lines, so every command applies between frames); blocking runs
  // pause when *interrupt becomes true (Ctrl-C).
  void set_interactive(std::atomic<bool>* interrupt) { interrupt_ = interrupt; }
  bool running() const { return running_; }
  // Steps the background run for up to `budget` of wall time. Returns how long the REPL may wait
  // for input before the next step is due (zero: at once; realtime runs wait for the clock).
  std::chrono::steady_clock::duration run_slice(std::chrono::steady_clock::duration budget);
  // Ctrl-C during a background run.
  void pause_run();
  // `run <seconds>` as a background run that pauses itself after `seconds` of the target's time
  // (the view's pages: one page's run never holds another's commands).
  void run_for(double seconds);
  // `restart`: the target's scenario from its start, running again in the REPL.
  void restart();
  // The robot commands act on now: a connected remote robot, or the local simulation's.
  RobotTarget& target();
  LocalTarget& local() { return local_; }
  // What `robot` takes: the scene's robots and the connections.
  std::vector<std::string> robot_names();
  // Call while waiting for input: keeps connections alive, serves `serve` clients when paused.
  void idle();
  bool realtime() const { return realtime_; }
  // A person at a terminal gets real time by default; scripts and pipes run as fast as possible.
  void set_realtime(bool on) { realtime_ = on; }
  // Called after every step of an advance, before watches (the view samples and sends from it).
  void set_step_hook(std::function<void()> hook) { step_hook_ = std::move(hook); }
  // Keys read after every step besides watch/plot/until ones (a remote robot streams them).
  void set_observed_extra(std::vector<std::string> keys) { observed_extra_ = std::move(keys); }

 private:
  void dispatch(const Command& c);
  void robot_command(const Command& c);
  // The local simulation for `command`; one line saying why not while a remote robot is current.
  SimulationTarget& simulation(const std::string& command);
  // A key's value: sweep.* from the last sweep, log.* from the console's log player, else target.
  std::string value(const std::string& key);
  void connect(const std::vector<std::string>& a);
  void disconnect(const std::vector<std::string>& a);
  void serve(const std::vector<std::string>& a);
  void view(const std::vector<std::string>& a);
  void poll_view();  // the view's pages: their commands run here, between the console's
  void lost_connection(const std::string& why);
  void load(const std::string& path);
  std::string resolve(const std::string& path) const;  // relative to the running script first
  // Advances up to `steps`; watches, plots, debug output, realtime and interrupts apply. `until`
  // (may be null) stops the run when it returns true; `until_keys` are the keys it reads (a
  // remote robot streams them). Returns true if `until` became true.
  bool advance(std::uint64_t steps, const std::function<bool()>& until,
               const std::vector<std::string>& until_keys = {});
  // The keys read after every step (watch, plot, until), for the target to stream.
  void observe(const std::vector<std::string>& until_keys);
  // Per step: watches, plots, debug output. False when a debug request asks to pause.
  bool after_step();
  void print_watches();
  void record_plot_row();
  void start_pacing();  // realtime pacing counts from now
  std::chrono::steady_clock::time_point step_due();
  void refuse_while_running(const std::string& command) const;
  void start_background_run();                // running_ from now, paced from now
  void report_dropped(std::uint64_t before);  // stream samples lost since `before`
  std::uint64_t steps_for(double seconds) const;

  void help(const std::vector<std::string>& a);
  void run(const std::vector<std::string>& a);
  void set(const std::vector<std::string>& a);
  void move_robot(const std::vector<std::string>& a);
  void get(const std::vector<std::string>& a);
  void module_request(const std::vector<std::string>& a);
  void debug_request(const std::vector<std::string>& a);
  void watch(const std::vector<std::string>& a);
  void plot(const std::vector<std::string>& a);
  void log(const std::vector<std::string>& a);
  void report(const std::vector<std::string>& a);
  void video(const std::vector<std::string>& a);
  void expect(const std::vector<std::string>& a);
  void wait_until(const std::vector<std::string>& a);
  void note_parameters(const std::string& module);  // "": every module

  LocalTarget& local_;
  std::map<std::string, std::unique_ptr<RemoteTarget>> remotes_;  // by host:port
  RemoteTarget* remote_ = nullptr;     // current, or null: the local simulation
  RobotTarget* log_target_ = nullptr;  // where log_path_ was recorded (null: a file here)
  std::ostream& out_;
  std::atomic<bool>* interrupt_ = nullptr;
  bool quit_ = false;
  bool realtime_ = false;
  bool running_ = false;  // a background run (interactive `run` without seconds, or run_for)
  std::optional<std::uint64_t> run_steps_left_;  // run_for's steps still to go
  std::vector<std::string> script_stack_;

  std::vector<std::string> watch_keys_;
  std::uint64_t watch_every_ = 1;
  std::uint64_t steps_since_watch_ = 0;

  std::vector<std::string> plot_keys_;
  std::string plot_file_;
  std::string log_path_;  // log being recorded or last recorded/loaded, for `log save`
  plot::Table plot_table_;
  std::chrono::steady_clock::time_point plot_live_;  // the last live line of a recording plot

  std::chrono::steady_clock::time_point pace_start_;  // realtime: wall time of step 0
  std::uint64_t paced_steps_ = 0;                     // steps since pace_start_
  SweepCommand sweep_;
  TuneCommand tune_;
  std::function<void()> step_hook_;
  std::vector<std::string> observed_extra_;
  std::unique_ptr<view::ViewBridge> view_;  // `view`: last, so it goes first
};

}  // namespace stride::console
