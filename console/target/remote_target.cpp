#include "console/target/remote_target.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"
#include "robot/debug/log_directory.hpp"
#include "robot/runtime/console_key.hpp"
#include "robot/runtime/controller_keys.hpp"

namespace stride::console {

namespace {
using debug::Op;
using debug::Request;
using debug::request;

std::string number_text(double v) {
  std::ostringstream o;
  o.precision(10);
  o << v;
  return o.str();
}

Value decode(const TypeDesc& d, const std::string& bytes, const std::string& what) {
  try {
    ByteReader r(bytes);
    Value v = read_value(d, r);
    if (r.remaining() != 0) throw Error(std::to_string(r.remaining()) + " bytes left over");
    return v;
  } catch (const Error& e) {
    throw Error(what + ": the robot's value does not match its description (" + e.what() + ")");
  }
}
}  // namespace

RemoteTarget::RemoteTarget(const debug::Endpoint& endpoint, const std::string& token,
                           debug::ClientOptions options)
    : endpoint_(endpoint), client_(std::make_unique<debug::DebugClient>(endpoint, token, options)) {
  period_ = client_->welcome().period;
  if (!(period_ > 0)) period_ = call(request(Op::List))->fields().number("period");
}

std::string RemoteTarget::name() const {
  return "robot " + client_->hello().robot + " at " + endpoint_.text();
}

std::unique_ptr<debug::ServerMessage> RemoteTarget::call(Request r) {
  return client_->call(std::move(r));
}

RemoteTarget::Listing RemoteTarget::list() {
  const auto m = call(request(Op::List));
  const auto& f = m->fields();
  Listing l{f.texts("representations"), f.texts("providers"),   f.texts("modules"),
            f.texts("debug"),           f.texts("debug_state"), f.text_lists("available")};
  if (!(period_ > 0)) period_ = f.number("period");
  if (l.providers.size() != l.representations.size() ||
      l.available.size() != l.representations.size() || l.debug_state.size() != l.debug.size())
    throw Error("the robot's list has lists of different lengths");
  return l;
}

RemoteTarget::Root& RemoteTarget::fetch(const std::string& key) {
  const std::string root_key = split_console_key(key).root();
  const auto m = call(request(Op::Get, root_key));
  const std::string desc_bytes = m->fields().bytes("desc");
  Root& root = roots_[root_key];
  if (!root.desc || root.desc_bytes != desc_bytes) {
    ByteReader r(desc_bytes);
    root.desc = read_type_desc(r);
    root.desc_bytes = desc_bytes;
  }
  root.value = decode(*root.desc, m->fields().bytes("value"), root_key);
  return root;
}

std::string RemoteTarget::streamed(const std::string& key) {
  for (std::size_t i = 0; i < subscribed_.size(); ++i) {
    if (subscribed_[i] != key) continue;
    const std::string& bytes = current_->values.at(i);
    if (bytes.empty()) throw Error(key + ": not in this frame on the robot");
    return print_value(*subscribed_descs_[i], decode(*subscribed_descs_[i], bytes, key));
  }
  return {};
}

std::string RemoteTarget::get(const std::string& key) {
  if (key == "robot.name") return robot();
  if (is_controller_key(key)) {
    if (current_ && key.starts_with("debug:")) {  // streamed with the frame
      const auto& keys = current_->debug_keys;
      for (std::size_t i = 0; i < keys.size(); ++i)
        if (keys[i] == std::string_view(key).substr(6))
          return debug_value_text(current_->debug_values[i]);
    }
    return call(request(Op::Value, key))->fields().text("text");  // the robot's own words
  }
  if (key.starts_with("representation:") || key.starts_with("module:")) {
    if (current_)
      if (std::string v = streamed(key); !v.empty()) return v;
    const ConsoleKey k = split_console_key(key);
    Root& root = fetch(key);
    const auto [d, v] = value_at(*root.desc, root.value, k.path, k.name);
    return print_value(*d, *v);
  }
  throw Error(quote(key) + " is a simulation's; " + name() +
              " answers representation:X, module:X, provider:X, override:X, debug:X.y and "
              "robot.name");
}

const TypeDesc& RemoteTarget::type_of(const std::string& key) {
  if (!key.starts_with("representation:") && !key.starts_with("module:"))
    throw Error("'" + key + "' has no type description (representation:X or module:X have)");
  const ConsoleKey k = split_console_key(key);
  Root& root = fetch(key);
  return *value_at(*root.desc, root.value, k.path, k.name).first;
}

void RemoteTarget::set(const std::string& key, const std::string& fields) {
  call(request(Op::Set, key, fields));
}

std::vector<std::string> RemoteTarget::representations() {
  return list().representations;
}

std::vector<std::string> RemoteTarget::parameter_modules() {
  return list().modules;
}

std::string RemoteTarget::provider_of(const std::string& representation) {
  const Listing l = list();
  for (std::size_t i = 0; i < l.representations.size(); ++i)
    if (l.representations[i] == representation) return l.providers[i];
  throw Error("no representation '" + representation + "' on the blackboard");
}

std::vector<std::string> RemoteTarget::providers_available(const std::string& representation) {
  const Listing l = list();
  for (std::size_t i = 0; i < l.representations.size(); ++i)
    if (l.representations[i] == representation) return l.available[i];
  return {};
}

RobotTarget::Providers RemoteTarget::providers() {
  Listing l = list();
  return {std::move(l.representations), std::move(l.providers), std::move(l.available)};
}

std::optional<std::vector<ModuleDeclaration>> RemoteTarget::module_declarations() {
  return debug::module_graph_of(call(request(Op::List))->fields());
}

double RemoteTarget::refresh_period(double patience) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(patience);
  while (!(period_ > 0) && std::chrono::steady_clock::now() < until) {
    list();  // sets period_ once the robot's loop has run
    if (!(period_ > 0)) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return period_;
}

void RemoteTarget::restart() {
  call(request(Op::Restart));
  current_.reset();
}

void RemoteTarget::swap_provider(const std::string& representation, const std::string& module) {
  call(request(Op::Mr, representation, module));
}

std::vector<std::pair<std::string, DebugSwitch>> RemoteTarget::debug_requests() {
  const Listing l = list();
  std::vector<std::pair<std::string, DebugSwitch>> out;
  for (std::size_t i = 0; i < l.debug.size(); ++i) {
    const auto state = debug_switch_named(l.debug_state[i]);
    if (!state)
      throw Error("the robot's debug request " + quote(l.debug[i]) + " is in an unknown state " +
                  quote(l.debug_state[i]));
    out.emplace_back(l.debug[i], *state);
  }
  return out;
}

void RemoteTarget::set_debug_request(const std::string& name, DebugSwitch state) {
  call(request(Op::Dr, name, std::string(debug_switch_name(state))));
}

void RemoteTarget::hold_lines(const debug::Sample& s) {
  for (const auto& line : s.lines) held_.emplace_back(s.time, line);
}

void RemoteTarget::stream_idle() {
  Request r = request(Op::Subscribe);
  r.keys = {"representation:FrameInfo.frame"};
  client_->send_only(std::move(r));
  idle_stream_ = true;
}

std::vector<std::string> RemoteTarget::idle_lines() {
  if (!idle_stream_) stream_idle();
  client_->keep_alive();
  std::vector<std::string> out = client_->take_notes();
  while (auto s = client_->next_sample(0)) hold_lines(*s);
  for (auto& [t, line] : held_) out.push_back("t=" + number_text(t) + " " + line);
  held_.clear();
  return out;
}

DebugOutput RemoteTarget::take_debug_output() {
  DebugOutput d;
  d.lines = client_->take_notes();  // what the robot said unasked, e.g. that a log stopped
  for (auto& held : held_) d.lines.push_back(std::move(held.second));
  held_.clear();
  if (!current_) return d;
  d.lines.insert(d.lines.end(), current_->lines.begin(), current_->lines.end());
  d.stop = std::move(current_->stop);
  current_->lines.clear();
  current_->stop.clear();
  return d;
}

void RemoteTarget::log_start(const std::string& path) {
  call(request(Op::LogStart, path));
}

void RemoteTarget::log_stop() {
  call(request(Op::LogStop));
}

std::string RemoteTarget::log_save(const std::string& path, const std::string& destination) {
  const auto info = call(request(Op::LogInfo, path));
  const std::uint64_t size = info->fields().unsigned_integer("size", UINT64_MAX);
  const std::string sha256 = info->fields().bytes("sha256");
  const std::string partial = destination + ".part";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("log save: cannot write '" + partial + "'");
    for (std::uint64_t offset = 0; offset < size;) {
      Request r = request(Op::LogFetch, path);
      r.offset = offset;
      r.length = std::min<std::uint64_t>(debug::kMaxLogChunk, size - offset);
      const std::string data = call(std::move(r))->fields().bytes("data");
      if (data.empty()) throw Error("log save: '" + path + "' on the robot ended early");
      out.write(data.data(), static_cast<std::streamsize>(data.size()));
      offset += data.size();
    }
    if (!out.flush()) throw Error("log save: cannot write '" + partial + "'");
  }
  if (debug::file_sha256(partial) != sha256) {
    std::remove(partial.c_str());
    throw Error("log save: '" + path + "' arrived damaged (SHA-256 differs); nothing written");
  }
  std::error_code ec;
  std::filesystem::rename(partial, destination, ec);
  if (ec) {
    std::remove(partial.c_str());
    throw Error("log save: cannot write '" + destination + "': " + ec.message() +
                "; nothing written");
  }
  return "downloaded " + path + " from " + name() + " (" + std::to_string(size) +
         " bytes, SHA-256 checked) as " + destination;
}

