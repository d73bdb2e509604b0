// An outside probe of the debug protocol with its limits, against the real `stride run --debug`
// with tokens, over loopback: wrong types, huge lengths, bytes that are not UTF-8, path tricks in
// log names, slow pre-authentication peers and reconnect storms. Every case must end in an error
// reply or the end of that connection, with every string UTF-8; nothing outside the log directory
// changes; the server goes on serving. The counts printed are those in robot/debug/README.md.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <iostream>
#include <map>

#include <gtest/gtest.h>

#include "robot/debug/auth.hpp"
#include "robot/debug/debug_client.hpp"
#include "tests/debug/raw_peer.hpp"
#include "tests/debug/served_process.hpp"
#include "tests/lola/lola_test_support.hpp"

namespace stride::test {
namespace {

using Packer = msgpack::packer<msgpack::sbuffer>;
using Clock = std::chrono::steady_clock;

// Outcomes of the cases of one kind.
struct Tally {
  std::map<std::string, int> outcomes;  // "error reply", "ok reply", "connection ended"
  int not_utf8 = 0;                     // answers with a str that is not ASCII (a raw echo)
  int cases() const {
    int n = 0;
    for (const auto& [k, v] : outcomes) n += v;
    return n;
  }
  std::string text() const {
    std::string s = std::to_string(cases()) + " cases:";
    for (const auto& [k, v] : outcomes) s += " " + std::to_string(v) + " " + k + ",";
    return s + " " + std::to_string(not_utf8) + " answers not UTF-8";
  }
};

// An authenticated connection made by hand, opened again whenever the server ends it.
class RawSession {
 public:
  RawSession(const debug::Endpoint& at, std::string token) : at_(at), token_(std::move(token)) {}

  // Sends one framed payload (or raw bytes when `framed` is false) and files the outcome.
  void ask(Tally& tally, const std::string& payload, bool framed = true) {
    if (!fd_) open();
    std::string bytes = payload;
    if (framed) {
      bytes.clear();
      debug::append_frame(bytes, payload);
    }
    ::send(fd_.get(), bytes.data(), bytes.size(), MSG_NOSIGNAL);
    const std::string answer = next_answer();
    if (answer.empty()) {
      ++tally.outcomes["connection ended"];
      fd_.reset();
      return;
    }
    const auto h = msgpack::unpack(answer.data(), answer.size());
    tally.not_utf8 += !all_ascii(h.get());
    const debug::MapView m(h.get(), "answer");
    if (m.text("t") != "reply") {
      ++tally.outcomes["connection ended"];  // denied: the server closes it
      fd_.reset();
    } else {
      ++tally.outcomes[m.boolean("ok") ? "ok reply" : "error reply"];
    }
  }

 private:
  void open() {
    fd_ = connect_from(at_, "127.0.0.1");
    in_ = debug::FrameReader(debug::kMaxServerMessage);
    const std::string hello = next("hello");
    ASSERT_FALSE(hello.empty());
    const auto h = msgpack::unpack(hello.data(), hello.size());
    const std::string theirs = debug::MapView(h.get(), "hello").bytes("nonce");
    const std::string mine = debug::random_nonce();
    std::string framed;
    debug::append_frame(framed,
                        debug::encode_auth({debug::client_proof(token_, theirs, mine), mine}));
    ::send(fd_.get(), framed.data(), framed.size(), MSG_NOSIGNAL);
    ASSERT_FALSE(next("welcome").empty());
  }
  // The next message of `type`, skipping samples and notes ("" when the connection ends).
  std::string next(const std::string& type) {
    for (;;) {
      const std::string m = read_one();
      if (m.empty()) return m;
      const auto h = msgpack::unpack(m.data(), m.size());
      if (debug::MapView(h.get(), "m").text("t") == type) return m;
    }
  }
  std::string read_one() {
    char buffer[65536];
    for (int i = 0; i < 200; ++i) {
      if (auto m = in_.next()) return *m;
      const ssize_t n = ::recv(fd_.get(), buffer, sizeof buffer, 0);
      if (n <= 0) return "";
      in_.feed(std::string_view(buffer, static_cast<std::size_t>(n)));
    }
    return "";
  }
  std::string next_answer() {
    for (;;) {
      const std::string m = read_one();
      if (m.empty()) return m;
      const auto h = msgpack::unpack(m.data(), m.size());
      const std::string t = debug::MapView(h.get(), "m").text("t");
      if (t == "reply" || t == "denied") return m;
    }
  }

