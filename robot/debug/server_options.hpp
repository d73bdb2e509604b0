#pragma once
// How a debug server listens, whom it lets in and how much it lets each client have.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "robot/debug/auth.hpp"
#include "robot/debug/socket_io.hpp"

namespace stride::debug {

struct ServerOptions {
  Endpoint listen;                 // loopback unless tokens are given
  std::vector<Token> tokens;       // empty: no authentication (loopback only)
  std::string log_dir = ".";       // where clients' `log start` writes and `log save` reads
  std::string robot;               // the name clients see
  bool keep_debug_output = false;  // the loop's own console shows debug output too (`serve`)
  std::size_t max_clients = 16;    // authenticated (admitted) clients
  // Connections not yet authenticated have slots of their own, so that peers which never log in
  // cannot keep a team's console out: at most this many in all and from one address; a new one
  // beyond either closes the oldest (of that address, or of the address with the most).
  std::size_t max_pending = 32;
  std::size_t max_pending_per_address = 8;
  double handshake_timeout = 2;  // s from accept to welcome
  double idle_timeout = 60;      // s without a message from a client (clients ping every 10 s)
  double request_rate = 500;     // requests per second per client, as a burst of as many
  std::size_t stream_queue = 256 * 1024;      // bytes queued to a client before samples drop
  std::size_t reply_queue = 4 * 1024 * 1024;  // bytes queued before its requests are not read
  // One line per event (connections, rejections); default: standard error.
  std::function<void(const std::string&)> log;
};

struct ServerStats {
  std::uint64_t clients = 0;   // connected and admitted now
  std::uint64_t accepted = 0;  // connections accepted so far
  std::uint64_t rejected = 0;  // refused or dropped: limits, tokens, bad messages, timeouts
  std::uint64_t requests = 0;
  std::uint64_t samples_sent = 0;
  std::uint64_t samples_dropped = 0;   // slow clients' lost samples (they are told)
  std::uint64_t snapshots_lost = 0;    // frames the server thread fell behind on
  std::uint64_t loop_allocations = 0;  // snapshot buffers and value copies the loop allocated
};

}  // namespace stride::debug
