// One page's WebSocket: the token handshake when one is needed (PROTOCOL.md), then its messages
// to the bridge and a bounded queue of what the bridge sends it.
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <deque>
#include <sstream>
#include <variant>

#include "console/view/server_state.hpp"
#include "console/view/view_message.hpp"
#include "robot/core/error.hpp"

namespace stride::view {

namespace beast = boost::beast;
namespace websocket = beast::websocket;
namespace http = beast::http;

namespace {

std::string hex(std::string_view bytes) {
  static constexpr char digits[] = "0123456789abcdef";
  std::string out;
  for (unsigned char c : bytes) {
    out += digits[c >> 4];
    out += digits[c & 15];
  }
  return out;
}

}  // namespace

class WsSession : public std::enable_shared_from_this<WsSession> {
 public:
  WsSession(ServerState& s, beast::tcp_stream stream, ConnectionCount count)
      : s_(s), ws_(std::move(stream)), count_(std::move(count)) {}

  ~WsSession() {
    if (!joined_) return;
    --s_.clients;
    s_.post_event({ClientEvent::Kind::Left, id_, "", false});
  }

  void accept(http::request<http::string_body> req, std::string received) {
    boost::system::error_code ignored;
    beast::get_lowest_layer(ws_).socket().set_option(
        boost::asio::socket_base::send_buffer_size(s_.options.send_buffer), ignored);
    ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    ws_.read_message_max(s_.options.max_message);
    // The request again with what followed it: Beast reads the frames among them after it.
    std::ostringstream raw;
    raw << req;
    handshake_ = raw.str() + received;
    ws_.async_accept(boost::asio::buffer(handshake_),
                     [self = shared_from_this()](beast::error_code ec) {
                       if (!ec) self->on_accept();
                     });
  }

  void queue(std::string text, bool frame) {
    if (closing_) return;
    if (frame) {
      if (frames_queued_ >= s_.options.frame_backlog) {
        ++dropped_;
        ++s_.dropped;
        return;
      }
      // The page's own count goes first: {"type":"frame",... -> {"dropped":N,"type":"frame",...
      text.insert(1, "\"dropped\":" + std::to_string(dropped_) + ",");
      ++frames_queued_;
    } else if (queue_.size() - frames_queued_ >= s_.options.control_backlog) {
      closing_ = true;  // the page stopped reading what may not be dropped: cut it off
      beast::get_lowest_layer(ws_).close();
      return;
    }
    queue_.push_back({std::move(text), frame});
    if (!writing_) write_next();
  }

 private:
  void on_accept() {
    if (s_.clients.load() >= s_.options.max_clients)
      return close_with(websocket::close_code::try_again_later);
    id_ = s_.next_id++;
    if (s_.options.tokens.empty()) return join(false);
    nonce_ = hex(debug::random_nonce());
    queue("{\"type\":\"auth\",\"nonce\":\"" + nonce_ + "\"}", false);
    read();
  }

  void join(bool read_only) {
    joined_ = true;
    ++s_.clients;
    s_.sessions[id_] = weak_from_this();
    s_.post_event({ClientEvent::Kind::Joined, id_, "", read_only});
    if (nonce_.empty()) read();
  }

  void read() {
    ws_.async_read(buffer_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      self->on_read(ec);
    });
  }

  void on_read(beast::error_code ec) {
    if (ec) return;  // closed, timed out, too big (Beast answers 1009) or malformed
    std::string text = beast::buffers_to_string(buffer_.data());
    buffer_.consume(buffer_.size());
    if (!joined_) {
      if (!ws_.got_text() || !authenticate(text))
        return close_with(websocket::close_code::policy_error);
    } else {
      s_.post_event({ClientEvent::Kind::Message, id_, std::move(text), false});
    }
    read();
  }

  // The page's proof of a token (PROTOCOL.md); on success it joins.
  bool authenticate(const std::string& text) {
    AuthRequest auth;
    try {
      const ViewRequest r = decode_view_message(text);
      if (!std::holds_alternative<AuthRequest>(r)) return false;
      auth = std::get<AuthRequest>(r);
    } catch (const Error&) {
      return false;
    }
    for (const debug::Token& t : s_.options.tokens) {
      const std::string expected =
          hex(debug::keyed_hash(t.secret, "stride-view-1 client" + nonce_ + auth.nonce));
      if (!debug::same_proof(expected, auth.proof)) continue;
      const std::string server =
          hex(debug::keyed_hash(t.secret, "stride-view-1 server" + nonce_ + auth.nonce));
      queue(std::string("{\"type\":\"auth_ok\",\"proof\":\"") + server +
                "\",\"read_only\":" + (t.read_only ? "true" : "false") + "}",
            false);
      join(t.read_only);
      return true;
    }
    return false;
  }

  void write_next() {
    writing_ = true;
    ws_.text(true);
    ws_.async_write(
        boost::asio::buffer(queue_.front().text),
        [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_write(ec); });
  }

  void on_write(beast::error_code ec) {
    writing_ = false;
    if (queue_.front().frame) --frames_queued_;
    queue_.pop_front();
    if (ec) {
      closing_ = true;
      return;
    }
    if (pending_close_) return close_with(*pending_close_);
    if (!queue_.empty()) write_next();
  }

  // A close handshake with `code` (after the write in progress, if any).
  void close_with(websocket::close_code code) {
    if (writing_) {
      pending_close_ = code;
      return;
    }
    closing_ = true;
    ws_.async_close(code, [self = shared_from_this()](beast::error_code) {});
  }

  struct Outgoing {
    std::string text;
    bool frame = false;
  };

  ServerState& s_;
  websocket::stream<beast::tcp_stream> ws_;
  ConnectionCount count_;
  beast::flat_buffer buffer_;
  std::deque<Outgoing> queue_;
  std::size_t frames_queued_ = 0;
  std::uint64_t dropped_ = 0;
  std::uint64_t id_ = 0;
  std::string nonce_;      // hex; empty: no token needed
  std::string handshake_;  // the upgrade request and the bytes after it
  bool joined_ = false, writing_ = false, closing_ = false;
  std::optional<websocket::close_code> pending_close_;
};

void start_ws_session(ServerState& state, beast::tcp_stream stream,
                      http::request<http::string_body> request, std::string received,
                      ConnectionCount count) {
  std::make_shared<WsSession>(state, std::move(stream), std::move(count))
      ->accept(std::move(request), std::move(received));
}

void queue_for(WsSession& session, std::string text, bool frame) {
  session.queue(std::move(text), frame);
}

}  // namespace stride::view
