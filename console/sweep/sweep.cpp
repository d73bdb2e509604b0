#include "console/sweep/sweep.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <exception>
#include <numeric>
#include <set>

#include "console/sweep/run_keys.hpp"
#include "console/sweep/run_session.hpp"
#include "console/sweep/sweep_compiled.hpp"
#include "robot/core/error.hpp"

namespace stride::sweep {
namespace {

// Errors of a spec element: "file:line: what" when it came from a file.
Error at(const SweepSpec& s, int line, const std::string& what) {
  if (s.file.empty() || line <= 0) return Error("sweep '" + s.name + "': " + what);
  return error_at(s.file, line, what);
}

// The same for an error a run's scene or session raised: its kind (bad input, usage) is kept so
// the command exits with that kind's code.
[[noreturn]] void rethrow_at(const SweepSpec& s, const std::string& prefix, const Error& e) {
  const Error plain = at(s, 0, prefix + e.what());
  if (dynamic_cast<const InputError*>(&e)) throw InputError(plain.what());
  if (dynamic_cast<const UsageError*>(&e)) throw UsageError(plain.what());
  throw plain;
}

void check_time(const SweepSpec& s, const TimePoint& p, int line) {
  static const std::set<std::string> marks = {"start", "end", "walk_start", "walk_end"};
  if (!marks.count(p.mark))
    throw at(s, line, "unknown time mark '" + p.mark + "' (start, end, walk_start, walk_end)");
}

bool walk_mark(const TimePoint& p) {
  return p.mark == "walk_start" || p.mark == "walk_end";
}

class Compiler {
 public:
  Compiler(const SweepSpec& s, const Plan& p, Sweep::Compiled& c, std::vector<RecordColumn>& r)
      : s_(s), plan_(p), c_(c), record_(r) {}

  void compile() {
    check_settings();
    if (s_.until.mark == "end") throw at(s_, 0, "the run's length cannot be relative to its end");
    check_time(s_, s_.until, 0);
    for (const ValueSpec& v : s_.record.values) {
      check_time(s_, v.at, v.line);
      wrap(v.line, [&] { check_key(v.key, false); });
      add_column(v.name, key_is_text(v.key), v.line);
      c_.walk_frame = c_.walk_frame || key_needs_walk_frame(v.key);
    }
    for (const SummarySpec& m : s_.record.summaries) compile_summary(m);
    for (const DerivedSpec& d : s_.record.derived) {
      Expression e = wrap(d.line, [&] { return Expression(d.expression, row_resolver()); });
      const bool text = e.yields_text([&](int slot) { return slot_is_text(slot); });
      c_.derived.push_back(std::move(e));
      add_column(d.name, text, d.line);
    }
    for (const TraceSpec& t : s_.record.traces) compile_trace(t);
  }

 private:
  template <class F>
  auto wrap(int line, F&& f) -> decltype(f()) {
    try {
      return f();
    } catch (const Error& e) {
      throw at(s_, line, e.what());
    }
  }

  void check_settings() {
    const auto check = [&](const std::vector<Setting>& list, int line) {
      for (const Setting& x : list) wrap(line, [&] { check_setting_target(x.target); });
    };
    check(s_.settings, 0);
    for (const Block& b : s_.blocks) {
      check(b.settings, 0);
      for (const Factor& f : b.factors)
        for (const Level& l : f.levels) check(l.settings, f.line);
      for (const Block::Range& r : b.ranges)
        for (const std::string& t : r.targets) wrap(r.line, [&] { check_setting_target(t); });
    }
  }

  void add_column(const std::string& name, bool text, int line) {
    const auto taken = [&](const std::string& n) {
      return n == "run" || n == "status" || n == "reason" ||
             std::find(plan_.columns.begin(), plan_.columns.end(), n) != plan_.columns.end() ||
             std::any_of(record_.begin(), record_.end(),
                         [&](const RecordColumn& r) { return r.name == n; });
    };
    if (name.empty()) throw at(s_, line, "a record column needs a name");
    if (taken(name)) throw at(s_, line, "column '" + name + "' is named twice");
    record_.push_back({name, text});
  }

