#include "robot/debug/socket_io.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>

#include "robot/core/error.hpp"

namespace stride::debug {

Endpoint parse_endpoint(std::string_view text, std::string_view what) {
  Endpoint e;
  const auto colon = text.rfind(':');
  std::string_view port = text;
  if (colon != std::string_view::npos) {
    if (colon > 0) e.host = std::string(text.substr(0, colon));
    port = text.substr(colon + 1);
  }
  unsigned value = 0;
  const auto [end, ec] = std::from_chars(port.data(), port.data() + port.size(), value);
  if (port.empty() || ec != std::errc() || end != port.data() + port.size() || value > 65535)
    throw Error(std::string(what) + ": expected host:port with a port 0-65535, got '" +
                std::string(text.substr(0, 80)) + "'");
  e.port = static_cast<std::uint16_t>(value);
  return e;
}

bool is_loopback(const Endpoint& e) {
  if (e.host == "localhost") return true;
  in_addr a{};
  return inet_pton(AF_INET, e.host.c_str(), &a) == 1 && (ntohl(a.s_addr) >> 24) == 127;
}

Fd& Fd::operator=(Fd&& o) noexcept {
  if (this != &o) {
    reset();
    fd_ = o.release();
  }
  return *this;
}

int Fd::release() {
  const int fd = fd_;
  fd_ = -1;
  return fd;
}

void Fd::reset() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void set_nonblocking(int fd) {
  const int flags = ::fcntl(fd, F_GETFL, 0);
  if (flags < 0 || ::fcntl(fd, F_SETFL, flags | O_NONBLOCK) < 0)
    throw Error(std::string("fcntl(O_NONBLOCK): ") + std::strerror(errno));
}

void set_no_delay(int fd) {
  int one = 1;
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
}

std::string address_text(const sockaddr_in& a) {
  char host[INET_ADDRSTRLEN] = "?";
  inet_ntop(AF_INET, &a.sin_addr, host, sizeof host);
  return std::string(host) + ":" + std::to_string(ntohs(a.sin_port));
}

namespace {
sockaddr_in resolve(const Endpoint& e) {
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  const int rc = ::getaddrinfo(e.host.c_str(), nullptr, &hints, &found);
  if (rc != 0 || !found)
    throw Error("cannot resolve '" + e.host + "': " + std::string(gai_strerror(rc)));
  sockaddr_in a = *reinterpret_cast<const sockaddr_in*>(found->ai_addr);
  ::freeaddrinfo(found);
  a.sin_port = htons(e.port);
  return a;
}
}  // namespace

Fd listen_tcp(const Endpoint& at, Endpoint& bound) {
  const sockaddr_in a = resolve(at);
  Fd fd(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0));
  if (!fd) throw Error(std::string("socket: ") + std::strerror(errno));
  int one = 1;
  ::setsockopt(fd.get(), SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  if (::bind(fd.get(), reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0)
    throw Error("cannot listen on " + at.text() + ": " + std::strerror(errno));
  if (::listen(fd.get(), 128) != 0)  // room for a burst of connections between wakes
    throw Error("cannot listen on " + at.text() + ": " + std::strerror(errno));
  set_nonblocking(fd.get());
  sockaddr_in b{};
  socklen_t n = sizeof b;
  ::getsockname(fd.get(), reinterpret_cast<sockaddr*>(&b), &n);
  bound = {at.host, ntohs(b.sin_port)};
  return fd;
}

Fd connect_tcp(const Endpoint& to, double timeout_seconds) {
  const sockaddr_in a = resolve(to);
  Fd fd(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0));
  if (!fd) throw Error(std::string("socket: ") + std::strerror(errno));
  set_nonblocking(fd.get());
  if (::connect(fd.get(), reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0) {
    if (errno != EINPROGRESS)
      throw Error("cannot connect to " + to.text() + ": " + std::strerror(errno));
    pollfd p{fd.get(), POLLOUT, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(timeout_seconds * 1000));
    if (ready == 0)
      throw Error("cannot connect to " + to.text() + ": no answer within " +
                  std::to_string(timeout_seconds).substr(0, 4) + " s");
    int err = 0;
    socklen_t n = sizeof err;
    ::getsockopt(fd.get(), SOL_SOCKET, SO_ERROR, &err, &n);
    if (ready < 0 || err != 0)
      throw Error("cannot connect to " + to.text() + ": " + std::strerror(err ? err : errno));
  }
  const int flags = ::fcntl(fd.get(), F_GETFL, 0);
  ::fcntl(fd.get(), F_SETFL, flags & ~O_NONBLOCK);
  set_no_delay(fd.get());
  return fd;
}

}  // namespace stride::debug