  debug::Endpoint at_;
  std::string token_;
  debug::Fd fd_;
  debug::FrameReader in_{debug::kMaxServerMessage};
};

// One request map: the fields of `fields` in order, each packed by its function.
using Field = std::pair<std::string, std::function<void(Packer&)>>;
std::string request_map(const std::vector<Field>& fields) {
  msgpack::sbuffer buffer;
  Packer p(buffer);
  p.pack_map(static_cast<std::uint32_t>(fields.size()));
  for (const auto& [key, value] : fields) {
    p.pack(key);
    value(p);
  }
  return std::string(buffer.data(), buffer.size());
}

Field str(const std::string& key, const std::string& value) {
  return {key, [value](Packer& p) { p.pack(value); }};
}
Field uint(const std::string& key, std::uint64_t value) {
  return {key, [value](Packer& p) { p.pack(value); }};
}

// A valid request of `op` (with the read-only token it changes nothing), as fields.
std::vector<Field> valid_request(const std::string& op) {
  std::vector<Field> f = {str("t", "req"), uint("id", 1), str("op", op)};
  const bool log = op.starts_with("log_");
  f.push_back(str("key", log ? "probe.log" : "representation:FrameInfo"));
  f.push_back(str("text", "off"));
  f.push_back(
      {"keys", [](Packer& p) { p.pack(std::vector<std::string>{"representation:FrameInfo"}); }});
  f.push_back(uint("every", 1));
  f.push_back(uint("offset", 0));
  f.push_back(uint("length", 16));
  f.push_back({"json", [](Packer& p) { p.pack(false); }});
  return f;
}

const std::vector<std::string> kOps = {
    "list",      "get",      "set",      "mr",        "dr",     "subscribe", "unsubscribe",
    "log_start", "log_stop", "log_info", "log_fetch", "report", "ping",      "value"};

// Values of every msgpack kind (and out of range) for a field of another kind.
std::vector<std::function<void(Packer&)>> wrong_values() {
  return {[](Packer& p) { p.pack(3); },
          [](Packer& p) { p.pack(-1); },
          [](Packer& p) { p.pack(1.5); },
          [](Packer& p) { p.pack_nil(); },
          [](Packer& p) { p.pack(true); },
          [](Packer& p) { p.pack_bin(1).pack_bin_body("\0", 1); },
          [](Packer& p) { p.pack(std::vector<int>{1}); },
          [](Packer& p) {
            p.pack(std::map<std::string, int>{{"a", 1}});
          },
          [](Packer& p) { p.pack(std::string("x")); },
          [](Packer& p) { p.pack(UINT64_MAX); }};
}

Tally wrong_types(const debug::Endpoint& at) {
  Tally t;
  for (const auto& op : kOps) {
    RawSession s(at, kReadOnlyToken);  // a fresh budget of requests per op
    const auto valid = valid_request(op);
    for (std::size_t field = 0; field < valid.size(); ++field)
      for (const auto& bad : wrong_values()) {
        auto fields = valid;
        fields[field].second = bad;
        s.ask(t, request_map(fields));
      }
  }
  return t;
}

// Lengths and counts at and over every limit.
Tally huge_lengths(const debug::Endpoint& at) {
  Tally t;
  RawSession s(at, kReadOnlyToken);
  auto prefix = [](std::uint32_t n) {
    return std::string{static_cast<char>(n >> 24), static_cast<char>(n >> 16),
                       static_cast<char>(n >> 8), static_cast<char>(n)};
  };
  s.ask(t, prefix(0xffffffffu), false);      // announces 4 GiB
  s.ask(t, prefix(64 * 1024 + 1), false);    // one over the limit
  s.ask(t, std::string(64 * 1024, '\xc1'));  // at the limit, not msgpack
  s.ask(t, std::string("\xdb\xff\xff\xff\xff"
                       "abc",
                       8));                          // str32 of 4 GiB in 8 bytes
  s.ask(t, std::string("\xdd\xff\xff\xff\xff", 5));  // array32 of 4 G elements
  s.ask(t, std::string(100, '\x91') + "\x01");       // arrays nested 100 deep
  std::vector<Field> wide;
  for (int i = 0; i < 65; ++i) wide.push_back(uint("k" + std::to_string(i), 1));
  s.ask(t, request_map(wide));  // a map over 64 entries
  auto with = [](std::vector<Field> f, Field changed) {
    for (auto& x : f)
      if (x.first == changed.first) x = changed;
    return f;
  };
  const std::vector<std::string> many(257, "representation:FrameInfo");
  s.ask(t, request_map(
               with(valid_request("subscribe"), {"keys", [many](Packer& p) { p.pack(many); }})));
  s.ask(t, request_map(with(valid_request("get"), str("key", std::string(513, 'k')))));
  s.ask(t, request_map(with(valid_request("log_fetch"), uint("length", 1ull << 40))));
  s.ask(t, request_map(with(valid_request("log_fetch"), uint("offset", 1ull << 60))));
  s.ask(t, request_map(with(valid_request("subscribe"), uint("every", 1000000000))));
  s.ask(t, request_map(with(valid_request("ping"), uint("id", 1ull << 60))));
  return t;
}

// Bytes that are not UTF-8 (lone, truncated, overlong, surrogate, above U+10FFFF) in each str
// that the op reads (fields it ignores are never looked at).
Tally bad_utf8(const debug::Endpoint& at) {
  Tally t;
  const std::vector<std::string> bad = {"\xff", "\xc3", "\xc0\xaf", "\xed\xa0\x80",
                                        "\xf4\x90\x80\x80"};
  const std::vector<std::pair<std::string, std::vector<std::string>>> read = {
      {"get", {"key"}},        {"set", {"key", "text"}},
      {"mr", {"key", "text"}}, {"dr", {"key", "text"}},
      {"value", {"key"}},      {"log_start", {"key"}},
      {"subscribe", {"keys"}}, {"ping", {}}};
  for (const auto& [op, used] : read) {
    RawSession s(at, kReadOnlyToken);
    std::vector<std::string> fields = used;
    fields.insert(fields.end(), {"t", "op"});
    for (const auto& b : bad)
      for (const auto& field : fields) {
        auto request = valid_request(op);
        for (auto& f : request)
          if (f.first == field && field == "keys")
            f.second = [b](Packer& p) { p.pack(std::vector<std::string>{"x" + b}); };
          else if (f.first == field)
            f.second = [b, field](Packer& p) { p.pack((field == "t" ? "req" : "x") + b); };
        s.ask(t, request_map(request));
      }
  }
  return t;
}

// Log names that try to leave the log directory or reach a file the server did not write.
Tally path_tricks(const debug::Endpoint& at, const std::string& dir, const std::string& outside) {
  Tally t;
  ::symlink(outside.c_str(), (dir + "/planted.log").c_str());
  ::link((dir + "/tokens").c_str(), (dir + "/hard.log").c_str());
  ::mkfifo((dir + "/fifo.log").c_str(), 0644);
  const std::vector<std::string> names = {"../x.log",
                                          "..",
                                          "/etc/passwd",
                                          outside,
                                          "a/b.log",
                                          std::string("x.log\0.txt", 10),
                                          ".hidden.log",
                                          "x.log/",
                                          "%2e%2e%2fx.log",
                                          "x.LOG",
                                          std::string(101, 'a'),
                                          "tokens",
                                          "planted.log",
                                          "hard.log",
                                          "fifo.log"};
  RawSession writer(at, kFullToken), reader(at, kReadOnlyToken);
  for (const auto& name : names) {
    auto start = valid_request("log_start");
    auto info = valid_request("log_info");
    auto fetch = valid_request("log_fetch");
    for (auto* f : {&start, &info, &fetch}) (*f)[3] = str("key", name);
    writer.ask(t, request_map(start));
    reader.ask(t, request_map(info));
    reader.ask(t, request_map(fetch));
  }
  return t;
}

// Peers that send a message a byte every 100 ms (it would take 10 s): seconds until the last
// one is closed.
double slowloris(const debug::Endpoint& at, int peers) {
  std::string slow;
  debug::append_frame(slow, std::string(100, 'a'));
  std::vector<debug::Fd> fds;
  for (int i = 0; i < peers; ++i) fds.push_back(connect_from(at, "127.0.0.4"));
  const auto start = Clock::now();
  std::vector<double> closed(peers, -1);
  for (std::size_t sent = 0; sent < slow.size(); ++sent) {
    bool open = false;
    for (int i = 0; i < peers; ++i) {
      if (closed[i] >= 0) continue;
      char buffer[4096];
      ssize_t got;
      while ((got = ::recv(fds[i].get(), buffer, sizeof buffer, MSG_DONTWAIT)) > 0) {
      }  // the hello, then the denial
      if (got == 0 || ::send(fds[i].get(), &slow[sent], 1, MSG_NOSIGNAL) < 0)
        closed[i] = std::chrono::duration<double>(Clock::now() - start).count();
      open |= closed[i] < 0;
    }
    if (!open) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  double longest = 0;
  for (double c : closed) longest = c < 0 ? 1e9 : std::max(longest, c);
  return longest;
}

// Connections opened and closed as fast as they go from `source` for `seconds`, while a console
// logs in from 127.0.0.1 every 100 ms: how many of its logins succeeded, of how many.
struct Storm {
  int logins = 0, tries = 0, connections = 0;
};
Storm storm(const debug::Endpoint& at, const std::string& source, double seconds) {
  std::atomic<bool> stop{false};
  std::atomic<int> count{0};
  std::vector<std::thread> threads;
  for (int i = 0; i < 3; ++i)
    threads.emplace_back([&] {
      while (!stop)
        if (connect_from(at, source)) ++count;
    });
  Storm s;
  const auto start = Clock::now();
  while (std::chrono::duration<double>(Clock::now() - start).count() < seconds) {
    ++s.tries;
    try {
      debug::DebugClient console(at, kFullToken);
      console.call(debug::request(debug::Op::Ping));
      ++s.logins;
    } catch (const Error&) {
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  stop = true;
  for (auto& t : threads) t.join();
  s.connections = count;
  return s;
}

TEST(DebugProbe, HostileRequestsEndInErrorsAndTheServerGoesOn) {
  Served robot("probe", true);
  ASSERT_NE(robot.at.port, 0) << robot.process.err();
  const std::string outside = fresh_dir("probe_outside") + "/victim.log";
  std::ofstream(outside) << "outside";

  const std::vector<std::pair<std::string, Tally>> kinds = {
      {"wrong types", wrong_types(robot.at)},
      {"huge lengths and counts", huge_lengths(robot.at)},
      {"not UTF-8", bad_utf8(robot.at)},
      {"path tricks in log names", path_tricks(robot.at, robot.dir, outside)}};
  for (const auto& [name, tally] : kinds) {
    std::cout << "probe: " << name << ": " << tally.text() << "\n";
    EXPECT_EQ(tally.not_utf8, 0) << name;
  }
  // Nothing invalid was accepted: ok replies only where the bad field is one the op ignores.
  EXPECT_EQ(kinds[1].second.outcomes.count("ok reply"), 0u) << kinds[1].second.text();
  EXPECT_EQ(kinds[2].second.outcomes.count("ok reply"), 0u) << kinds[2].second.text();
  EXPECT_EQ(kinds[3].second.outcomes.count("ok reply"), 0u) << kinds[3].second.text();
  EXPECT_EQ(read_file(outside), "outside");
  EXPECT_FALSE(std::filesystem::exists(robot.dir + "/../x.log"));

  const double slow = slowloris(robot.at, 8);
  std::cout << "probe: slow authentication (8 peers, a byte per 100 ms): all closed after " << slow
            << " s\n";
  EXPECT_LT(slow, 4.0);  // the 2 s handshake limit, with room for a busy machine

  const Storm other = storm(robot.at, "127.0.0.5", 3), same = storm(robot.at, "127.0.0.1", 3);
  std::cout << "probe: reconnect storm from another address (" << other.connections
            << " connections in 3 s): " << other.logins << " of " << other.tries
            << " console logins; from the console's own address (" << same.connections
            << " connections): " << same.logins << " of " << same.tries << "\n";
  EXPECT_EQ(other.logins, other.tries);
  EXPECT_GT(other.connections, 50);  // it was a storm (hundreds a second here, fewer sanitized)

  // The 17 silent peers, reopened when dropped, from the console's own address.
  int logins = 0;
  {
    SilentPeers silent(robot.at, "127.0.0.1", 17);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    for (int i = 0; i < 15; ++i) try {
        debug::DebugClient console(robot.at, kFullToken);
        console.call(debug::request(debug::Op::Ping));
        ++logins;
      } catch (const Error&) {
      }
    std::cout << "probe: 17 silent peers from the console's own address (" << silent.reopened()
              << " connections): " << logins << " of 15 console logins\n";
  }

  debug::DebugClient console(robot.at, kFullToken);  // still serving, the loop still running
  const auto frame = [&] {
    return console.call(debug::request(debug::Op::List))->fields().integer("frame");
  };
  const std::int64_t before = frame();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_GT(frame(), before);
}

}  // namespace
}  // namespace stride::test