  int frame_key(const std::string& key, int line, bool for_trace = false) {
    wrap(line, [&] { check_key(key, true); });
    c_.walk_frame = c_.walk_frame || key_needs_walk_frame(key);
    const auto it = std::find(c_.frame_keys.begin(), c_.frame_keys.end(), key);
    const auto k = static_cast<std::size_t>(it - c_.frame_keys.begin());
    if (it == c_.frame_keys.end()) {
      c_.frame_keys.push_back(key);
      c_.trace_only.push_back(true);
    }
    c_.trace_only[k] = c_.trace_only[k] && for_trace;
    return static_cast<int>(k);
  }

  void compile_summary(const SummarySpec& m) {
    check_time(s_, m.from, m.line);
    check_time(s_, m.to, m.line);
    c_.walk_frame = c_.walk_frame || walk_mark(m.from) || walk_mark(m.to);
    Sweep::Compiled::Summary out;
    out.key = frame_key(m.key, m.line);
    if (!m.until.empty())
      out.until = wrap(m.line, [&] {
        return Expression(m.until,
                          [&](std::string_view n) { return frame_key(std::string(n), m.line); });
      });
    c_.summaries.push_back(std::move(out));
    add_column(m.name, false, m.line);
  }

  void compile_trace(const TraceSpec& t) {
    check_time(s_, t.from, t.line);
    c_.walk_frame = c_.walk_frame || walk_mark(t.from);
    Sweep::Compiled::Trace out;
    if (!t.where.empty())
      out.where = wrap(t.line, [&] { return Expression(t.where, plan_resolver()); });
    for (const auto& [name, key] : t.columns) out.keys.push_back(frame_key(key, t.line, true));
    c_.traces.push_back(std::move(out));
  }

  Expression::Resolver plan_resolver() const {
    return [this](std::string_view n) -> int {
      const auto it = std::find(plan_.columns.begin(), plan_.columns.end(), n);
      if (it == plan_.columns.end())
        throw Error("unknown column '" + std::string(n) + "' (the plan's: " + list(plan_.columns) +
                    ")");
      return static_cast<int>(it - plan_.columns.begin());
    };
  }
  // Plan columns, then the record columns named so far.
  Expression::Resolver row_resolver() const {
    return [this](std::string_view n) -> int {
      for (std::size_t i = 0; i < record_.size(); ++i)
        if (record_[i].name == n) return static_cast<int>(plan_.columns.size() + i);
      const auto it = std::find(plan_.columns.begin(), plan_.columns.end(), n);
      if (it != plan_.columns.end()) return static_cast<int>(it - plan_.columns.begin());
      std::vector<std::string> names = plan_.columns;
      for (const RecordColumn& r : record_) names.push_back(r.name);
      throw Error("unknown column '" + std::string(n) + "' (known so far: " + list(names) + ")");
    };
  }
  bool slot_is_text(int slot) const {
    const auto n = static_cast<std::size_t>(slot);
    return n >= plan_.columns.size() && record_[n - plan_.columns.size()].text;
  }
  static std::string list(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
  }

