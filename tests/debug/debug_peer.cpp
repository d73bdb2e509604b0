// debug_peer: one debug-server client in its own process, for the fault tests and the load tool.
//   debug_peer honest <host:port> <seconds> <keys> [every]   stream keys, check the frames
//   debug_peer garbage <host:port> <seconds>                 flood random bytes, reconnecting
//   debug_peer churn <host:port> <seconds>                   connect, greet, drop, again
//   debug_peer half <host:port>                              half a request, then wait (killed)
//   debug_peer noread <host:port> <keys>                     subscribe, then never read
//   debug_peer huge <host:port>                              announce a 4 GB message
//   debug_peer wrong-token <host:port> <count>               authenticate wrongly, count times
// <keys>: comma-separated; "Rep.field:N" stands for representation:Rep.field[0..N-1].
// Prints one result line (key=value ...) on standard output; exit status 0 when it did its part.
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "robot/debug/auth.hpp"
#include "robot/debug/debug_client.hpp"
#include "robot/debug/msgpack_map.hpp"

namespace {

using namespace stride;
using namespace stride::debug;
using Clock = std::chrono::steady_clock;

std::vector<std::string> expand_keys(const std::string& spec) {
  std::vector<std::string> keys;
  std::stringstream in(spec);
  for (std::string item; std::getline(in, item, ',');) {
    const auto colon = item.rfind(':');
    if (item.starts_with("representation:") || item.starts_with("module:") ||
        colon == std::string::npos) {
      keys.push_back(item);
      continue;
    }
    const int n = std::stoi(item.substr(colon + 1));
    for (int i = 0; i < n; ++i)
      keys.push_back("representation:" + item.substr(0, colon) + "[" + std::to_string(i) + "]");
  }
  return keys;
}

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// Streams for `seconds` and checks that every frame from the first one streamed to the last one
// received either arrived or was counted as dropped by the server.
int honest(const Endpoint& at, double seconds, const std::string& spec, std::uint64_t every) {
  DebugClient client(at, "");
  Request r;
  r.op = Op::Subscribe;
  r.keys = expand_keys(spec);
  r.every = every;
  const auto reply = client.call(r);
  const std::int64_t from = reply->fields().integer("from");
  std::uint64_t received = 0, dropped = 0, out_of_order = 0, empty = 0;
  std::int64_t last = from - static_cast<std::int64_t>(every);
  const auto start = Clock::now();
  while (seconds_since(start) < seconds) {
    auto s = client.next_sample(1.0);
    if (!s) continue;
    if (s->frame <= last || (s->frame - from) % static_cast<std::int64_t>(every) != 0)
      ++out_of_order;
    last = s->frame;
    dropped = s->dropped;
    ++received;
    for (const auto& v : s->values) empty += v.empty();
  }
  const std::uint64_t expected =
      received ? static_cast<std::uint64_t>((last - from) / static_cast<std::int64_t>(every) + 1)
               : 0;
  const bool complete = received > 0 && received + dropped == expected && out_of_order == 0;
  std::cout << "role=honest received=" << received << " dropped=" << dropped
            << " expected=" << expected << " out_of_order=" << out_of_order
            << " empty_values=" << empty << " keys=" << r.keys.size()
            << " complete=" << (complete ? 1 : 0) << std::endl;
  return complete ? 0 : 1;
}

int garbage(const Endpoint& at, double seconds) {
  std::mt19937_64 rng(1);
  std::string junk(65536, '\0');
  std::uint64_t connections = 0, bytes = 0;
  const auto start = Clock::now();
  while (seconds_since(start) < seconds) {
    Fd fd;
    try {
      fd = connect_tcp(at, 2);
    } catch (const Error&) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      continue;
    }
    ++connections;
    while (seconds_since(start) < seconds) {
      for (auto& c : junk) c = static_cast<char>(rng());
      const ssize_t n = ::send(fd.get(), junk.data(), junk.size(), MSG_NOSIGNAL);
      if (n <= 0) break;  // the server closed it: connect again
      bytes += static_cast<std::uint64_t>(n);
    }
  }
  std::cout << "role=garbage connections=" << connections << " bytes=" << bytes << std::endl;
  return 0;
}

