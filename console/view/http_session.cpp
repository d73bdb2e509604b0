// One TCP connection's HTTP requests: the page's files (GET/HEAD), 404/405/431 otherwise, and the
// hand-over of a /ws upgrade to the WebSocket session.
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket/rfc6455.hpp>
#include <fstream>
#include <optional>
#include <sstream>

#include "console/view/server_state.hpp"

namespace stride::view {

namespace beast = boost::beast;
namespace http = beast::http;
using tcp = boost::asio::ip::tcp;

namespace {

constexpr std::size_t kMaxHeader = 8 * 1024;
constexpr std::uintmax_t kMaxFile = 32 * 1024 * 1024;

using Request = http::request<http::string_body>;
using Response = http::response<http::string_body>;

Response plain(http::status status, const Request& req, const std::string& text) {
  Response r{status, req.version()};
  r.set(http::field::content_type, "text/plain; charset=utf-8");
  r.set(http::field::cache_control, "no-store");
  r.body() = text + "\n";
  r.keep_alive(req.keep_alive());
  r.prepare_payload();
  return r;
}

Response answer(const WebRoots& roots, const Request& req) {
  if (req.method() != http::verb::get && req.method() != http::verb::head)
    return plain(http::status::method_not_allowed, req, "only GET and HEAD");
  const std::string_view target(req.target().data(), req.target().size());
  const auto file = resolve_web_path(roots, target);
  std::error_code ec;
  if (!file || std::filesystem::file_size(*file, ec) > kMaxFile || ec)
    return plain(http::status::not_found, req, "not found");
  std::ifstream in(*file, std::ios::binary);
  std::ostringstream body;
  body << in.rdbuf();
  if (!in) return plain(http::status::not_found, req, "not found");
  Response r{http::status::ok, req.version()};
  r.set(http::field::content_type, std::string(mime_type(*file)));
  r.set(http::field::cache_control, "no-cache");
  r.set("X-Content-Type-Options", "nosniff");
  r.body() = body.str();
  r.keep_alive(req.keep_alive());
  r.prepare_payload();
  if (req.method() == http::verb::head) r.body().clear();  // keeps Content-Length
  return r;
}

class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(ServerState& s, tcp::socket socket, ConnectionCount count)
      : s_(s), stream_(std::move(socket)), count_(std::move(count)) {}

  void read() {
    parser_.emplace();
    parser_->header_limit(kMaxHeader);
    parser_->body_limit(kMaxHeader);
    stream_.expires_after(s_.options.request_timeout);
    http::async_read(
        stream_, buffer_, *parser_,
        [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_read(ec); });
  }

 private:
  void on_read(beast::error_code ec) {
    if (ec == http::error::header_limit || ec == http::error::body_limit) {
      Request req;
      return write(plain(http::status::request_header_fields_too_large, req, "request too large"),
                   true);
    }
    if (ec) return close();
    Request req = parser_->release();
    const std::string_view target(req.target().data(), req.target().size());
    if (beast::websocket::is_upgrade(req) && target.substr(0, target.find('?')) == "/ws") {
      stream_.expires_never();
      // Frames a page sent right behind its request are in buffer_: the session reads them first.
      return start_ws_session(s_, std::move(stream_), std::move(req),
                              beast::buffers_to_string(buffer_.data()), std::move(count_));
    }
    const bool last = !req.keep_alive();
    write(answer(s_.options.roots, req), last);
  }

  void write(Response r, bool last) {
    response_ = std::make_shared<Response>(std::move(r));
    http::async_write(stream_, *response_,
                      [self = shared_from_this(), last](beast::error_code ec, std::size_t) {
                        if (ec || last) return self->close();
                        self->read();
                      });
  }

  void close() {
    beast::error_code ignored;
    stream_.socket().shutdown(tcp::socket::shutdown_both, ignored);
    stream_.close();
  }

  ServerState& s_;
  beast::tcp_stream stream_;
  ConnectionCount count_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  std::shared_ptr<Response> response_;
};

}  // namespace

void start_http_session(ServerState& state, tcp::socket socket, ConnectionCount count) {
  std::make_shared<HttpSession>(state, std::move(socket), std::move(count))->read();
}

}  // namespace stride::view
