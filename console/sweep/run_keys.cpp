#include "console/sweep/run_keys.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <type_traits>

#include "robot/core/error.hpp"
#include "simulator/report/run_report.hpp"

namespace stride::sweep {
namespace {

using console::WalkFrame;

const std::vector<std::pair<std::string_view, double WalkFrame::*>>& frame_fields() {
  static const auto fields = [] {
    std::vector<std::pair<std::string_view, double WalkFrame::*>> out;
    for_each_field<WalkFrame>([&](const auto& f) { out.emplace_back(f.name, f.member); });
    return out;
  }();
  return fields;
}

int frame_field(std::string_view name) {
  const auto& fields = frame_fields();
  for (std::size_t i = 0; i < fields.size(); ++i)
    if (fields[i].first == name) return static_cast<int>(i);
  return -1;
}

template <class T>
std::string field_names() {
  std::string s;
  for_each_field<T>([&](const auto& f) { s += (s.empty() ? "" : ", ") + std::string(f.name); });
  return s;
}

template <class Result>
bool result_field_exists(std::string_view name) {
  bool found = false;
  for_each_field<Result>([&](const auto& f) { found = found || f.name == name; });
  return found;
}

template <class Result>
Cell result_field(const Result& w, std::string_view name) {
  Cell out = 0.0;
  for_each_field<Result>([&](const auto& f) {
    if (f.name != name) return;
    const auto& v = w.*(f.member);
    if constexpr (std::is_enum_v<std::remove_cvref_t<decltype(v)>>)
      out = std::string(EnumNames<std::remove_cvref_t<decltype(v)>>::names[static_cast<int>(v)]);
    else
      out = static_cast<double>(v);
  });
  return out;
}

// "representation:Name.path" -> {Name, path}
std::pair<std::string, std::string> split_framework_key(const std::string& key) {
  const std::string rest = key.substr(key.find(':') + 1);
  const std::size_t cut = rest.find_first_of(".[");
  if (cut == std::string::npos) return {rest, ""};
  return {rest.substr(0, cut), rest.substr(rest[cut] == '.' ? cut + 1 : cut)};
}

Runtime& runtime_of(console::SimSession& s, const std::string& key) {
  Runtime* rt = s.simulation().robot_count() > 0 ? s.runtime(0) : nullptr;
  if (!rt) throw Error(key + ": robot 0 has no <controller>");
  return *rt;
}

const std::string kPerFrameKeys =
    "representation:<Name>.<path>, frame.<field> (WalkFrame: " + field_names<WalkFrame>() + ")";
const std::string kRunKeys = "walk.<field> (" + field_names<sim::WalkMetricsResult>() +
                             "), landing.<field> (" + field_names<sim::LandingMetricsResult>() +
                             ", touch-downs from the walk's start), module:<Name>.<path>, "
                             "pattern.duration, pattern.start_delay, "
                             "sim.time, sim.steps, sim.hash, robot.period";

}  // namespace

void check_key(const std::string& key, bool per_frame) {
  if (key.rfind("representation:", 0) == 0 && key.size() > 15) return;
  if (key.rfind("frame.", 0) == 0) {
    if (frame_field(key.substr(6)) >= 0) return;
    throw Error("unknown key '" + key + "' (WalkFrame fields: " + field_names<WalkFrame>() + ")");
  }
  if (!per_frame) {
    if (key.rfind("walk.", 0) == 0 && result_field_exists<sim::WalkMetricsResult>(key.substr(5)))
      return;
    if (key.rfind("landing.", 0) == 0 &&
        result_field_exists<sim::LandingMetricsResult>(key.substr(8)))
      return;
    if (key.rfind("module:", 0) == 0 && key.size() > 7) return;
    if (key == "pattern.duration" || key == "pattern.start_delay" || key == "sim.time" ||
        key == "sim.steps" || key == "sim.hash" || key == "robot.period")
      return;
    throw Error("unknown key '" + key + "' (expected " + kPerFrameKeys + ", " + kRunKeys + ")");
  }
  throw Error("unknown per-frame key '" + key + "' (expected " + kPerFrameKeys + ")");
}

bool key_is_text(const std::string& key) {
  return key == "walk.tipped" || key == "sim.hash";
}

bool key_needs_walk_frame(const std::string& key) {
  return key.rfind("frame.", 0) == 0;
}

FrameKeys::FrameKeys(console::SimSession& session, const console::WalkFrameObserver* walk,
                     const std::vector<std::string>& keys, const std::vector<bool>& needed)
    : walk_(walk), values_(keys.size(), 0.0) {
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const std::string& key = keys[k];
    Bound b;
    if (!needed.empty() && !needed[k]) {
      values_[k] = std::numeric_limits<double>::quiet_NaN();
    } else if (key.rfind("frame.", 0) == 0) {
      b.frame_field = frame_field(key.substr(6));
      if (b.frame_field < 0 || !walk) throw Error("key '" + key + "' needs the walk observer");
    } else {
      const auto [name, path] = split_framework_key(key);
      const Slot& slot = runtime_of(session, key).representation_slot(name);
      b.reader.emplace(slot.desc(), path, name);
      auto it = std::find(slots_.begin(), slots_.end(), &slot);
      b.slot = static_cast<int>(it - slots_.begin());
      if (it == slots_.end()) slots_.push_back(&slot);
    }
    bound_.push_back(std::move(b));
  }
  bytes_.resize(slots_.size());
}

