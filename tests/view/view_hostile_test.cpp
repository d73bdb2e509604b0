// Hostile pages against `stride view`: malformed WebSocket frames and oversized messages close
// only their own connection; a page that stops reading loses frames (counted) while the others
// and the simulation go on; 100 connections at once are served or cleanly refused.
#include <gtest/gtest.h>

#include "simulator/simulation.hpp"
#include "tests/view/view_client.hpp"

namespace stride::view_test {
namespace {

constexpr const char* kScene = "nao_stand_controlled.xml";

// A TCP connection that upgrades by hand, then writes whatever bytes a test gives it.
class RawPage {
 public:
  explicit RawPage(unsigned short port, bool upgrade = true) {
    bool done = false;
    stream_.expires_after(10s);
    stream_.async_connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port),
                          [&](beast::error_code ec) {
                            ok_ = !ec;
                            done = true;
                          });
    run_until(io_, done, 12s);
    if (!upgrade) return;
    write(
        "GET /ws HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
        "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n");
  }
  void write(const std::string& bytes) {
    bool done = false;
    stream_.expires_after(10s);
    asio::async_write(stream_, asio::buffer(bytes), [&](beast::error_code ec, std::size_t) {
      ok_ = ok_ && !ec;
      done = true;
    });
    run_until(io_, done, 12s);
  }
  // Everything the server sends until it closes (or `timeout`); `closed` says which.
  std::string read_all(std::chrono::milliseconds timeout, bool& closed) {
    std::string got;
    char chunk[4096];
    const auto end = std::chrono::steady_clock::now() + timeout;
    closed = false;
    while (!closed && std::chrono::steady_clock::now() < end) {
      bool done = false;
      stream_.expires_after(timeout);
      stream_.async_read_some(asio::buffer(chunk), [&](beast::error_code ec, std::size_t n) {
        got.append(chunk, n);
        closed = ec.failed();
        done = true;
      });
      if (!run_until(io_, done, timeout)) break;
    }
    return got;
  }

 private:
  asio::io_context io_;
  beast::tcp_stream stream_{io_};
  bool ok_ = false;
};

// The close code in the last close frame (opcode 8) of `bytes`, or -1.
int close_code_in(const std::string& bytes) {
  const std::size_t at = bytes.rfind("\x88\x02");
  if (at == std::string::npos || at + 4 > bytes.size()) return -1;
  return (static_cast<unsigned char>(bytes[at + 2]) << 8) |
         static_cast<unsigned char>(bytes[at + 3]);
}

class ViewHostile : public ::testing::Test {
 protected:
  void SetUp() override {
    view_ = std::make_unique<ViewProcess>(std::vector<std::string>{scene_path(kScene)}, "127.0.0.1",
                                          "hostile");
    ASSERT_NE(view_->port(), 0) << view_->out() << view_->err();
  }
  // A page that keeps working: a command's reply and its frame.
  static void still_served(WsClient& page, int id, double t) {
    const Json r = command(page, id, "step 10");
    ASSERT_TRUE(r.is_object());
    EXPECT_EQ(r["ok"], true);
    const Json f = page.read_type("frame");
    ASSERT_TRUE(f.is_object());
    EXPECT_NEAR(f["t"].get<double>(), t, 1e-9);
  }
  // A clean end: exit code 0 on SIGTERM (under the sanitizers: no leak, no error report).
  void TearDown() override {
    if (view_) {
      EXPECT_EQ(view_->stop(), 0) << view_->err();
    }
  }
  std::unique_ptr<ViewProcess> view_;
};

TEST_F(ViewHostile, MalformedFramesCloseOnlyTheirConnection) {
  WsClient good(view_->port());
  ASSERT_TRUE(good.read_type("frame").is_object());
  const std::vector<std::string> hostile = {
      std::string("\x81\x05hello", 7),                     // unmasked client frame
      std::string("\x83\x80\x01\x02\x03\x04", 6),          // reserved opcode 3
      std::string("\xf1\x80\x01\x02\x03\x04", 6),          // reserved bits set
      std::string("\x89\xfe\x01\x00\x01\x02\x03\x04", 8),  // a 256-byte ping (control > 125)
      std::string("\x81\xff\x7f\xff\xff\xff\xff\xff\xff\xff\x01\x02\x03\x04", 14),  // 2^63 length
      std::string("\x81\x82\x00\x00\x00\x00\xc3\x28", 8),  // a text frame that is not UTF-8
  };
  for (std::size_t i = 0; i < hostile.size(); ++i) {
    RawPage raw(view_->port());
    raw.write(hostile[i]);
    bool closed = false;
    const std::string got = raw.read_all(10s, closed);
    EXPECT_TRUE(closed) << "hostile frame " << i;
    const int code = close_code_in(got);
    EXPECT_TRUE(code == 1002 || code == 1007 || code == 1009) << "frame " << i << " code " << code;
  }
  still_served(good, 1, 0.01);
}