std::string RemoteTarget::report_text() {
  return call(request(Op::Report))->fields().text("text");
}

std::string RemoteTarget::report_json() {
  Request r = request(Op::Report);
  r.on = true;
  return call(std::move(r))->fields().text("json");
}

std::string RemoteTarget::time_text() {
  if (current_) return number_text(current_->time);
  return get("representation:FrameInfo.time");
}

std::vector<std::string> RemoteTarget::stream_keys() const {
  const std::vector<std::string> asked =
      observed_.empty() ? std::vector<std::string>{"representation:FrameInfo.frame"} : observed_;
  std::vector<std::string> framework;  // simulation keys fail in get(), not in the stream
  std::vector<std::string> debug;
  for (const auto& k : asked)
    if (k.starts_with("representation:") || k.starts_with("module:"))
      framework.push_back(k);
    else if (k.starts_with("debug:"))
      debug.push_back(k);
  if (framework.empty()) framework.push_back("representation:FrameInfo.frame");
  framework.insert(framework.end(), debug.begin(), debug.end());
  return framework;
}

std::int64_t RemoteTarget::subscribe(const std::vector<std::string>& keys) {
  Request r = request(Op::Subscribe);
  r.keys = keys;
  const auto reply = call(r);
  // Anything earlier belongs to an older subscription; only its lines are still to be said.
  while (auto s = client_->next_sample(0)) hold_lines(*s);
  idle_stream_ = false;
  stream_keys_ = keys;
  seen_dropped_ = 0;
  subscribed_.clear();
  for (const auto& k : keys)
    if (!k.starts_with("debug:")) subscribed_.push_back(k);
  subscribed_descs_.clear();
  for (const auto& bytes : reply->fields().byte_list("descs")) {
    ByteReader in(bytes);
    subscribed_descs_.push_back(read_type_desc(in));
  }
  if (subscribed_descs_.size() != subscribed_.size())
    throw Error("the robot described " + std::to_string(subscribed_descs_.size()) +
                " streamed keys for " + std::to_string(subscribed_.size()));
  return reply->fields().integer("from");
}

