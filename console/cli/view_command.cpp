// `stride view <scene> | --connect host:port | --log <file> [--scene <scene>] [--listen a:p]
// [--token-file f] [--seconds S]`: the live view in a browser (console/view/PROTOCOL.md). A
// local simulation starts paused; the page runs, pauses, steps and resets it. The first stdout
// line is "view: <url>" (port 0 picks a free port). Ends after --seconds, or on Ctrl-C.
#include <iostream>
#include <optional>
#include <ostream>
#include <sstream>
#include <thread>

#include "console/cli/arguments.hpp"
#include "console/cli/exit_codes.hpp"
#include "console/cli/subcommand.hpp"
#include "console/interpreter/interpreter.hpp"
#include "console/output/interrupt_flag.hpp"
#include "console/view/output_capture.hpp"
#include "console/view/view_bridge.hpp"
#include "console/view/view_options.hpp"
#include "robot/core/error.hpp"
#include "robot/debug/socket_io.hpp"

namespace stride::cli {
namespace {

using Clock = std::chrono::steady_clock;

// Serves until --seconds pass, the page quits, or Ctrl-C; background runs step between polls.
void serve(console::Interpreter& in, view::ViewBridge& bridge, std::optional<double> seconds) {
  console::InterruptFlag interrupt;
  const auto end = seconds ? Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                std::chrono::duration<double>(*seconds))
                           : Clock::time_point::max();
  while (!interrupt.raised() && !in.quit_requested() && Clock::now() < end) {
    bridge.poll();
    auto wait = std::chrono::duration_cast<Clock::duration>(std::chrono::milliseconds(5));
    if (in.running()) {
      const bool remote = &in.target() != &in.local();
      try {
        wait = in.run_slice(std::chrono::milliseconds(20));
      } catch (const Error& e) {
        const bool lost = remote && &in.target() == &in.local();
        bridge.event(lost ? "link_lost" : "info", std::string("run stopped: ") + e.what());
        if (lost) bridge.refresh_scene();
      }
    }
    if (wait > Clock::duration::zero())
      std::this_thread::sleep_for(std::min<Clock::duration>(wait, std::chrono::milliseconds(5)));
  }
  bridge.poll();
}

// Loads the scene or connects before serving, so that a bad one fails before any URL is printed.
void prepare(console::Interpreter& in, const std::string& scene, const std::string& connect,
             const std::string& token_file) {
  if (!scene.empty()) in.execute("load " + scene);
  if (connect.empty()) return;
  const auto tokens = debug::tokens_from(token_file);
  in.execute("connect " + connect + (tokens.empty() ? "" : " " + tokens.front().secret));
}

}  // namespace

int view_main(Args args, std::ostream& out, std::ostream& err) {
  try {
    ArgumentReader a(args, "view");
    const std::string connect = a.text_or("--connect", "");
    const std::string log = a.text_or("--log", "");
    const std::string token_file = a.text_or("--token-file", "");
    std::string scene = a.text_or("--scene", "");
    if (!connect.empty() && (!log.empty() || !scene.empty()))
      throw UsageError("stride view: --connect takes no scene or log");
    if (connect.empty() && log.empty()) scene = a.positional("scene");
    if (!log.empty() && scene.empty()) scene = "scenes/nao_stand_controlled.xml";
    std::optional<double> seconds;
    if (a.has("--seconds")) seconds = a.number("--seconds");
    view::WebServerOptions options;
    try {
      options = view::view_server_options(a.text_or("--listen", "127.0.0.1:8080"), token_file,
                                          "--listen");
    } catch (const Error& e) {  // the command line names a wrong address or token file
      throw UsageError(e.what());
    }
    a.finish();
    console::LocalTarget local;
    std::atomic<bool> never{false};  // Ctrl-C ends the view; the page pauses runs
    console::Interpreter in(local, out);
    in.set_interactive(&never);
    std::ostringstream early;  // what loading prints comes after the URL line
    {
      view::OutputCapture hold(out, early);
      prepare(in, scene, connect, token_file);
    }
    const std::string mode = !connect.empty() ? "remote" : !log.empty() ? "log" : "sim";
    view::ViewBridge bridge(in, out, std::move(options), mode);
    out << "view: " << bridge.url() << std::endl << early.str() << std::flush;
    if (!log.empty()) {
      bridge.command("log load " + log);
      bridge.command("log goto 0");
    }
    if (!connect.empty()) bridge.command("run");  // follows the robot's stream
    serve(in, bridge, seconds);
    return kExitOk;
  } catch (const Error& e) {
    return report_error(e, err, "stride view: ");
  }
}

}  // namespace stride::cli
