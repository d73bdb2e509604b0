#pragma once
// What the view's tests share: a started `stride view` process (its URL from its first line) and
// Beast clients for HTTP and the WebSocket whose every wait is bounded.
#include <signal.h>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <chrono>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "tests/child_process.hpp"

namespace stride::view_test {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using Json = nlohmann::json;
using namespace std::chrono_literals;

inline std::string stride_binary() {
  return std::string(STRIDE_BINARY_DIR) + "/stride";
}
inline std::string scene_path(const std::string& name) {
  return std::string(STRIDE_SOURCE_DIR) + "/scenes/" + name;
}

// `stride view <args> --listen <address>:0 --seconds 120`, running until the object goes.
class ViewProcess {
 public:
  explicit ViewProcess(std::vector<std::string> args, const std::string& address = "127.0.0.1",
                       const std::string& name = "view") {
    dir_ = test_support::fresh_path("view", name);
    std::filesystem::create_directories(dir_);
    std::vector<std::string> all{stride_binary(), "view"};
    all.insert(all.end(), args.begin(), args.end());
    for (const char* a : {"--listen", "", "--seconds", "120"}) all.emplace_back(a);
    all[all.size() - 3] = address + ":0";
    pid_ = test_support::start_process(all, dir_ / "out.txt", dir_ / "err.txt");
    const std::regex first("^view: http://[0-9.]+:([0-9]+)/\n");
    for (int i = 0; i < 600 && port_ == 0; ++i) {  // up to 60 s (a sanitized build loads slowly)
      std::smatch m;
      const std::string out = test_support::read_text(dir_ / "out.txt");
      if (std::regex_search(out, m, first))
        port_ = static_cast<unsigned short>(std::stoi(m[1]));
      else
        std::this_thread::sleep_for(100ms);
    }
  }
  ~ViewProcess() { stop(); }
  ViewProcess(const ViewProcess&) = delete;
  ViewProcess& operator=(const ViewProcess&) = delete;

  unsigned short port() const { return port_; }
  std::string out() const { return test_support::read_text(dir_ / "out.txt"); }
  std::string err() const { return test_support::read_text(dir_ / "err.txt"); }
  // SIGTERM (a clean end), then its exit code.
  int stop() {
    if (pid_ <= 0) return code_;
    ::kill(pid_, SIGTERM);
    code_ = test_support::finish_process(pid_);
    pid_ = 0;
    return code_;
  }

 private:
  std::filesystem::path dir_;
  pid_t pid_ = 0;
  int code_ = -1;
  unsigned short port_ = 0;
};

// Runs `io` until `done` or `timeout`; false on timeout.
inline bool run_until(asio::io_context& io, const bool& done, std::chrono::milliseconds timeout) {
  io.restart();
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (!done && std::chrono::steady_clock::now() < end) io.run_for(20ms);
  return done;
}

struct HttpReply {
  int status = 0;
  std::string content_type;
  std::string body;
};

// One GET (or `method`) of `target`; status 0 if no answer within 10 s.
inline HttpReply http_get(unsigned short port, const std::string& target,
                          http::verb method = http::verb::get,
                          const std::string& address = "127.0.0.1") {
  asio::io_context io;
  beast::tcp_stream stream(io);
  beast::flat_buffer buffer;
  http::request<http::empty_body> req{method, target, 11};
  req.set(http::field::host, address);
  http::response_parser<http::string_body> parser;
  parser.skip(method == http::verb::head);  // a HEAD answer has a length but no body
  parser.body_limit(64 * 1024 * 1024);
  bool done = false;
  stream.expires_after(10s);
  stream.async_connect(tcp::endpoint(asio::ip::make_address(address), port),
                       [&](beast::error_code ec) {
                         if (ec) return void(done = true);
                         http::async_write(stream, req, [&](beast::error_code ec, std::size_t) {
                           if (ec) return void(done = true);
                           http::async_read(stream, buffer, parser,
                                            [&](beast::error_code, std::size_t) { done = true; });
                         });
                       });
  run_until(io, done, 12s);
  const auto& res = parser.get();
  return {static_cast<int>(res.result_int()), std::string(res[http::field::content_type]),
          res.body()};
}

// A page's WebSocket, read message by message with a bound on every wait.
class WsClient {
 public:
  // Connects and upgrades; connected() says whether it worked.
  explicit WsClient(unsigned short port, const std::string& address = "127.0.0.1") {
    bool done = false;
    beast::get_lowest_layer(ws_).expires_after(10s);
    beast::get_lowest_layer(ws_).async_connect(
        tcp::endpoint(asio::ip::make_address(address), port), [&](beast::error_code ec) {
          if (ec) return void(done = true);
          ws_.async_handshake(address, "/ws", [&](beast::error_code ec) {
            ok_ = !ec;
            done = true;
          });
        });
    run_until(io_, done, 12s);
    beast::get_lowest_layer(ws_).expires_never();
  }
  bool connected() const { return ok_; }
  websocket::stream<beast::tcp_stream>& stream() { return ws_; }
  asio::io_context& io() { return io_; }

  // The next message, or nothing on timeout or close (closed() then says why).
  std::optional<std::string> read(std::chrono::milliseconds timeout = 10s) {
    if (!ok_) return std::nullopt;
    bool done = false;
    beast::error_code result;
    buffer_.consume(buffer_.size());
    ws_.async_read(buffer_, [&](beast::error_code ec, std::size_t) {
      result = ec;
      done = true;
    });
    if (!run_until(io_, done, timeout)) {
      beast::get_lowest_layer(ws_).cancel();
      run_until(io_, done, 2s);
      ok_ = false;
      return std::nullopt;
    }
    if (result) {
      ok_ = false;
      close_reason_ = ws_.reason().code;
      return std::nullopt;
    }
    return beast::buffers_to_string(buffer_.data());
  }

  // The next message of `type` (others skipped), as JSON; null on timeout or close.
  Json read_type(const std::string& type, std::chrono::milliseconds timeout = 10s) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          end - std::chrono::steady_clock::now());
      const auto text = read(std::max(left, 1ms));
      if (!text) return nullptr;
      Json j = Json::parse(*text, nullptr, false);
      if (j.is_object() && j.value("type", "") == type) return j;
    }
    return nullptr;
  }

  bool send(const std::string& text) {
    if (!ok_) return false;
    bool done = false;
    beast::error_code result;
    ws_.text(true);
    ws_.async_write(asio::buffer(text), [&](beast::error_code ec, std::size_t) {
      result = ec;
      done = true;
    });
    return run_until(io_, done, 10s) && !result;
  }
  // Close code the server sent (valid after read() returned nothing on a close).
  int close_code() const { return close_reason_; }

 private:
  asio::io_context io_;
  websocket::stream<beast::tcp_stream> ws_{io_};
  beast::flat_buffer buffer_;
  bool ok_ = false;
  int close_reason_ = 0;
};

// A reply to a `cmd` with `id` (other messages skipped).
inline Json command(WsClient& c, int id, const std::string& line,
                    std::chrono::milliseconds timeout = 30s) {
  c.send(Json{{"op", "cmd"}, {"id", id}, {"line", line}}.dump());
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < end) {
    Json r = c.read_type("reply", std::chrono::duration_cast<std::chrono::milliseconds>(
                                      end - std::chrono::steady_clock::now()));
    if (r.is_null() || r.value("id", -1) == id) return r;
  }
  return nullptr;
}

}  // namespace stride::view_test
