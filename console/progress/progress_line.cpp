#include "console/progress/progress_line.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <sstream>
#include <string_view>

#include "console/interpreter/values.hpp"
#include "robot/core/error.hpp"

namespace stride::console {
namespace {

constexpr double kTerminalRedraw = 0.1;  // [s] at most ten redraws a second

std::string fixed(double v, int decimals) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(decimals);
  s << v;
  return s.str();
}

// Two significant figures at least, so 0.35 walks/s and 12 walks/s both read well.
std::string rate_text(double rate) {
  return fixed(rate, rate >= 10 ? 0 : rate >= 1 ? 1 : 2);
}

double steady_seconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

}  // namespace

ProgressSettings progress_settings_from(const char* env_value, bool stderr_is_terminal) {
  const std::string_view v = env_value ? env_value : "";
  if (v.empty()) return {stderr_is_terminal ? ProgressMode::Terminal : ProgressMode::Plain};
  if (v == "tty") return {ProgressMode::Terminal};
  if (v == "off") return {ProgressMode::Quiet};
  if (v == "plain") return {ProgressMode::Plain};
  if (v.starts_with("plain:")) {
    const double every = parse_number(v.substr(6), "STRIDE_PROGRESS=plain:<seconds>");
    if (every <= 0) throw Error("STRIDE_PROGRESS=plain:<seconds>: expected seconds > 0");
    return {ProgressMode::Plain, every};
  }
  throw Error("STRIDE_PROGRESS: expected tty, plain, plain:<seconds> or off, got '" +
              std::string(v.substr(0, 40)) + "'");
}

ProgressSettings progress_settings() {
  return progress_settings_from(std::getenv("STRIDE_PROGRESS"), ::isatty(STDERR_FILENO) == 1);
}

std::string format_duration(double seconds) {
  if (!(seconds >= 0) || !std::isfinite(seconds)) return "?";
  const long long s = std::llround(seconds);
  char text[32];
  if (s < 60)
    std::snprintf(text, sizeof text, "%lld s", s);
  else if (s < 3600)
    std::snprintf(text, sizeof text, "%lld min %02lld s", s / 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%lld h %02lld min", s / 3600, (s % 3600) / 60);
  return text;
}

std::string format_progress(const ProgressSpec& spec, const ProgressCounts& c) {
  std::string line = spec.label + ": " + fixed(c.done, spec.decimals);
  if (spec.total > 0) line += "/" + fixed(spec.total, spec.decimals);
  if (!spec.unit.empty()) line += " " + spec.unit;
  if (spec.total > 0)
    line += " (" + std::to_string(static_cast<int>(std::floor(100 * c.done / spec.total))) + " %)";
  if (c.failed > 0) line += ", " + std::to_string(c.failed) + " " + spec.failure;
  line += ", " + format_duration(c.elapsed);
  const double rate = c.elapsed > 0 ? c.done / c.elapsed : 0;
  if (c.done > 0 && c.elapsed > 0)
    line += spec.rate_as_speedup ? ", " + rate_text(rate) + "x real time"
                                 : ", " + rate_text(rate) + " " +
                                       (spec.unit.empty() ? std::string("") : spec.unit) + "/s";
  if (spec.total > 0 && c.done < spec.total)
    line += ", ETA " + (rate > 0 ? format_duration((spec.total - c.done) / rate) : "?");
  return line;
}

ProgressLine::ProgressLine(std::ostream& out, ProgressSpec spec, ProgressSettings settings,
                           Clock clock)
    : out_(out),
      spec_(std::move(spec)),
      settings_(settings),
      clock_(clock ? std::move(clock) : Clock(steady_seconds)) {
  start_ = clock_();
}

ProgressLine::~ProgressLine() {
  finish();
}

double ProgressLine::now() const {
  return clock_() - start_;
}

void ProgressLine::advance(double amount, std::size_t failed) {
  std::lock_guard lock(mutex_);
  counts_.done += amount;
  counts_.failed += failed;
  draw_if_due(false);
}

void ProgressLine::set_done(double done, std::size_t failed) {
  std::lock_guard lock(mutex_);
  counts_.done = done;
  counts_.failed = failed;
  draw_if_due(false);
}

void ProgressLine::tick() {
  std::lock_guard lock(mutex_);
  draw_if_due(false);
}

void ProgressLine::finish() {
  std::lock_guard lock(mutex_);
  if (finished_) return;
  // A command that never needed a line (shorter than one period) does not get a last one.
  if (last_draw_ || drawn_before_clear_) {
    draw_if_due(true);
    if (settings_.mode == ProgressMode::Terminal) out_ << '\n' << std::flush;
  }
  finished_ = true;
}

void ProgressLine::clear() {
  std::lock_guard lock(mutex_);
  if (finished_ || settings_.mode != ProgressMode::Terminal || !last_draw_) return;
  out_ << "\r\033[K" << std::flush;
  drawn_before_clear_ = true;
  last_draw_.reset();
}

ProgressCounts ProgressLine::counts() const {
  std::lock_guard lock(mutex_);
  ProgressCounts c = counts_;
  c.elapsed = now();
  return c;
}

void ProgressLine::draw_if_due(bool force) {
  if (finished_ || settings_.mode == ProgressMode::Quiet) return;
  counts_.elapsed = now();
  const double every =
      settings_.mode == ProgressMode::Terminal ? kTerminalRedraw : settings_.plain_every;
  // The first plain line waits a whole period: a short command prints only its last line.
  const double since = counts_.elapsed - last_draw_.value_or(0);
  if (!force && since < every) return;
  last_draw_ = counts_.elapsed;
  if (settings_.mode == ProgressMode::Terminal)
    out_ << '\r' << format_progress(spec_, counts_) << "\033[K" << std::flush;
  else
    out_ << format_progress(spec_, counts_) << '\n' << std::flush;
}

}  // namespace stride::console
