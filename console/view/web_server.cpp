#include "console/view/web_server.hpp"

#include <boost/asio/ip/address.hpp>
#include <boost/asio/post.hpp>

#include "console/view/server_state.hpp"
#include "robot/core/error.hpp"

namespace stride::view {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;

namespace {

void accept_next(ServerState& s) {
  s.acceptor.async_accept([&s](boost::system::error_code ec, tcp::socket socket) {
    if (ec == asio::error::operation_aborted) return;
    if (!ec) {
      if (s.connections.load() >= s.options.max_connections) {
        boost::system::error_code ignored;
        socket.close(ignored);  // over the limit: refused at once
      } else {
        start_http_session(s, std::move(socket), ConnectionCount(s));
      }
    }
    accept_next(s);
  });
}

// Runs `f(session)` on the server thread for each joined page (or only `client`).
template <class F>
void for_sessions(ServerState& s, F f) {
  for (auto it = s.sessions.begin(); it != s.sessions.end();) {
    if (auto p = it->second.lock()) {
      f(*p);
      ++it;
    } else {
      it = s.sessions.erase(it);
    }
  }
}

}  // namespace

bool loopback_address(const std::string& address) {
  boost::system::error_code ec;
  const auto a = asio::ip::make_address(address, ec);
  return !ec && a.is_loopback();
}

WebServer::WebServer(WebServerOptions options)
    : state_(std::make_unique<ServerState>(std::move(options))) {
  ServerState& s = *state_;
  const std::string where = s.options.address + ":" + std::to_string(s.options.port);
  boost::system::error_code ec;
  const auto address = asio::ip::make_address(s.options.address, ec);
  if (ec) throw Error("view: '" + s.options.address + "' is not an IP address");
  const tcp::endpoint endpoint(address, s.options.port);
  s.acceptor.open(endpoint.protocol(), ec);
  if (!ec) s.acceptor.set_option(asio::socket_base::reuse_address(true), ec);
  if (!ec) s.acceptor.bind(endpoint, ec);
  if (!ec) s.acceptor.listen(asio::socket_base::max_listen_connections, ec);
  if (ec) throw Error("view: cannot listen on " + where + " (" + ec.message() + ")");
  port_ = s.acceptor.local_endpoint().port();
  accept_next(s);
  thread_ = std::thread([&s] { s.io.run(); });
}

WebServer::~WebServer() {
  state_->io.stop();
  thread_.join();
}

std::string WebServer::url() const {
  const std::string& a = state_->options.address;
  const std::string host = a.find(':') != std::string::npos ? "[" + a + "]" : a;
  return "http://" + host + ":" + std::to_string(port_) + "/";
}

std::vector<ClientEvent> WebServer::take_events() {
  std::lock_guard lock(state_->mutex);
  return std::exchange(state_->events, {});
}

void WebServer::send(std::uint64_t client, std::string text) {
  ServerState& s = *state_;
  asio::post(s.io, [&s, client, text = std::move(text)]() mutable {
    const auto it = s.sessions.find(client);
    if (it == s.sessions.end()) return;
    if (auto p = it->second.lock()) queue_for(*p, std::move(text), false);
  });
}

void WebServer::broadcast(std::string text) {
  ServerState& s = *state_;
  asio::post(s.io, [&s, text = std::move(text)] {
    for_sessions(s, [&](WsSession& w) { queue_for(w, text, false); });
  });
}

void WebServer::broadcast_frame(std::string text) {
  ServerState& s = *state_;
  asio::post(s.io, [&s, text = std::move(text)] {
    for_sessions(s, [&](WsSession& w) { queue_for(w, text, true); });
  });
}

std::size_t WebServer::clients() const {
  return state_->clients.load();
}
std::uint64_t WebServer::dropped() const {
  return state_->dropped.load();
}

}  // namespace stride::view
