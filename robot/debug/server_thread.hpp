#pragma once
// The debug server's own thread (internal to server.cpp): accepts and authenticates clients, reads
// their requests, answers what it can from the latest snapshot, passes the rest to the loop, and
// streams samples. It polls sockets and the exchange; it never blocks on a client.
#include <atomic>
#include <chrono>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "robot/debug/exchange.hpp"
#include "robot/debug/log_directory.hpp"
#include "robot/debug/served_values.hpp"
#include "robot/debug/server_options.hpp"
#include "robot/debug/socket_io.hpp"
#include "robot/debug/wire.hpp"

namespace stride::debug {

using Clock = std::chrono::steady_clock;

struct Subscription {
  std::vector<StreamKey> keys;
  std::vector<std::string> debug_keys;  // debug:X.y keys, streamed as numbers
  std::vector<std::string> lines;       // debug output waiting for the next sample sent
  std::string stop;
  std::uint64_t lines_dropped = 0;
  std::uint64_t every = 1;
  std::int64_t from = 0;  // first sampled frame
  std::uint64_t dropped = 0;
  bool due(std::int64_t frame) const {
    return frame >= from && (frame - from) % static_cast<std::int64_t>(every) == 0;
  }
  std::uint64_t due_between(std::int64_t first, std::int64_t last) const;  // inclusive
};

struct ClientSession {
  enum class State { Greeting, Ready, Closing };
  std::uint64_t id = 0;
  Fd fd;
  std::string address;
  std::uint32_t peer = 0;  // IPv4 address, network order: pending slots are counted per address
  State state = State::Greeting;
  std::string nonce;  // ours, for its proof
  bool read_only = false;
  bool logged_rejection = false;
  FrameReader in{kMaxClientMessage};
  std::deque<std::string> out;  // framed messages
  std::size_t out_bytes = 0;
  std::size_t out_offset = 0;  // of out.front() already sent
  Clock::time_point deadline;  // handshake or closing
  Clock::time_point last_heard;
  double bucket = 0;  // request tokens
  Clock::time_point bucket_time;
  int in_flight = 0;  // requests waiting for the loop
  std::optional<Subscription> sub;
};

class ServerThread {
 public:
  ServerThread(ServerOptions& options, Exchange& exchange, Fd listener, Fd wake);
  ~ServerThread();
  void run(const std::atomic<bool>& stop);
  ServerStats stats() const;

 private:
  struct Parked {
    std::uint64_t client;
    Request request;
    Clock::time_point deadline;
  };

  // server_thread.cpp: connections
  void accept_clients(Clock::time_point now);
  void make_pending_room(std::uint32_t peer, Clock::time_point now);
  void evict(ClientSession& c, const std::string& why, Clock::time_point now);
  void read_client(ClientSession& c, Clock::time_point now);
  void write_client(ClientSession& c);
  void check_timeouts(ClientSession& c, Clock::time_point now);
  void on_message(ClientSession& c, const std::string& payload, Clock::time_point now);
  void on_auth(ClientSession& c, const AuthMessage& a, Clock::time_point now);
  void admit(ClientSession& c, bool read_only, const std::string& proof);
  std::string too_many() const;
  void reject(ClientSession& c, const std::string& why, Clock::time_point now);
  void say_goodbye(ClientSession& c, const std::string& why, Clock::time_point now);
  void drop(ClientSession& c, const std::string& why);
  void send(ClientSession& c, const std::string& payload);
  bool send_sample(ClientSession& c, const std::string& payload);
  void log(const std::string& line, Clock::time_point now);
  void shutdown();

  // server_requests.cpp: requests, the loop's replies, streams
  void on_request(ClientSession& c, Request& r, Clock::time_point now);
  void to_loop(ClientSession& c, Request& r);
  bool try_answer(ClientSession& c, const Request& r);  // false: wait for a snapshot
  void answer_get(ClientSession& c, const Request& r, std::size_t slot);
  void answer_subscribe(ClientSession& c, const Request& r, const std::vector<std::size_t>& slots);
  void answer_log(ClientSession& c, const Request& r);
  void take_from_loop();
  void on_catalogue(std::shared_ptr<const Catalogue> c);
  void on_snapshot(std::unique_ptr<Snapshot> s);
  void on_loop_reply(LoopReply& r);
  void on_note(const LoopReply& r);  // a client's log stopped by itself
  void stream(Snapshot& s);
  void hold_debug_output(Subscription& sub, const Snapshot& s);
  void fill_debug_output(Sample& sample, Subscription& sub, const Snapshot& s);
  void retry_parked(Clock::time_point now);
  void publish_wanted(Clock::time_point now);
  ClientSession* find(std::uint64_t id);

  ServerOptions& options_;
  Exchange& x_;
  Fd listener_;
  Fd wake_;
  LogDirectory logs_;
  std::map<std::uint64_t, std::unique_ptr<ClientSession>> clients_;
  std::uint64_t next_id_ = 1;
  std::unique_ptr<ServedCatalogue> catalogue_;
  std::unique_ptr<Snapshot> latest_;  // of catalogue_'s generation
  std::int64_t last_frame_ = -1;
  std::vector<Parked> parked_;
  std::map<std::string, Clock::time_point> recent_gets_;  // root key -> last get
  std::array<std::uint64_t, kMaxSlots / 64> wanted_{};
  std::uint64_t wanted_generation_ = 0;

  Clock::time_point log_window_;
  int log_lines_ = 0;
  std::uint64_t log_suppressed_ = 0;

  std::atomic<std::uint64_t> accepted_{0}, rejected_{0}, requests_{0}, sent_{0}, dropped_{0};
  std::atomic<std::uint64_t> admitted_now_{0};
};

}  // namespace stride::debug
