#pragma once
// One progress line for every command that runs longer than a few seconds (experiments, sweeps,
// long runs, swing-leg studies): done/total, failures, elapsed, rate and ETA. On a terminal the
// line is redrawn in place; otherwise a plain line is written every few seconds and at the end,
// so logs of CI jobs and batch runs show how far a study got. Thread-safe: workers may report.
#include <chrono>
#include <cstddef>
#include <functional>
#include <iosfwd>
#include <mutex>
#include <optional>
#include <string>

namespace stride::console {

// Terminal: one line redrawn in place ("\r", erase to end). Plain: a line every `plain_every`
// seconds and a last one. Quiet: nothing.
enum class ProgressMode { Terminal, Plain, Quiet };

struct ProgressSettings {
  ProgressMode mode = ProgressMode::Plain;
  double plain_every = 10.0;  // [s] between plain lines
};

// From STRIDE_PROGRESS ("tty", "plain", "plain:<seconds>", "off"; the value as given to the
// environment) or, when that is empty, from whether stderr is a terminal. A bad value is an
// Error naming the variable.
ProgressSettings progress_settings_from(const char* env_value, bool stderr_is_terminal);
// The same for this process's environment and stderr.
ProgressSettings progress_settings();

// What a line says, apart from its clock: the caller's label and unit.
struct ProgressSpec {
  std::string label;               // "posture", "sweep gains.sweep", "run"
  double total = 0;                // in `unit`; 0: unknown (no percentage, no ETA)
  std::string unit = "";           // "walks", "s" (simulated), ...
  int decimals = 0;                // of done/total: 0 for counts, 1 for simulated seconds
  std::string failure = "failed";  // the word for failed items ("lost", "failed")
  bool rate_as_speedup = false;    // rate as "N.Nx real time" (a simulated-time unit)
};

// The progress state a line is drawn from.
struct ProgressCounts {
  double done = 0;
  std::size_t failed = 0;
  double elapsed = 0;  // [s] wall time
};

// The line, e.g. "posture: 12/90 walks (13 %), 1 failed, 34 s, 0.35 walks/s, ETA 3 min 42 s".
std::string format_progress(const ProgressSpec& spec, const ProgressCounts& counts);
// "7 s", "3 min 05 s", "2 h 04 min"; negative or unknown as "?".
std::string format_duration(double seconds);

class ProgressLine {
 public:
  using Clock = std::function<double()>;  // monotonic seconds
  ProgressLine(std::ostream& out, ProgressSpec spec, ProgressSettings settings, Clock clock = {});
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  ~ProgressLine();  // finishes the line if finish() was not called

  // `amount` more done (items or simulated seconds); `failed` of them failed.
  void advance(double amount = 1, std::size_t failed = 0);
  // Sets the done amount outright (a run's simulated time).
  void set_done(double done, std::size_t failed = 0);
  // Redraws if one is due (long items with no advance in between).
  void tick();
  // Erases the terminal line before other output; the next advance draws it again.
  void clear();
  // The last line, if any line was drawn (a short command prints none); ends the terminal line.
  void finish();

  ProgressCounts counts() const;

 private:
  void draw_if_due(bool force);
  double now() const;

  mutable std::mutex mutex_;
  std::ostream& out_;
  ProgressSpec spec_;
  ProgressSettings settings_;
  Clock clock_;
  double start_ = 0;
  ProgressCounts counts_;
  std::optional<double> last_draw_;
  bool drawn_before_clear_ = false;
  bool finished_ = false;
};

}  // namespace stride::console
