#pragma once
// What the control loop and the debug server's thread share: two request/reply rings, a ring of
// frame snapshots with a ring to hand their buffers back, and a few atomics. Everything is
// bounded; neither side ever waits for the other (spsc_ring.hpp).
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "robot/debug/protocol.hpp"
#include "robot/debug/spsc_ring.hpp"
#include "robot/framework/plan.hpp"
#include "robot/framework/slot.hpp"

namespace stride::debug {

inline constexpr std::size_t kMaxSlots = 512;  // representations + parameter modules served

// Names and type descriptions of everything on the blackboard, in a fixed order: the indices
// used by snapshots and the wanted mask. Rebuilt by the loop after every re-plan.
struct Catalogue {
  std::uint64_t generation = 0;
  std::vector<std::string> keys;        // "representation:X" then "module:X"
  std::vector<std::string> desc_bytes;  // write_type_desc of each
};

// A frame's values of the wanted slots. The loop only copies them (copies); the server thread
// encodes them as the log does (bytes, parts) when it takes the snapshot: encoding is several
// times a copy's cost and would otherwise lengthen every streamed frame.
struct Snapshot {
  std::uint64_t generation = 0;  // the catalogue it indexes
  std::int64_t frame = 0;
  double time = 0;
  std::uint64_t loop_frames = 0;  // Exchange::frames when made: the loop has not moved on while
                                  // this equals Exchange::frames
  bool new_frame = false;  // false: republished between frames (after a change, or while paused)
  // Debug output of the frames since the last snapshot streamed (new frames only): printed lines,
  // the first request to pause, and every debug:X.y value (few: those of switched-on requests).
  std::vector<std::string> debug_lines;
  std::string debug_stop;
  std::vector<std::pair<std::string, double>> debug_values;
  std::vector<std::unique_ptr<Slot>> copies;  // per slot: the value at the boundary (or stale)
  // The loop writes only these two (the slots it copied); every line of the rest was last written
  // by the server thread, and writing it again from the loop's core would pull it across.
  std::uint32_t slot_count = 0;
  std::vector<std::uint32_t> copied;
  std::string bytes;                                           // server thread
  std::vector<std::pair<std::uint32_t, std::uint32_t>> parts;  // server: per slot offset, size
  static constexpr std::uint32_t kAbsent = 0xffffffffu;
};

// Encodes the copied values into bytes and parts (the server thread, before anything reads them).
void encode_copies(Snapshot& s);

// What the loop knows and the server formats for `list` and `report`.
// What `list` shows that changes only with the module plan: made once a plan, shared by every
// list and report until the next one (building it takes tens of microseconds of the loop).
struct RobotListing {
  std::vector<std::string> representations, providers;
  std::vector<std::vector<std::string>> available;
  std::vector<std::string> parameter_modules, module_order;
  std::vector<ModuleDeclaration> declarations;  // every registered module's requires/provides
  std::vector<std::string> debug_requests;
};

struct RobotState {
  std::string robot;
  double period = 0;
  std::int64_t frame = 0;
  double time = 0;
  std::shared_ptr<const RobotListing> listing = std::make_shared<const RobotListing>();
  std::vector<std::int64_t> module_ns;    // ModuleTimes of the last frame, in module order
  std::vector<std::string> debug_states;  // off, on, quiet; as listing->debug_requests
  std::string log_file;                   // being recorded ("" none)
  std::uint64_t log_frames = 0;
};

struct LoopRequest {
  std::uint64_t client = 0;
  Request request;
  std::string path;  // LogStart: the file in the log directory
};

struct LoopReply {
  std::uint64_t client = 0;
  std::uint64_t id = 0;
  Op op = Op::Ping;
  std::string error;         // empty: done
  std::string text;          // Mr: the new provider; LogStart/LogStop: the file; Value: the value
  std::uint64_t frames = 0;  // LogStop: frames in the closed log
  bool json = false;         // Report
  std::shared_ptr<const RobotState> state;  // List, Report
};

// Loop -> server, in one ring so that order holds: a reply always follows the snapshot that
// shows its effect (a `get` after a `set` sees the new value).
// A Note is no reply: reply.text tells reply.client that its log stopped by itself (a full disk).
struct LoopMessage {
  enum class Kind { Catalogue, Snapshot, Reply, Note };
  Kind kind = Kind::Reply;
  std::shared_ptr<const Catalogue> catalogue;
  std::unique_ptr<Snapshot> snapshot;
  LoopReply reply;
};

struct Exchange {
  SpscRing<LoopRequest, 256> requests;            // server -> loop
  SpscRing<LoopMessage, 64> to_server;            // loop -> server
  SpscRing<std::unique_ptr<Snapshot>, 64> spent;  // server -> loop (buffers to reuse)

  // Written by the server thread (seldom: when they change), read by the loop every frame.
  alignas(64) std::array<std::atomic<std::uint64_t>, kMaxSlots / 64> wanted{};  // slot bits needed
  std::atomic<std::uint64_t> wanted_generation{0};  // catalogue the bits index
  std::atomic<bool> clients{false};                 // anyone connected: snapshots are worth making
  // Written by the loop; on lines of their own, so the loop's writes every frame do not take
  // away the server's lines above.
  alignas(64) std::atomic<std::uint64_t> frames{0};  // frames the loop has passed
  std::atomic<double> period{0};                     // the loop's control period
  std::atomic<std::uint64_t> snapshots_lost{0};      // full ring: the server thread fell behind
  std::atomic<std::uint64_t> loop_allocations{0};    // snapshot buffers and copies the loop made
};

}  // namespace stride::debug