void RemoteTarget::hold_stream(bool hold) {
  hold_stream_ = hold;
  if (hold || next_frame_ < 0) return;
  next_frame_ = -1;
  current_.reset();
  try {
    stream_idle();
  } catch (const Error&) {  // a lost robot is told by the next call
  }
}

std::uint64_t RemoteTarget::advance(std::uint64_t steps, const std::function<bool()>& after_step) {
  if (steps == 0) return 0;
  const std::vector<std::string> keys = stream_keys();
  const bool goes_on = hold_stream_ && !idle_stream_ && next_frame_ >= 0 && keys == stream_keys_;
  const std::int64_t first = goes_on ? next_frame_ : subscribe(keys);
  next_frame_ = first;
  struct EndStream {  // however the run ends, the light stream follows, so no event is missed
    RemoteTarget& t;
    ~EndStream() {  // a held stream's last sample stays what `get` reads
      if (t.hold_stream_) return;
      t.current_.reset();
      t.hold_stream(false);
    }
  } end{*this};
  const double patience = std::max(2.0, 20 * period_);
  std::int64_t from = first;
  std::uint64_t done = 0;
  while (done < steps) {
    auto s = client_->next_sample(patience);
    if (!s)
      throw Error("no frame from " + name() + " for " + number_text(patience) +
                  " s (is its loop running?)");
    dropped_ += s->dropped - std::min(s->dropped, seen_dropped_);
    seen_dropped_ = s->dropped;
    if (s->frame < from) from = s->frame - static_cast<std::int64_t>(done);  // it restarted
    done = static_cast<std::uint64_t>(std::max<std::int64_t>(s->frame - from + 1, 0));
    next_frame_ = s->frame + 1;
    current_ = std::move(s);
    if (after_step && !after_step()) break;
  }
  return done;
}

}  // namespace stride::console
