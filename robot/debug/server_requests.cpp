// ServerThread, requests: what the server answers itself (get, subscribe, logs, ping) from the
// latest snapshot, what it hands to the loop (set, mr, dr, log start/stop, list, report), and the
// streams it sends after every frame.
#include <algorithm>

#include "robot/core/one_line.hpp"
#include "robot/debug/msgpack_map.hpp"
#include "robot/debug/robot_report.hpp"
#include "robot/debug/server_thread.hpp"
#include "robot/runtime/console_key.hpp"

namespace stride::debug {

namespace {
constexpr auto kParkLimit = std::chrono::seconds(2);    // the loop comes round far sooner
constexpr auto kGetInterest = std::chrono::seconds(5);  // a key got is kept in snapshots this long
constexpr int kMaxInFlight = 32;
constexpr std::size_t kMaxHeldLines = 1000;  // debug lines held for a client's next sample

bool is_debug_key(const std::string& key) {
  return key.starts_with("debug:");
}

// The keys of a subscription that name blackboard slots (the rest are debug:X.y values).
std::vector<std::string> slot_keys(const std::vector<std::string>& keys) {
  std::vector<std::string> out;
  for (const auto& k : keys)
    if (!is_debug_key(k)) out.push_back(k);
  return out;
}

MapWriter& ok_reply(MapWriter& w, std::uint64_t id) {
  return w.text("t", "reply").unsigned_integer("id", id).boolean("ok", true);
}
}  // namespace

std::uint64_t Subscription::due_between(std::int64_t first, std::int64_t last) const {
  first = std::max(first, from);
  if (last < first) return 0;
  const auto k = static_cast<std::int64_t>(every);
  const std::int64_t a = (first - from + k - 1) / k, b = (last - from) / k;
  return b >= a ? static_cast<std::uint64_t>(b - a + 1) : 0;
}

ClientSession* ServerThread::find(std::uint64_t id) {
  auto it = clients_.find(id);
  return it == clients_.end() || it->second->state != ClientSession::State::Ready
             ? nullptr
             : it->second.get();
}

void ServerThread::on_request(ClientSession& c, Request& r, Clock::time_point now) {
  requests_.fetch_add(1);
  c.bucket = std::min(options_.request_rate,
                      c.bucket + std::chrono::duration<double>(now - c.bucket_time).count() *
                                     options_.request_rate);
  c.bucket_time = now;
  if (c.bucket < 1)
    return send(
        c, encode_error_reply(r.id, "more than " +
                                        std::to_string(static_cast<int>(options_.request_rate)) +
                                        " requests per second: refused"));
  c.bucket -= 1;
  if (c.read_only && op_writes(r.op))
    return send(c, encode_error_reply(r.id, "'" + std::string(op_name(r.op)) +
                                                "' refused: this client's token is read-only"));
  switch (r.op) {
    case Op::Ping: {
      MapWriter w;
      ok_reply(w, r.id);
      return send(c, w.finish());
    }
    case Op::Unsubscribe: {
      c.sub.reset();
      MapWriter w;
      ok_reply(w, r.id);
      return send(c, w.finish());
    }
    case Op::LogInfo:
    case Op::LogFetch:
      return answer_log(c, r);
    case Op::Get:
    case Op::Subscribe:
      if (!try_answer(c, r)) parked_.push_back({c.id, std::move(r), now + kParkLimit});
      return;
    default:
      return to_loop(c, r);
  }
}

void ServerThread::to_loop(ClientSession& c, Request& r) {
  if (c.in_flight >= kMaxInFlight)
    return send(c, encode_error_reply(r.id, "more than " + std::to_string(kMaxInFlight) +
                                                " requests waiting for the robot's loop: refused"));
  LoopRequest in;
  in.client = c.id;
  try {
    if (r.op == Op::LogStart) in.path = logs_.create(r.key);  // a new file, or an error
  } catch (const Error& e) {
    return send(c, encode_error_reply(r.id, e.what()));
  }
  const std::uint64_t id = r.id;
  in.request = std::move(r);
  if (!x_.requests.try_push(in)) {
    if (in.request.op == Op::LogStart) logs_.discard(in.request.key);
    return send(c, encode_error_reply(id, "the robot's loop is busy: request refused"));
  }
  ++c.in_flight;
}

bool ServerThread::try_answer(ClientSession& c, const Request& r) {
  try {
    if (!catalogue_) return false;
    const std::vector<std::string> keys =
        r.op == Op::Get ? std::vector<std::string>{r.key} : slot_keys(r.keys);
    const std::vector<std::size_t> slots = slots_of(keys, *catalogue_);
    const auto now = Clock::now();
    for (const auto& k : keys) recent_gets_[split_console_key(k).root()] = now;
    // A snapshot the loop has moved on from (its slots were not wanted since) is not answered.
    if (!latest_ || latest_->loop_frames != x_.frames.load(std::memory_order_acquire)) return false;
    for (std::size_t s : slots)
      if (latest_->parts[s].first == Snapshot::kAbsent) return false;
    if (r.op == Op::Get)
      answer_get(c, r, slots[0]);
    else
      answer_subscribe(c, r, slots);
  } catch (const Error& e) {
    send(c, encode_error_reply(r.id, e.what()));
  }
  return true;
}

void ServerThread::answer_get(ClientSession& c, const Request& r, std::size_t slot) {
  const auto [offset, size] = latest_->parts[slot];
  MapWriter w;
  ok_reply(w, r.id)
      .text("key", catalogue_->key(slot))
      .bytes("desc", catalogue_->desc_bytes(slot))
      .bytes("value", std::string_view(latest_->bytes).substr(offset, size))
      .integer("frame", latest_->frame)
      .number("time", latest_->time);
  send(c, w.finish());
}

void ServerThread::answer_subscribe(ClientSession& c, const Request& r,
                                    const std::vector<std::size_t>&) {
  SnapshotValues values(*catalogue_, *latest_);
  Subscription s;
  s.keys = resolve_keys(slot_keys(r.keys), *catalogue_, values);  // throws naming a bad path
  for (const auto& k : r.keys)
    if (is_debug_key(k)) s.debug_keys.push_back(k.substr(6));
  s.every = r.every;
  s.from = latest_->frame + 1;
  std::vector<std::string> descs;
  for (const auto& k : s.keys) descs.push_back(k.desc_bytes);
  c.sub = std::move(s);
  MapWriter w;
  ok_reply(w, r.id).byte_list("descs", descs).integer("from", c.sub->from);
  send(c, w.finish());
}

void ServerThread::answer_log(ClientSession& c, const Request& r) {
  try {
    MapWriter w;
    ok_reply(w, r.id);
    if (r.op == Op::LogInfo) {
      const auto info = logs_.info(r.key);
      w.unsigned_integer("size", info.size).bytes("sha256", info.sha256);
    } else {
      std::uint64_t size = 0;
      const std::string data = logs_.read(r.key, r.offset, r.length, size);
      w.bytes("data", data).unsigned_integer("size", size);
    }
    send(c, w.finish());
  } catch (const Error& e) {
    send(c, encode_error_reply(r.id, e.what()));
  }
}

void ServerThread::take_from_loop() {
  LoopMessage m;
  while (x_.to_server.try_pop(m)) {
    switch (m.kind) {
      case LoopMessage::Kind::Catalogue:
        on_catalogue(std::move(m.catalogue));
        break;
      case LoopMessage::Kind::Snapshot:
        on_snapshot(std::move(m.snapshot));
        break;
      case LoopMessage::Kind::Reply:
        on_loop_reply(m.reply);
        break;
      case LoopMessage::Kind::Note:
        on_note(m.reply);
        break;
    }
  }
}

void ServerThread::on_catalogue(std::shared_ptr<const Catalogue> c) {
  catalogue_ = std::make_unique<ServedCatalogue>(std::move(c));
  if (latest_) x_.spent.try_push(latest_);
  latest_.reset();
  for (auto& [id, client] : clients_)
    if (client->sub) rebind_keys(client->sub->keys, *catalogue_);
}

void ServerThread::on_note(const LoopReply& r) {
  options_.log("debug server: " + one_line(r.text, 400));  // never lost to the line budget
  if (ClientSession* c = find(r.client)) {
    MapWriter w;
    w.text("t", "note").text("text", one_line(r.text, 2000));
    send(*c, w.finish());
  }
}

void ServerThread::on_loop_reply(LoopReply& r) {
  if (r.op == Op::LogStart && !r.error.empty()) logs_.discard(r.text);  // created for it, empty
  auto it = clients_.find(r.client);
  if (it != clients_.end()) --it->second->in_flight;
  ClientSession* c = find(r.client);
  if (!c) return;  // gone while its request waited
  if (!r.error.empty()) return send(*c, encode_error_reply(r.id, r.error));
  MapWriter w;
  ok_reply(w, r.id);
  switch (r.op) {
    case Op::Mr:
      w.text("provider", r.text);
      break;
    case Op::LogStart:
      w.text("file", r.text);
      break;
    case Op::LogStop:
      w.text("file", r.text).unsigned_integer("frames", r.frames);
      break;
    case Op::Value:
      w.text("text", r.text);
      break;
    case Op::List:
      write_list_fields(w, *r.state);
      break;
    case Op::Report:
      w.text(r.json ? "json" : "text",
             r.json ? robot_report_json(*r.state, stats()) : robot_report_text(*r.state, stats()));
      break;
    default:
      break;
  }
  send(*c, w.finish());
}

void ServerThread::on_snapshot(std::unique_ptr<Snapshot> s) {
  if (!catalogue_ || s->generation != catalogue_->generation()) {
    x_.spent.try_push(s);
    return;
  }
  encode_copies(*s);
  if (s->new_frame) stream(*s);
  if (latest_) x_.spent.try_push(latest_);
  latest_ = std::move(s);
}

void ServerThread::stream(Snapshot& s) {
  // A restarted controller counts its frames from 0 again: subscriptions start anew with it.
  if (last_frame_ >= 0 && s.frame < last_frame_)
    for (auto& [id, c] : clients_)
      if (c->sub) c->sub->from = s.frame;
  const std::int64_t gap_first = last_frame_ + 1;
  const bool gap = last_frame_ >= 0 && s.frame > gap_first;
  last_frame_ = s.frame;
  SnapshotValues values(*catalogue_, s);
  for (auto& [id, c] : clients_) {
    if (!c->sub || c->state != ClientSession::State::Ready) continue;
    Subscription& sub = *c->sub;
    const std::uint64_t lost = gap ? sub.due_between(gap_first, s.frame - 1) : 0;
    sub.dropped += lost;
    dropped_.fetch_add(lost);
    hold_debug_output(sub, s);
    if (!sub.due(s.frame)) continue;
    Sample sample{s.frame, s.time, sample_values(sub.keys, values), sub.dropped};
    fill_debug_output(sample, sub, s);
    if (send_sample(*c, encode_sample(sample))) {
      sent_.fetch_add(1);
      sub.lines.clear();
      sub.stop.clear();
    } else {
      ++sub.dropped;  // told with its next sample
      dropped_.fetch_add(1);
    }
  }
}

void ServerThread::hold_debug_output(Subscription& sub, const Snapshot& s) {
  for (const auto& line : s.debug_lines)
    if (sub.lines.size() < kMaxHeldLines)
      sub.lines.push_back(line);
    else
      ++sub.lines_dropped;
  if (sub.stop.empty()) sub.stop = s.debug_stop;
}

void ServerThread::fill_debug_output(Sample& sample, Subscription& sub, const Snapshot& s) {
  if (sub.lines_dropped > 0) {
    sub.lines.push_back("(" + std::to_string(sub.lines_dropped) + " debug lines dropped)");
    sub.lines_dropped = 0;
  }
  sample.lines = sub.lines;
  sample.stop = sub.stop;
  for (const auto& key : sub.debug_keys) {
    const auto it = std::find_if(s.debug_values.begin(), s.debug_values.end(),
                                 [&](const auto& kv) { return kv.first == key; });
    if (it == s.debug_values.end()) continue;  // not emitted (yet): the client asks the loop
    sample.debug_keys.push_back(key);
    sample.debug_values.push_back(it->second);
  }
}

void ServerThread::retry_parked(Clock::time_point now) {
  if (parked_.empty()) return;
  std::vector<Parked> still;
  for (auto& p : parked_) {
    ClientSession* c = find(p.client);
    if (!c) continue;
    if (try_answer(*c, p.request)) continue;
    if (now > p.deadline) {
      send(*c, encode_error_reply(p.request.id,
                                  "the robot's loop did not come round within 2 s (stalled?)"));
      continue;
    }
    still.push_back(std::move(p));
  }
  parked_ = std::move(still);
}

void ServerThread::publish_wanted(Clock::time_point now) {
  if (!catalogue_) return;
  std::array<std::uint64_t, kMaxSlots / 64> bits{};
  auto want = [&](std::size_t slot) {
    if (slot < kMaxSlots) bits[slot / 64] |= std::uint64_t{1} << (slot % 64);
  };
  std::erase_if(recent_gets_, [&](const auto& kv) { return now - kv.second > kGetInterest; });
  for (const auto& [key, when] : recent_gets_)
    if (auto slot = catalogue_->find(key)) want(*slot);
  for (const auto& [id, c] : clients_) {
    if (!c->sub) continue;
    // Every stream has its frames, even one of debug values alone.
    if (auto slot = catalogue_->find("representation:FrameInfo")) want(*slot);
    for (const auto& k : c->sub->keys)
      if (k.slot != StreamKey::kGone) want(k.slot);
  }
  if (bits == wanted_ && wanted_generation_ == catalogue_->generation()) return;
  wanted_ = bits;
  wanted_generation_ = catalogue_->generation();
  for (std::size_t i = 0; i < bits.size(); ++i)
    x_.wanted[i].store(bits[i], std::memory_order_relaxed);
  x_.wanted_generation.store(wanted_generation_, std::memory_order_release);
}

}  // namespace stride::debug
