#include "console/view/view_bridge.hpp"

#include <ostream>
#include <regex>
#include <sstream>

#include "console/interpreter/interpreter.hpp"
#include "console/interpreter/values.hpp"
#include "console/view/output_capture.hpp"
#include "robot/core/error.hpp"
#include "robot/core/number_text.hpp"  // parse_number

namespace stride::view {

namespace {

std::string first_word(const std::string& line) {
  const auto b = line.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return line.substr(b, line.find_first_of(" \t", b) - b);
}

// Commands after which the page's 3D scene is another one.
bool changes_scene(const std::string& word) {
  return word == "load" || word == "reset" || word == "robot" || word == "connect" ||
         word == "disconnect";
}

}  // namespace

// `log goto k` shows frame k; `log load f` another log (its frame count from the summary).
void ViewBridge::note_log_command(const std::string& line, const std::string& output) {
  std::istringstream words(line);
  std::string log, verb, arg;
  words >> log >> verb >> arg;
  try {
    if (verb == "goto") {
      log_frame_ = static_cast<std::size_t>(std::stoull(arg));
      sample();  // the shown frame's values: plots fill as the log is played or scrubbed
    }
    if (verb == "load") {
      log_frame_.reset();
      std::smatch m;
      log_frames_ = std::regex_search(output, m, std::regex(": ([0-9]+) frames"))
                        ? static_cast<std::size_t>(std::stoull(m[1]))
                        : 0;
    }
  } catch (const std::exception&) {
    // the command succeeded, so its argument was a number; nothing to note otherwise
  }
}

ViewBridge::ViewBridge(console::Interpreter& interpreter, std::ostream& out,
                       WebServerOptions options, std::string mode)
    : interpreter_(interpreter), out_(out), mode_(std::move(mode)), server_(std::move(options)) {
  interpreter_.set_step_hook([this] { on_step(); });
  observe_keys();
}

ViewBridge::~ViewBridge() {
  interpreter_.set_step_hook({});
}

void ViewBridge::poll() {
  for (ClientEvent& e : server_.take_events()) {
    switch (e.kind) {
      case ClientEvent::Kind::Joined:
        on_join(e.client, e.read_only);
        break;
      case ClientEvent::Kind::Message:
        on_message(e.client, e.text);
        break;
      case ClientEvent::Kind::Left:
        read_only_.erase(e.client);
        if (times_pages_.erase(e.client) > 0 && times_pages_.empty()) observe_keys();
        break;
    }
  }
  // A paused remote robot's clock goes on: after the frame that shows the pause, the pages get
  // none until `run` follows it again (a command's reply still brings one).
  answer_page_runs();
  const bool paused_remote = mode_ == "remote" && !interpreter_.running() && !last_running_;
  if (!paused_remote) send_frame_if_due(false);
  const auto now = std::chrono::steady_clock::now();
  if (now - last_status_ > std::chrono::seconds(2) && server_.clients() > 0) {
    last_status_ = now;
    server_.broadcast(
        dump({{"type", "status"}, {"dropped", server_.dropped()}, {"clients", server_.clients()}}));
  }
}

void ViewBridge::event(const std::string& kind, const std::string& text) {
  server_.broadcast(dump({{"type", "event"}, {"kind", kind}, {"text", text}, {"t", time()}}));
}

void ViewBridge::on_step() {
  last_step_wall_ = std::chrono::system_clock::now();
  const int spf = steps_per_frame();
  if (spf > 0 && step_count() % static_cast<std::uint64_t>(spf) == 0) sample();
  send_frame_if_due(false);
}

void ViewBridge::on_join(std::uint64_t client, bool read_only) {
  if (read_only) read_only_.insert(client);
  server_.send(client, dump(hello()));
  server_.send(client, dump(scene()));
  Json f = frame(false);
  f["dropped"] = 0;  // a page's count starts with it
  server_.send(client, dump(f));
}

void ViewBridge::on_message(std::uint64_t client, const std::string& text) {
  ViewRequest r;
  try {
    r = decode_view_message(text);
  } catch (const Error& e) {
    server_.send(client, dump({{"type", "error"}, {"error", e.what()}}));
    return;
  }
  if (const auto* c = std::get_if<CmdRequest>(&r)) return run_cmd(client, *c);
  if (const auto* w = std::get_if<WatchRequest>(&r)) return watch(client, *w);
  if (const auto* g = std::get_if<GetRequest>(&r)) return get(client, *g);
  if (std::holds_alternative<TreeRequest>(r)) return server_.send(client, dump(tree()));
  if (const auto* t = std::get_if<TimesRequest>(&r)) {
    const bool before = !times_pages_.empty();
    if (t->on)
      times_pages_.insert(client);
    else
      times_pages_.erase(client);
    if (before != !times_pages_.empty()) observe_keys();
    return;
  }
  server_.send(client, dump({{"type", "error"}, {"error", "ws message: already authenticated"}}));
}

void ViewBridge::run_cmd(std::uint64_t client, const CmdRequest& c) {
  const std::string word = first_word(c.line);
  Json reply = {{"type", "reply"}, {"id", c.id}};
  if (read_only_.contains(client) && word != "get" && word != "help" && !word.empty()) {
    reply.update(
        {{"ok", false}, {"output", ""}, {"error", word + ": this page's token is read-only"}});
    return server_.send(client, dump(reply));
  }
  if (start_page_run(client, c)) return;
  std::string error;
  const std::string output = execute(c.line, error);
  reply.update({{"ok", error.empty()}, {"output", output}});
  if (!error.empty()) reply["error"] = error;
  server_.send(client, dump(reply));
  send_frame_if_due(true);
}

// `run <seconds>` typed on a page runs in the background: that page is answered when the run
// ends (or is paused), and every page's commands are served between its slices meanwhile.
bool ViewBridge::start_page_run(std::uint64_t client, const CmdRequest& c) {
  std::istringstream words(c.line);
  std::string run, seconds, more;
  words >> run >> seconds >> more;
  if (run != "run" || seconds.empty() || !more.empty() || mode_ == "log") return false;
  std::ostringstream captured;
  double until = 0;
  try {
    OutputCapture capture(out_, captured);
    const double span = parse_number(seconds, "run: seconds");
    interpreter_.run_for(span);
    until = time() + span;
  } catch (const Error& e) {
    server_.send(client, dump({{"type", "reply"},
                               {"id", c.id},
                               {"ok", false},
                               {"output", captured.str()},
                               {"error", e.what()}}));
    return true;
  }
  page_runs_.push_back({client, c.id, until});
  return true;
}

// The pages whose `run <seconds>` has ended are told where it stopped.
void ViewBridge::answer_page_runs() {
  if (page_runs_.empty() || interpreter_.running()) return;
  const double now = time();
  const std::string at = "paused at t=" + interpreter_.target().time_text();
  for (const PageRun& r : page_runs_) {
    const bool early = now < r.until - 1e-9;
    const Json reply = {{"type", "reply"},
                        {"id", r.id},
                        {"ok", true},
                        {"output", at + (early ? " (paused before the run's end)\n" : "\n")}};
    server_.send(r.client, dump(reply));
  }
  page_runs_.clear();
  send_frame_if_due(true);
}

std::string ViewBridge::execute(const std::string& line, std::string& error) {
  std::ostringstream captured;
  {
    OutputCapture capture(out_, captured);
    try {
      interpreter_.execute(line);
    } catch (const Error& e) {
      error = e.what();
    } catch (const std::exception& e) {  // a failure the console does not describe: its text
      error = e.what();
    }
  }
  const std::string word = first_word(line);
  if (error.empty() && word == "log") note_log_command(line, captured.str());
  if (changes_scene(word)) refresh_scene();
  if (word == "mr") observe_keys();  // whether the walk's plan still drives the robot
  return captured.str();
}

void ViewBridge::refresh_scene() {
  observe_keys();
  server_.broadcast(dump(scene()));
}

std::string ViewBridge::command(const std::string& line) {
  std::string error;
  std::string output = execute(line, error);
  send_frame_if_due(true);
  if (!error.empty()) throw Error(error);
  return output;
}

std::string ViewBridge::value(const std::string& key) {
  if (key.starts_with("log.")) return interpreter_.local().get(key);
  return interpreter_.target().get(key);
}

void ViewBridge::watch(std::uint64_t client, const WatchRequest& w) {
  for (const std::string& key : w.keys) {
    std::string problem;
    try {
      const std::string v = value(key);
      if (v != "true" && v != "false") console::parse_number(v, key);
    } catch (const Error& e) {
      problem = e.what();
    }
    if (!problem.empty())
      return server_.send(client,
                          dump({{"type", "error"}, {"error", "watch: " + key + ": " + problem}}));
  }
  watch_keys_ = w.keys;
  rows_.clear();
  observe_keys();
}

void ViewBridge::get(std::uint64_t client, const GetRequest& g) {
  Json reply = {{"type", "value"}, {"id", g.id}, {"key", g.key}};
  try {
    reply["text"] = value(g.key);
  } catch (const Error& e) {
    reply["error"] = e.what();
  }
  server_.send(client, dump(reply));
}

}  // namespace stride::view