int churn(const Endpoint& at, double seconds) {
  std::uint64_t greeted = 0, refused = 0;
  const auto start = Clock::now();
  while (seconds_since(start) < seconds) {
    try {
      DebugClient client(at, "");  // connect + hello + welcome, then drop at once
      ++greeted;
    } catch (const Error&) {
      ++refused;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
  std::cout << "role=churn greeted=" << greeted << " refused=" << refused << std::endl;
  return greeted > 0 ? 0 : 1;
}

void send_all(int fd, const std::string& bytes) {
  for (std::size_t sent = 0; sent < bytes.size();) {
    const ssize_t n = ::send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) return;
    sent += static_cast<std::size_t>(n);
  }
}

int half(const Endpoint& at) {
  Fd fd = connect_tcp(at, 2);
  Request r;
  r.id = 1;
  r.op = Op::Set;
  r.key = "module:Stand";
  r.text = "knee_pitch=0.5";
  std::string framed;
  append_frame(framed, encode_request(r));
  send_all(fd.get(), framed.substr(0, framed.size() / 2));
  std::cout << "role=half sent=" << framed.size() / 2 << " of=" << framed.size() << std::endl;
  for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));  // until killed
}

int noread(const Endpoint& at, const std::string& spec) {
  DebugClient client(at, "");
  Request r;
  r.op = Op::Subscribe;
  r.keys = expand_keys(spec);
  client.call(r);
  std::cout << "role=noread subscribed=" << r.keys.size() << std::endl;
  for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));  // never reads; until killed
}

int huge(const Endpoint& at) {
  Fd fd = connect_tcp(at, 2);
  send_all(fd.get(), std::string("\xff\xff\xff\xff", 4) + std::string(1024, 'x'));
  char buffer[4096];
  std::uint64_t received = 0;
  bool denied = false;
  for (;;) {
    const ssize_t n = ::recv(fd.get(), buffer, sizeof buffer, 0);
    if (n <= 0) break;
    received += static_cast<std::uint64_t>(n);
    denied |= std::string(buffer, static_cast<std::size_t>(n)).find("denied") != std::string::npos;
  }
  std::cout << "role=huge closed=1 denied=" << denied << " received=" << received << std::endl;
  return denied ? 0 : 1;
}

int wrong_token(const Endpoint& at, int count) {
  int denied = 0;
  for (int i = 0; i < count; ++i) {
    try {
      DebugClient client(at, "not-the-token-" + std::to_string(i));
    } catch (const Error& e) {
      denied += std::string(e.what()).find("wrong token") != std::string::npos;
    }
  }
  std::cout << "role=wrong-token attempts=" << count << " denied=" << denied << std::endl;
  return denied == count ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> a(argv + 1, argv + argc);
  try {
    if (a.size() < 2) throw Error("usage: debug_peer <role> <host:port> ...");
    const Endpoint at = parse_endpoint(a[1], "debug_peer");
    const std::string& role = a[0];
    if (role == "honest" && a.size() >= 4)
      return honest(at, std::stod(a[2]), a[3], a.size() > 4 ? std::stoull(a[4]) : 1);
    if (role == "garbage" && a.size() == 3) return garbage(at, std::stod(a[2]));
    if (role == "churn" && a.size() == 3) return churn(at, std::stod(a[2]));
    if (role == "half") return half(at);
    if (role == "noread" && a.size() == 3) return noread(at, a[2]);
    if (role == "huge") return huge(at);
    if (role == "wrong-token" && a.size() == 3) return wrong_token(at, std::stoi(a[2]));
    throw Error("debug_peer: unknown role or arguments");
  } catch (const std::exception& e) {
    std::cout << "role=" << (a.empty() ? "?" : a[0]) << " error=\"" << e.what() << "\""
              << std::endl;
    return 2;
  }
}
