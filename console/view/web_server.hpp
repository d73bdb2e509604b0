#pragma once
// The view's HTTP + WebSocket server: Boost.Beast on a thread of its own. It serves the page's
// files and one WebSocket per page; the bridge's thread takes what pages sent (take_events) and
// queues what they get (send, broadcast, broadcast_frame). A page that reads slowly loses frame
// messages (counted per page), never others; one that lets those pile up is disconnected.
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "console/view/static_files.hpp"
#include "robot/debug/auth.hpp"

namespace stride::view {

struct WebServerOptions {
  std::string address = "127.0.0.1";
  unsigned short port = 8080;  // 0: any free port (port() says which)
  WebRoots roots;
  std::vector<debug::Token> tokens;   // non-empty: a WebSocket must prove one (PROTOCOL.md)
  std::size_t max_clients = 32;       // WebSockets; the next is closed with 1013
  std::size_t max_connections = 128;  // TCP connections of any kind; the next is closed at once
  std::size_t max_message = 64 * 1024;
  std::size_t frame_backlog = 16;      // frames queued for a page before new ones are dropped
  std::size_t control_backlog = 4096;  // other messages queued before the page is cut off
  int send_buffer = 128 * 1024;        // a page's socket send buffer: a slow page soon drops frames
  std::chrono::seconds request_timeout{10};  // a connection's time to send a full HTTP request
};

struct ClientEvent {
  enum class Kind { Joined, Message, Left };
  Kind kind = Kind::Message;
  std::uint64_t client = 0;
  std::string text;        // Message: the text frame
  bool read_only = false;  // Joined: proved a read-only token
};

struct ServerState;

class WebServer {
 public:
  // Binds and starts serving; throws stride::Error naming the address on failure.
  explicit WebServer(WebServerOptions options);
  ~WebServer();
  WebServer(const WebServer&) = delete;
  WebServer& operator=(const WebServer&) = delete;

  unsigned short port() const { return port_; }
  std::string url() const;  // http://address:port/

  // Joins, messages and departures since the last call, in order.
  std::vector<ClientEvent> take_events();
  void send(std::uint64_t client, std::string text);  // never dropped
  void broadcast(std::string text);                   // to every page, never dropped
  // A frame (a JSON object text): each page gets it with its own "dropped" count first, or
  // drops it when it still has frame_backlog frames to read.
  void broadcast_frame(std::string text);
  std::size_t clients() const;
  std::uint64_t dropped() const;  // frames dropped, all pages together

 private:
  std::unique_ptr<ServerState> state_;
  unsigned short port_ = 0;
  std::thread thread_;
};

// Whether clients on `address` may skip the token: 127.0.0.0/8 and ::1.
bool loopback_address(const std::string& address);

}  // namespace stride::view
