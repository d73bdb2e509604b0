#pragma once
// What the view server's thread shares between its sessions (console/view/ internal). Sessions
// live on the server thread only; the bridge thread reaches them through posts to `io`.
#include <atomic>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/http/message.hpp>
#include <boost/beast/http/string_body.hpp>
#include <map>
#include <memory>
#include <mutex>

#include "console/view/web_server.hpp"

namespace stride::view {

class WsSession;

struct ServerState {
  explicit ServerState(WebServerOptions o) : options(std::move(o)) {}

  WebServerOptions options;

  std::mutex mutex;  // guards events
  std::vector<ClientEvent> events;
  void post_event(ClientEvent e) {
    std::lock_guard lock(mutex);
    events.push_back(std::move(e));
  }

  // Server thread only.
  std::map<std::uint64_t, std::weak_ptr<WsSession>> sessions;  // joined pages
  std::uint64_t next_id = 1;
  std::atomic<std::size_t> connections{0};
  std::atomic<std::size_t> clients{0};
  std::atomic<std::uint64_t> dropped{0};

  // Last: destroyed first, so the sessions its pending handlers own still find the above.
  boost::asio::io_context io;
  boost::asio::ip::tcp::acceptor acceptor{io};
};

// Counts a connection while it lives.
class ConnectionCount {
 public:
  explicit ConnectionCount(ServerState& s) : s_(&s) { ++s_->connections; }
  ~ConnectionCount() {
    if (s_) --s_->connections;
  }
  ConnectionCount(ConnectionCount&& o) noexcept : s_(std::exchange(o.s_, nullptr)) {}
  ConnectionCount(const ConnectionCount&) = delete;
  ConnectionCount& operator=(const ConnectionCount&) = delete;
  ConnectionCount& operator=(ConnectionCount&&) = delete;

 private:
  ServerState* s_;
};

// Serves one TCP connection's HTTP requests; hands a /ws upgrade to a WsSession.
void start_http_session(ServerState& state, boost::asio::ip::tcp::socket socket,
                        ConnectionCount count);

// Takes over a connection whose request asks for the WebSocket; `received` are the bytes that
// came after the request.
void start_ws_session(ServerState& state, boost::beast::tcp_stream stream,
                      boost::beast::http::request<boost::beast::http::string_body> request,
                      std::string received, ConnectionCount count);

// Queues `text` for a joined page (frame: may be dropped). Server thread only.
void queue_for(WsSession& session, std::string text, bool frame);

}  // namespace stride::view
