#pragma once
// The client side of the debug protocol: connect and authenticate, call requests, receive stream
// samples. Single-threaded: whatever arrives while waiting for a reply (samples, old ping replies)
// is kept or discarded as it comes. Used by the console's remote target, tools and tests.
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "robot/debug/server_message.hpp"
#include "robot/debug/socket_io.hpp"
#include "robot/debug/wire.hpp"

namespace stride::debug {

// The connection is gone (closed, reset, timed out, or the server said goodbye).
class ConnectionLost : public Error {
 public:
  using Error::Error;
};

struct ClientOptions {
  double timeout = 5;              // s for connecting, the handshake and each reply
  double ping_every = 10;          // s: keeps the server's idle timeout away
  std::size_t max_samples = 8192;  // kept unread; older ones are discarded and counted
};

class DebugClient {
 public:
  // Connects and authenticates (token may be empty on loopback); throws stride::Error naming the
  // endpoint and why.
  DebugClient(const Endpoint& to, const std::string& token, ClientOptions options = {});

  const Endpoint& endpoint() const { return to_; }
  const Hello& hello() const { return hello_; }
  const Welcome& welcome() const { return welcome_; }

  // Sends `r` (its id is assigned) and waits for the reply. A reply with ok=false throws
  // stride::Error with the server's text; a lost connection throws ConnectionLost.
  std::unique_ptr<ServerMessage> call(Request r);
  // Sends without waiting; the reply is discarded when it comes.
  void send_only(Request r);
  // The next stream sample, waiting up to `timeout` s; nothing on timeout.
  std::optional<Sample> next_sample(double timeout);
  void drop_samples() { samples_.clear(); }
  // Reads what has arrived and pings when due; call it while otherwise idle.
  void keep_alive();
  std::uint64_t samples_discarded() const { return discarded_; }
  // What the robot told this client unasked since the last call (e.g. that its log stopped on a
  // full disk), one line each, oldest first.
  std::vector<std::string> take_notes();

 private:
  std::uint64_t send_request(Request& r);
  void send_payload(const std::string& payload);
  // Waits up to `timeout` s for bytes and dispatches every complete message; false on timeout.
  bool receive(double timeout);
  void dispatch(const std::string& payload);
  std::unique_ptr<ServerMessage> next_message(double timeout);  // handshake only
  void handshake(const std::string& token);
  [[noreturn]] void lost(const std::string& why);

  Endpoint to_;
  ClientOptions options_;
  Fd fd_;
  FrameReader in_{kMaxServerMessage};
  Hello hello_;
  Welcome welcome_;
  std::uint64_t next_id_ = 1;
  std::map<std::uint64_t, std::unique_ptr<ServerMessage>> replies_;
  std::set<std::uint64_t> discard_;  // replies nobody waits for
  std::deque<Sample> samples_;
  std::uint64_t discarded_ = 0;
  std::vector<std::string> notes_;  // at most kMaxNotes kept
  std::deque<std::unique_ptr<ServerMessage>> handshake_messages_;
  bool handshaking_ = true;
  double last_sent_ = 0;  // steady seconds
};

}  // namespace stride::debug