  const SweepSpec& s_;
  const Plan& plan_;
  Sweep::Compiled& c_;
  std::vector<RecordColumn>& record_;
};

// Loads each scene of `runs` once, with the settings of the first run that uses it, and binds
// every key. A scene that does not load is noted, not thrown, while another one loads: its runs
// become failed rows saying why, as an overnight sweep over robot variants needs. A key that
// does not bind is a mistake in the sweep file and throws.
std::vector<std::string> check_scenes(const Sweep& sweep, const Sweep::Compiled& c,
                                      const std::vector<std::size_t>& runs) {
  const SweepSpec& s = sweep.spec();
  std::set<std::string> seen;
  std::vector<std::string> unloadable;
  std::exception_ptr first_load_error;  // kept whole: its kind (bad input, usage) sets the exit
  std::string first_prefix;
  bool loaded = false;
  for (std::size_t i : runs) {
    const RunPlan& run = sweep.plan().runs.at(i);
    const std::string scene = scene_path_of(s, run);
    if (!seen.insert(scene).second) continue;
    std::unique_ptr<console::SimSession> session;
    try {
      session = build_run_session(s, run);
    } catch (const Error& e) {
      const std::string prefix = "run " + std::to_string(run.id) + ": ";
      unloadable.push_back(prefix + e.what());
      if (!first_load_error) {
        first_load_error = std::current_exception();
        first_prefix = prefix;
      }
      continue;
    }
    try {
      if (session->simulation().robot_count() == 0) throw Error(scene + ": the scene has no robot");
      std::optional<console::WalkFrameObserver> walk;
      if (c.walk_frame) walk.emplace(*session);
      FrameKeys keys(*session, walk ? &*walk : nullptr, c.frame_keys);
      loaded = true;
    } catch (const Error& e) {
      rethrow_at(s, "run " + std::to_string(run.id) + ": ", e);
    }
  }
  if (!loaded && first_load_error) try {
      std::rethrow_exception(first_load_error);
    } catch (const Error& e) {
      rethrow_at(s, first_prefix, e);
    }
  return unloadable;
}

}  // namespace

std::vector<Cell> plan_cells(const RunPlan& run) {
  std::vector<Cell> out;
  for (const std::string& text : run.cells) {
    double v = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (!text.empty() && r.ec == std::errc() && r.ptr == text.data() + text.size())
      out.emplace_back(v);
    else
      out.emplace_back(text);
  }
  return out;
}

Cell cell_value(const std::string& text, bool text_column) {
  if (text_column) return text;
  double v = std::numeric_limits<double>::quiet_NaN();
  std::from_chars(text.data(), text.data() + text.size(), v);
  return v;
}

Sweep::Sweep(SweepSpec spec, bool scenes) : spec_(std::move(spec)), compiled_(new Compiled) {
  plan_ = expand(spec_);
  Compiler(spec_, plan_, *compiled_, record_).compile();
  if (!scenes) return;
  std::vector<std::size_t> all(plan_.runs.size());
  std::iota(all.begin(), all.end(), 0);
  check_scenes(all);
}

const std::vector<std::string>& Sweep::check_scenes(const std::vector<std::size_t>& runs) {
  unloadable_ = stride::sweep::check_scenes(*this, *compiled_, runs);
  return unloadable_;
}

Sweep::~Sweep() = default;
Sweep::Sweep(Sweep&&) noexcept = default;

std::vector<std::string> Sweep::csv_header() const {
  std::vector<std::string> h{"run"};
  h.insert(h.end(), plan_.columns.begin(), plan_.columns.end());
  h.push_back("status");
  for (const RecordColumn& r : record_) h.push_back(r.name);
  h.push_back("reason");
  return h;
}

std::vector<std::string> Sweep::csv_cells(const RunRow& row) const {
  const RunPlan& plan = plan_.runs.at(static_cast<std::size_t>(row.run));
  std::vector<std::string> cells{std::to_string(row.run)};
  cells.insert(cells.end(), plan.cells.begin(), plan.cells.end());
  cells.push_back(row.ok ? "ok" : "failed");
  if (row.ok)
    cells.insert(cells.end(), row.cells.begin(), row.cells.end());
  else
    cells.resize(cells.size() + record_.size());
  cells.push_back(row.reason);
  return cells;
}

bool Sweep::column_is_text(const std::string& name) const {
  if (name == "status" || name == "reason" || name == "scene") return true;
  for (const RecordColumn& r : record_)
    if (r.name == name) return r.text;
  return false;
}

RunRow Sweep::run(std::size_t index) const {
  const auto t0 = std::chrono::steady_clock::now();
  RunRow row;
  const RunPlan& plan = plan_.runs.at(index);
  row.run = plan.id;
  try {
    row.cells = execute_run(*this, *compiled_, plan, row.trace_csv);
    row.ok = true;
  } catch (const std::exception& e) {
    row.ok = false;
    row.cells.clear();
    row.trace_csv.clear();
    row.reason = e.what();
    std::replace(row.reason.begin(), row.reason.end(), '\n', ' ');
  }
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return row;
}

}  // namespace stride::sweep