TEST_F(ViewHostile, SilentAndOversizedRequestsAreClosed) {
  WsClient good(view_->port());
  ASSERT_TRUE(good.read_type("frame").is_object());
  RawPage silent(view_->port(), false);  // connects and says nothing
  RawPage huge(view_->port(), false);
  huge.write("GET / HTTP/1.1\r\nHost: x\r\nX-Big: " + std::string(9000, 'a') + "\r\n\r\n");
  bool closed = false;
  EXPECT_EQ(huge.read_all(10s, closed).rfind("HTTP/1.1 431", 0), 0u);
  EXPECT_TRUE(closed);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_TRUE(silent.read_all(20s, closed).empty());
  EXPECT_TRUE(closed);  // after the 10 s a connection has to send its request
  EXPECT_GT(std::chrono::steady_clock::now() - start, 5s);
  still_served(good, 1, 0.01);
}

TEST_F(ViewHostile, AnOversizedMessageIsClosedWith1009) {
  WsClient good(view_->port());
  ASSERT_TRUE(good.read_type("frame").is_object());
  WsClient big(view_->port());
  ASSERT_TRUE(big.read_type("frame").is_object());
  big.send(R"({"op":"cmd","id":1,"line":")" + std::string(70 * 1024, 'x') + "\"}");
  while (big.read(10s)) {
  }
  EXPECT_EQ(big.close_code(), 1009);
  WsClient small(view_->port());  // 64 KiB - 1 is allowed: an error reply, not a close
  ASSERT_TRUE(small.read_type("frame").is_object());
  small.send(R"({"op":"cmd","id":2,"line":")" + std::string(64 * 1024 - 40, 'x') + "\"}");
  const Json e = small.read_type("error");
  ASSERT_TRUE(e.is_object());
  EXPECT_NE(e["error"].get<std::string>().find("longer than 4096"), std::string::npos);
  still_served(good, 3, 0.01);
}

TEST_F(ViewHostile, APageThatStopsReadingLosesFramesNotTheOthersOrTheSimulation) {
  const auto sim = sim::Simulation::from_file(scene_path(kScene));
  const double dt = sim->scene().physics.step, period = sim->robot(0).period();
  // The stalled page: a tiny receive buffer, joined, then never read again.
  WsClient stalled(view_->port());
  stalled.stream().next_layer().socket().set_option(asio::socket_base::receive_buffer_size(2048));
  ASSERT_TRUE(stalled.read_type("frame").is_object());
  WsClient good(view_->port());
  ASSERT_TRUE(good.read_type("frame").is_object());
  good.send(R"({"op":"watch","keys":["representation:FrameInfo.time"]})");
  // Real time: 4 s of wall time, 240 frames at 60 a second, more than the socket buffers hold.
  ASSERT_EQ(command(good, 9, "realtime on")["ok"], true);
  good.send(R"({"op":"cmd","id":1,"line":"step 4000"})");
  std::vector<double> times;
  std::uint64_t dropped_good = 0, dropped_all = 0;
  double last_t = 0;
  Json reply;
  const auto end = std::chrono::steady_clock::now() + 120s;
  while ((reply.is_null() || last_t < 4000 * dt - 1e-9) && std::chrono::steady_clock::now() < end) {
    const auto text = good.read(30s);
    ASSERT_TRUE(text.has_value());
    const Json m = Json::parse(*text);
    if (m["type"] == "reply" && m["id"] == 1) reply = m;
    if (m["type"] == "status") dropped_all = std::max<std::uint64_t>(dropped_all, m["dropped"]);
    if (m["type"] != "frame") continue;
    dropped_good = m["dropped"];
    last_t = m["t"];
    for (const auto& row : m["samples"]["rows"]) times.push_back(row[1]);
  }
  EXPECT_EQ(reply["ok"], true);
  EXPECT_NEAR(last_t, 4000 * dt, 1e-9);  // every step happened
  // Every control frame's sample reached the page that reads, unless it too fell behind; then
  // the samples it lost are whole frames' (gaps of whole periods) and counted in its `dropped`.
  ASSERT_FALSE(times.empty());
  std::size_t missing = 0;
  for (std::size_t i = 1; i < times.size(); ++i) {
    const double gap = std::round((times[i] - times[i - 1]) / period);
    EXPECT_GE(gap, 1.0) << i;
    EXPECT_NEAR(times[i] - times[i - 1], gap * period, 1e-9) << i;
    missing += static_cast<std::size_t>(gap) - 1;
  }
  const auto all = static_cast<std::size_t>(std::llround(4000 * dt / period));
  if (dropped_good == 0) {
    EXPECT_EQ(times.size(), all);
    EXPECT_EQ(missing, 0u);
  } else {
    EXPECT_LT(times.size(), all);
  }
  // The stalled page's frames were dropped and counted (the status message says so).
  const auto status_end = std::chrono::steady_clock::now() + 10s;
  while (dropped_all == 0 && std::chrono::steady_clock::now() < status_end) {
    const Json s = good.read_type("status", 5s);
    if (s.is_object()) dropped_all = s["dropped"];
  }
  EXPECT_GT(dropped_all, 0u);
}

