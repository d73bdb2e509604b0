#include "robot/debug/loop_side.hpp"

#include <exception>

#include "robot/runtime/controller_keys.hpp"

namespace stride::debug {

namespace {
// Appends up to `limit` lines in all, counting the rest; the first stop reason stays.
void hold(DebugText& to, std::uint64_t& dropped, const std::vector<std::string>& lines,
          const std::string& stop, std::size_t limit) {
  for (const auto& line : lines)
    if (to.lines.size() < limit)
      to.lines.push_back(line);
    else
      ++dropped;
  if (to.stop.empty()) to.stop = stop;
}

void say_dropped(std::vector<std::string>& lines, std::uint64_t& dropped) {
  if (dropped > 0) lines.push_back("(" + std::to_string(dropped) + " debug lines dropped)");
  dropped = 0;
}
}  // namespace

LoopSide::LoopSide(Exchange& exchange, std::string robot_name, bool keep_debug_output)
    : x_(exchange), robot_(std::move(robot_name)), keep_(keep_debug_output) {}

void LoopSide::take_debug_output(Runtime& rt) {
  const std::vector<std::string> lines = rt.take_debug_lines();
  const std::string stop = rt.take_debug_stop();
  if (lines.empty() && stop.empty()) return;
  if (keep_) hold(kept_, kept_dropped_, lines, stop, kMaxDebugLines);
  if (x_.clients.load(std::memory_order_relaxed))
    hold(pending_, pending_dropped_, lines, stop, kMaxHeldLines);
}

DebugText LoopSide::take_kept_debug_output() {
  DebugText out = std::move(kept_);
  kept_ = {};
  say_dropped(out.lines, kept_dropped_);
  return out;
}

void LoopSide::refresh_catalogue(Runtime& rt) {
  auto c = std::make_shared<Catalogue>();
  c->generation = ++generation_;
  slots_.clear();
  auto add = [&](std::string key, const Slot& s) {
    if (slots_.size() >= kMaxSlots) return;  // more are not served (never the case for the NAO)
    std::string desc;
    ByteWriter w(desc);
    write_type_desc(w, s.desc());
    c->keys.push_back(std::move(key));
    c->desc_bytes.push_back(std::move(desc));
    slots_.push_back(&s);
  };
  for (const auto& name : rt.representation_names())
    add("representation:" + name, rt.representation_slot(name));
  for (const auto& module : rt.parameter_modules())
    add("module:" + module, rt.parameter_slot_of(module));
  frame_info_ = &rt.representation<FrameInfo>();
  runtime_ = &rt;
  plan_generation_ = rt.plan_generation();
  wanted_.fill(0);
  pending_catalogue_ = std::move(c);
}

bool LoopSide::take_request(LoopRequest& in) {
  if (!held_) return x_.requests.try_pop(in);
  in = std::move(*held_);
  held_.reset();
  return true;
}

LoopReply LoopSide::apply(Runtime& rt, LoopRequest& in) {
  const Request& r = in.request;
  LoopReply out;
  out.client = in.client;
  out.id = r.id;
  out.op = r.op;
  out.json = r.on;
  try {
    switch (r.op) {
      case Op::Set:
        rt.set(r.key, r.text);
        break;
      case Op::Mr:
        rt.swap_provider(r.key, r.text);
        out.text = rt.provider_of(r.key);
        break;
      case Op::Dr:
        rt.set_debug_request(r.key, debug_switch_named(r.text).value_or(DebugSwitch::Off));
        break;
      case Op::Value:
        out.text = controller_value(rt, r.key);
        break;
      case Op::LogStart:
        out.text = r.key;  // also on an error: the server removes the file it created
        start_log(rt, in);
        break;
      case Op::LogStop: {
        if (!log_) throw Error("no log is being recorded");
        out.text = log_file_;
        out.frames = log_->frames_written();
        const auto log = std::move(log_);
        log_file_.clear();
        log->close();
        break;
      }
      case Op::Restart:  // done by the loop's owner after this frame (take_restart)
        if (!restartable_) throw Error("restart: this robot's loop cannot restart its scenario");
        restart_ = true;
        break;
      case Op::List:
      case Op::Report:
        if (const std::pair<const Runtime*, std::uint64_t> now{&rt, rt.plan_generation()};
            !listing_ || listing_of_ != now) {  // once a plan
          listing_ = robot_listing(rt);
          listing_of_ = now;
        }
        out.state =
            std::make_shared<RobotState>(robot_state(rt, robot_, listing_, log_file_, log_.get()));
        break;
      default:
        throw Error(std::string(op_name(r.op)) + " is not a loop request");
    }
  } catch (const std::exception& e) {
    out.error = e.what();
  }
  return out;
}

void LoopSide::start_log(Runtime& rt, const LoopRequest& in) {
  if (log_) throw Error("a log is already being recorded (log stop first)");
  log_ = rt.open_log(in.path);
  log_file_ = in.request.key;
  log_client_ = in.client;
}

void LoopSide::write_log() {
  try {
    log_->write_frame();
  } catch (const Error& e) {
    end_log(e.what());
  }
}

void LoopSide::end_log(const std::string& why) {
  LoopReply note;
  note.client = log_client_;
  note.op = Op::LogStop;
  note.text = "log '" + log_file_ + "' stopped after " + std::to_string(log_->frames_written()) +
              " frames: " + why;
  pending_note_ = std::move(note);  // sent at the next boundary
  log_.reset();                     // the frames written so far stay readable
  log_file_.clear();
}

void LoopSide::detached(Runtime& runtime) {
  if (&runtime != runtime_) return;
  runtime_ = nullptr;  // a runtime made later at the same address still gets a fresh catalogue
  frame_info_ = nullptr;
  slots_.clear();
  listing_.reset();
  if (log_) end_log("the robot's controller was replaced (reset or load)");
}

bool LoopSide::push_note() {
  if (!pending_note_) return false;
  LoopMessage m;
  m.kind = LoopMessage::Kind::Note;
  m.reply = std::move(*pending_note_);
  if (!x_.to_server.try_push(m)) {
    pending_note_ = std::move(m.reply);  // the next boundary tries again
    return false;
  }
  pending_note_.reset();
  return true;
}

bool LoopSide::wanted_changed() {
  bool changed = false;
  const bool current = x_.wanted_generation.load(std::memory_order_acquire) == generation_;
  for (std::size_t i = 0; i < wanted_.size(); ++i) {
    const std::uint64_t bits = current ? x_.wanted[i].load(std::memory_order_relaxed) : 0;
    changed |= bits != wanted_[i];
    wanted_[i] = bits;
  }
  return changed;
}

std::unique_ptr<Snapshot> LoopSide::take_buffer() {
  std::unique_ptr<Snapshot> s;
  if (!ready_.empty()) {
    s = std::move(ready_.back());
    ready_.pop_back();
  } else if (!x_.spent.try_pop(s)) {
    s = std::make_unique<Snapshot>();
    s->copied.reserve(kMaxSlots);
    x_.loop_allocations.fetch_add(1, std::memory_order_relaxed);
  }
  return s;
}

bool LoopSide::publish(bool new_frame) {
  std::unique_ptr<Snapshot> s = take_buffer();
  if (s->generation != generation_) {  // a buffer of another catalogue: its copies' types checked
    for (std::size_t i = 0; i < s->copies.size() && i < slots_.size(); ++i)
      if (s->copies[i] && s->copies[i]->type() != slots_[i]->type()) s->copies[i].reset();
    s->generation = generation_;
  }
  s->frame = frame_info_->frame;
  s->time = frame_info_->time;
  s->new_frame = new_frame;
  s->loop_frames = x_.frames.load(std::memory_order_relaxed);
  s->debug_lines.clear();
  s->debug_stop.clear();
  s->debug_values.clear();
  if (new_frame) {
    say_dropped(pending_.lines, pending_dropped_);
    s->debug_lines.swap(pending_.lines);
    s->debug_stop.swap(pending_.stop);
    s->debug_values.assign(runtime_->debug_values().begin(), runtime_->debug_values().end());
  }
  s->slot_count = static_cast<std::uint32_t>(slots_.size());
  s->copied.clear();
  if (s->copies.size() < slots_.size()) s->copies.resize(slots_.size());
  for (std::size_t word = 0; word < wanted_.size(); ++word) {
    for (std::uint64_t bits = wanted_[word]; bits; bits &= bits - 1) {
      const std::size_t i = word * 64 + static_cast<std::size_t>(__builtin_ctzll(bits));
      if (i >= slots_.size()) break;
      auto& copy = s->copies[i];
      // A buffer's first use of a slot, or a re-plan changed its type: the only allocation.
      if (!copy) {
        copy = slots_[i]->fresh();
        x_.loop_allocations.fetch_add(1, std::memory_order_relaxed);
      }
      slots_[i]->copy_to(*copy);
      s->copied.push_back(static_cast<std::uint32_t>(i));
    }
  }
  LoopMessage m;
  m.kind = LoopMessage::Kind::Snapshot;
  m.snapshot = std::move(s);
  if (x_.to_server.try_push(m)) return true;
  if (new_frame) {
    x_.snapshots_lost.fetch_add(1, std::memory_order_relaxed);
    // The server thread fell behind: the debug output waits for the next snapshot.
    pending_.lines.swap(m.snapshot->debug_lines);
    pending_.stop.swap(m.snapshot->debug_stop);
  }
  // Kept for the next publish (never pushed into `spent`: the server thread is its one producer).
  if (ready_.size() < kReadyBuffers) ready_.push_back(std::move(m.snapshot));
  return false;
}

bool LoopSide::push_catalogue() {
  if (!pending_catalogue_) return true;
  LoopMessage m;
  m.kind = LoopMessage::Kind::Catalogue;
  m.catalogue = pending_catalogue_;
  if (!x_.to_server.try_push(m)) return false;
  pending_catalogue_.reset();
  return true;
}

void LoopSide::service(Runtime& rt, bool new_frame) {
  if (&rt != runtime_ || rt.plan_generation() != plan_generation_) refresh_catalogue(rt);
  if (new_frame) {
    // The loop is its only writer: a plain store, not a locked add that waits for every store.
    x_.frames.store(x_.frames.load(std::memory_order_relaxed) + 1, std::memory_order_release);
    x_.period.store(frame_info_->period, std::memory_order_relaxed);
    take_debug_output(rt);
    if (log_) write_log();
  }
  // Nothing here wakes the server thread: a system call's wake-up of another core costs the loop
  // more than all its other boundary work; the server looks every 2 ms while it awaits the loop.
  if (pending_catalogue_) push_catalogue();
  push_note();
  // Room for every reply, a catalogue and a snapshot is made sure of before a request is taken.
  replies_.clear();
  LoopRequest in;
  bool listed = false;  // a list or report this boundary: the next one waits for the next frame
  while (static_cast<int>(replies_.size()) < kRequestsPerFrame &&
         x_.to_server.has_room(replies_.size() + 3) && take_request(in)) {
    const bool lists = in.request.op == Op::List || in.request.op == Op::Report;
    if (lists && listed) {
      held_ = std::move(in);
      break;
    }
    listed |= lists;
    replies_.push_back(apply(rt, in));
  }
  const bool applied = !replies_.empty();
  if (applied && rt.plan_generation() != plan_generation_) {
    refresh_catalogue(rt);  // a re-plan may have put new representations on the blackboard
    push_catalogue();
  }
  bool streamed = false;
  if (x_.clients.load(std::memory_order_relaxed) && !pending_catalogue_) {
    const bool more_wanted = wanted_changed();
    bool any = false;
    for (auto w : wanted_) any |= w != 0;
    streamed = any;
    if (any && (new_frame || more_wanted || applied)) publish(new_frame);
  }
  if (new_frame && !streamed) {  // nobody streams this frame: its debug output is not for anyone
    pending_.lines.clear();
    pending_.stop.clear();
    pending_dropped_ = 0;
  }
  for (auto& r : replies_) {
    LoopMessage m;
    m.reply = std::move(r);
    x_.to_server.try_push(m);  // room was made sure of above
  }
}

std::shared_ptr<const RobotListing> robot_listing(const Runtime& rt) {
  auto l = std::make_shared<RobotListing>();
  l->representations = rt.representation_names();
  for (const auto& rep : l->representations) {
    l->providers.push_back(rt.provider_of(rep));
    l->available.push_back(rt.providers_available(rep));
  }
  l->parameter_modules = rt.parameter_modules();
  l->module_order = rt.representation<ModuleTimes>().modules;
  l->declarations = rt.module_declarations();
  for (const auto& [name, state] : rt.debug_requests()) l->debug_requests.push_back(name);
  return l;
}

RobotState robot_state(const Runtime& rt, const std::string& robot,
                       std::shared_ptr<const RobotListing> listing, const std::string& log_file,
                       const LogWriter* log) {
  RobotState s;
  s.robot = robot;
  const auto& info = rt.representation<FrameInfo>();
  s.period = info.period;
  s.frame = info.frame;
  s.time = info.time;
  s.listing = std::move(listing);
  s.module_ns = rt.representation<ModuleTimes>().ns;
  for (const auto& [name, state] : rt.debug_requests())
    s.debug_states.emplace_back(debug_switch_name(state));
  s.log_file = log ? log_file : "";
  s.log_frames = log ? log->frames_written() : 0;
  return s;
}

}  // namespace stride::debug
