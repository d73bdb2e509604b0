#pragma once
// The control loop's half of the debug server: at each frame boundary it applies the requests that
// change the robot (set, mr, dr, log start/stop) exactly as a console command between frames, and
// publishes a snapshot of the slots the server's clients want. Bounded work per frame; it never
// waits for the server thread.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "robot/debug/exchange.hpp"
#include "robot/runtime/runtime.hpp"

namespace stride::debug {

// What the runtime's debug requests printed (lines) and the first request to pause ("" none).
struct DebugText {
  std::vector<std::string> lines;
  std::string stop;
};

class LoopSide final : public FrameBoundary {
 public:
  // The loop side takes the runtime's debug output after every frame and streams it to the
  // subscribed clients. `keep_debug_output`: the loop's own console shows it too (`serve` in a
  // console), so it is also kept for take_kept_debug_output().
  LoopSide(Exchange& exchange, std::string robot_name, bool keep_debug_output = false);
  void after_frame(Runtime& runtime) override { service(runtime, true); }
  // A client's log of that runtime stops (told with a note); the next runtime gets a catalogue.
  void detached(Runtime& runtime) override;
  // Between frames while the loop is paused (a console's `serve` while it is not running).
  void idle(Runtime& runtime) { service(runtime, false); }

  // The debug output taken from the runtime since the last call (with keep_debug_output).
  DebugText take_kept_debug_output();
  // `restart` requests are refused unless the loop's owner polls take_restart() and does them.
  void allow_restart() { restartable_ = true; }
  bool take_restart() { return std::exchange(restart_, false); }

  static constexpr int kRequestsPerFrame = 16;        // of which at most one list or report
  static constexpr std::size_t kMaxHeldLines = 1000;  // per client stream; more are counted

 private:
  void service(Runtime& rt, bool new_frame);
  void refresh_catalogue(Runtime& rt);
  LoopReply apply(Runtime& rt, LoopRequest& r);
  bool take_request(LoopRequest& in);  // the held one first, then the ring's next
  bool wanted_changed();
  bool publish(bool new_frame);
  std::unique_ptr<Snapshot> take_buffer();  // a ready one, a spent one, or a new one
  void encode_wanted(Snapshot& s);
  void take_debug_output(Runtime& rt);
  bool push_catalogue();
  void start_log(Runtime& rt, const LoopRequest& in);
  void write_log();
  void end_log(const std::string& why);
  bool push_note();

  Exchange& x_;
  std::string robot_;
  const Runtime* runtime_ = nullptr;
  bool restartable_ = false;
  bool restart_ = false;  // a client asked for a restart
  std::uint64_t plan_generation_ = 0;
  std::uint64_t generation_ = 0;
  std::shared_ptr<const Catalogue> pending_catalogue_;  // not yet taken by the ring
  std::vector<const Slot*> slots_;
  const FrameInfo* frame_info_ = nullptr;
  std::array<std::uint64_t, kMaxSlots / 64> wanted_{};  // bits of the last published snapshot
  // The log a client started (log_start): the debug server's own, so that its failure (a full
  // disk) stops that log and tells that client, and never leaves the runtime's step.
  std::unique_ptr<LogWriter> log_;
  std::string log_file_;
  std::uint64_t log_client_ = 0;
  std::optional<LoopReply> pending_note_;  // why the log stopped, not yet taken by the ring
  std::vector<LoopReply> replies_;         // of this boundary, sent after its snapshot
  // A list or report taken after another in the same boundary: each one builds the whole robot
  // state, so they go one a frame and a burst (a view opening) never stretches one boundary.
  std::optional<LoopRequest> held_;
  // Buffers the server had no room for, kept for the next publish: `spent` has one producer.
  static constexpr std::size_t kReadyBuffers = 3;
  std::vector<std::unique_ptr<Snapshot>> ready_;
  std::shared_ptr<const RobotListing> listing_;  // made at a plan's first list or report
  std::pair<const Runtime*, std::uint64_t> listing_of_{nullptr, 0};  // that runtime and plan
  DebugText pending_;  // to go with the next snapshot streamed
  std::uint64_t pending_dropped_ = 0;
  bool keep_ = false;
  DebugText kept_;
  std::uint64_t kept_dropped_ = 0;
};

// What `list` shows that only a new module plan changes, read from the runtime between frames.
std::shared_ptr<const RobotListing> robot_listing(const Runtime& rt);
// Everything `list` and `report` show: `listing` (robot_listing of this plan) and what changes
// every frame; `log` is the one being recorded for a client (or null).
RobotState robot_state(const Runtime& rt, const std::string& robot,
                       std::shared_ptr<const RobotListing> listing, const std::string& log_file,
                       const LogWriter* log);

}  // namespace stride::debug