TEST_F(ViewHostile, AHundredConnectionsAtOnceAreServedOrCleanlyRefused) {
  WsClient good(view_->port());
  ASSERT_TRUE(good.read_type("frame").is_object());
  asio::io_context io;
  std::vector<std::unique_ptr<websocket::stream<beast::tcp_stream>>> pages;
  std::vector<int> state(100, 0);  // 0 pending, 1 upgraded, -1 failed
  for (int i = 0; i < 100; ++i) {
    pages.push_back(std::make_unique<websocket::stream<beast::tcp_stream>>(io));
    auto& ws = *pages.back();
    beast::get_lowest_layer(ws).expires_after(30s);
    beast::get_lowest_layer(ws).async_connect(
        tcp::endpoint(asio::ip::make_address("127.0.0.1"), view_->port()),
        [&, i](beast::error_code ec) {
          if (ec) return void(state[i] = -1);
          pages[i]->async_handshake("127.0.0.1", "/ws",
                                    [&, i](beast::error_code ec) { state[i] = ec ? -1 : 1; });
        });
  }
  bool all = false;
  const auto end = std::chrono::steady_clock::now() + 40s;
  while (!all && std::chrono::steady_clock::now() < end) {
    io.run_for(50ms);
    all = std::none_of(state.begin(), state.end(), [](int s) { return s == 0; });
  }
  ASSERT_TRUE(all);
  // Each upgraded page gets hello (joined) or a close with 1013 (over the 32 pages).
  int joined = 0, refused = 0;
  std::vector<beast::flat_buffer> buffers(100);
  std::vector<int> outcome(100, 0);
  for (int i = 0; i < 100; ++i) {
    if (state[i] != 1) continue;
    beast::get_lowest_layer(*pages[i]).expires_never();
    pages[i]->async_read(buffers[i], [&, i](beast::error_code ec, std::size_t) {
      if (!ec && beast::buffers_to_string(buffers[i].data()).find("\"hello\"") != std::string::npos)
        outcome[i] = 1;
      else if (ec == websocket::error::closed && pages[i]->reason().code == 1013)
        outcome[i] = 2;
      else
        outcome[i] = 3;
    });
  }
  io.restart();  // it ran out of work after the handshakes
  const auto read_end = std::chrono::steady_clock::now() + 30s;
  auto settled = [&] {
    for (int i = 0; i < 100; ++i)
      if (state[i] == 1 && outcome[i] == 0) return false;
    return true;
  };
  while (!settled() && std::chrono::steady_clock::now() < read_end) io.run_for(50ms);
  for (int o : outcome) joined += o == 1, refused += o == 2;
  EXPECT_EQ(joined, 31);  // 32 pages with `good`
  EXPECT_EQ(joined + refused, 100);
  still_served(good, 1, 0.01);
  for (auto& p : pages) beast::get_lowest_layer(*p).close();
  pages.clear();
  WsClient later(view_->port());  // the places are free again
  EXPECT_TRUE(later.read_type("hello").is_object());
}

}  // namespace
}  // namespace stride::view_test