void FrameKeys::sample() {
  for (std::size_t s = 0; s < slots_.size(); ++s) {
    bytes_[s].clear();
    ByteWriter w(bytes_[s]);
    slots_[s]->encode(w);
  }
  for (std::size_t k = 0; k < bound_.size(); ++k) {
    const Bound& b = bound_[k];
    if (b.frame_field < 0 && !b.reader) continue;  // not needed by this run
    values_[k] = b.frame_field >= 0 ? walk_->frame().*(frame_fields()[b.frame_field].second)
                                    : b.reader->read_encoded(*slots_[b.slot], bytes_[b.slot]);
  }
}

Cell read_key(console::SimSession& session, const console::WalkFrameObserver* walk,
              const std::string& key) {
  auto& sim = session.simulation();
  if (key == "sim.time") return sim.time();
  if (key == "sim.steps") return static_cast<double>(sim.steps());
  if (key == "sim.hash") return sim::hash_hex(sim.state_hash());
  if (key == "robot.period") return sim.robot(0).period();
  if (key.rfind("walk.", 0) == 0) return result_field(sim.walk_metrics(0).result(), key.substr(5));
  if (key.rfind("landing.", 0) == 0) {
    // Touch-downs of the walk: from its start when robot 0 walks a pattern (not the first drop).
    const auto pattern = walk ? walk->pattern() : console::walk_pattern_info(session);
    const double from = pattern ? pattern->start_delay : 0.0;
    return result_field(sim.landing_metrics(0).result(from), key.substr(8));
  }
  if (key.rfind("pattern.", 0) == 0) {
    if (!walk || !walk->pattern())
      throw Error(key +
                  ": robot 0 walks no pattern (WalkingJointRequest from PatternWalk or "
                  "ConventionalWalk)");
    return key == "pattern.duration" ? walk->pattern()->duration : walk->pattern()->start_delay;
  }
  if (key.rfind("module:", 0) == 0) {
    const std::string text = runtime_of(session, key).get(key);
    double v = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (r.ec == std::errc() && r.ptr == text.data() + text.size()) return v;
    if (text == "true" || text == "false") return text == "true" ? 1.0 : 0.0;
    throw Error(key + ": '" + text + "' is not a number");
  }
  FrameKeys one(session, walk, {key});
  one.sample();
  return one.values()[0];
}

}  // namespace stride::sweep
