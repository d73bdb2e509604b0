#pragma once
// Peers that do not follow the debug protocol, for hostile tests over loopback: connections from
// another loopback address (another machine on the field), silent peers that hold connections,
// hand-made messages a strict encoder would not write, and a look at what the server answers.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>

#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include <msgpack.hpp>

#include "robot/debug/msgpack_map.hpp"
#include "robot/debug/protocol.hpp"
#include "robot/debug/socket_io.hpp"
#include "robot/debug/wire.hpp"

namespace stride::test {

// A blocking TCP connection to `at` from the loopback address `source` (e.g. "127.0.0.2"), or
// none if refused.
inline debug::Fd connect_from(const debug::Endpoint& at, const std::string& source) {
  debug::Fd fd(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0));
  sockaddr_in from{}, to{};
  from.sin_family = to.sin_family = AF_INET;
  ::inet_pton(AF_INET, source.c_str(), &from.sin_addr);
  ::inet_pton(AF_INET, at.host.c_str(), &to.sin_addr);
  to.sin_port = htons(at.port);
  if (::bind(fd.get(), reinterpret_cast<sockaddr*>(&from), sizeof from) != 0 ||
      ::connect(fd.get(), reinterpret_cast<sockaddr*>(&to), sizeof to) != 0)
    return debug::Fd();
  timeval tv{5, 0};  // every read of a test is bounded
  ::setsockopt(fd.get(), SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  return fd;
}

// Connections from `source` (another loopback address: another machine on the field) that never
// say a word, each opened again as soon as the server drops it.
class SilentPeers {
 public:
  SilentPeers(const debug::Endpoint& at, const std::string& source, int count) {
    thread_ = std::thread([this, at, source, count] { run(at, source, count); });
  }
  ~SilentPeers() {
    stop_ = true;
    thread_.join();
  }
  int reopened() const { return reopened_; }

 private:
  void run(const debug::Endpoint& at, const std::string& source, int count) {
    std::vector<debug::Fd> peers(count);
    while (!stop_) {
      std::vector<pollfd> fds;
      for (auto& p : peers) {
        if (!p) {
          p = connect_from(at, source);
          ++reopened_;
        }
        fds.push_back({p.get(), POLLIN, 0});
      }
      ::poll(fds.data(), fds.size(), 20);
      char buffer[4096];
      for (std::size_t i = 0; i < fds.size(); ++i)  // read the hello, never answer
        if ((fds[i].revents & (POLLIN | POLLHUP | POLLERR)) &&
            ::recv(peers[i].get(), buffer, sizeof buffer, MSG_DONTWAIT) <= 0)
          peers[i].reset();
    }
  }
  std::atomic<bool> stop_{false};
  std::atomic<int> reopened_{0};
  std::thread thread_;
};

// Every str in a decoded message (keys and values, nested) is ASCII: what we sent was ASCII but
// for the bad bytes, so anything else is a raw echo.
inline bool all_ascii(const msgpack::object& o) {
  if (o.type == msgpack::type::STR) {
    for (std::uint32_t i = 0; i < o.via.str.size; ++i)
      if (static_cast<unsigned char>(o.via.str.ptr[i]) >= 0x80) return false;
  } else if (o.type == msgpack::type::MAP) {
    for (std::uint32_t i = 0; i < o.via.map.size; ++i)
      if (!all_ascii(o.via.map.ptr[i].key) || !all_ascii(o.via.map.ptr[i].val)) return false;
  } else if (o.type == msgpack::type::ARRAY) {
    for (std::uint32_t i = 0; i < o.via.array.size; ++i)
      if (!all_ascii(o.via.array.ptr[i])) return false;
  }
  return true;
}

// A request map with raw str values (a strict packer would not write these bytes).
inline std::string raw_request(const std::string& t, const std::string& op,
                               const std::string& key) {
  msgpack::sbuffer buffer;
  msgpack::packer<msgpack::sbuffer> p(buffer);
  p.pack_map(4);
  p.pack(std::string("t")).pack(t);
  p.pack(std::string("id")).pack(9);
  p.pack(std::string("op")).pack(op);
  p.pack(std::string("key")).pack(key);
  return std::string(buffer.data(), buffer.size());
}

// The first message of type reply or denied after sending `payload` on `fd` ("" if the server
// closed the connection first).
inline std::string answer_on(const debug::Fd& fd, const std::string& payload) {
  std::string framed;
  debug::append_frame(framed, payload);
  ::send(fd.get(), framed.data(), framed.size(), MSG_NOSIGNAL);
  debug::FrameReader in(debug::kMaxServerMessage);
  char buffer[4096];
  for (int i = 0; i < 100; ++i) {
    while (auto m = in.next()) {
      const auto h = msgpack::unpack(m->data(), m->size());
      const std::string type = debug::MapView(h.get(), "m").text_or("t", "");
      if (type == "reply" || type == "denied") return *m;
    }
    const ssize_t n = ::recv(fd.get(), buffer, sizeof buffer, 0);
    if (n <= 0) break;
    in.feed(std::string_view(buffer, static_cast<std::size_t>(n)));
  }
  return "";
}

// The same on a fresh connection from 127.0.0.1.
inline std::string answer_to(const debug::Endpoint& at, const std::string& payload) {
  return answer_on(connect_from(at, "127.0.0.1"), payload);
}

}  // namespace stride::test
