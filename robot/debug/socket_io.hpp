#pragma once
// The few POSIX TCP calls the debug server and its clients need (IPv4).
#include <cstdint>
#include <string>
#include <string_view>

struct sockaddr_in;

namespace stride::debug {

struct Endpoint {
  std::string host = "127.0.0.1";
  std::uint16_t port = 0;
  std::string text() const { return host + ":" + std::to_string(port); }
};

// "host:port", ":port" or "port" (host 127.0.0.1); `what` names the option in errors.
Endpoint parse_endpoint(std::string_view text, std::string_view what);
bool is_loopback(const Endpoint& e);  // 127.0.0.0/8 or "localhost"

// An owned file descriptor.
class Fd {
 public:
  Fd() = default;
  explicit Fd(int fd) : fd_(fd) {}
  Fd(Fd&& o) noexcept : fd_(o.release()) {}
  Fd& operator=(Fd&& o) noexcept;
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() { reset(); }
  int get() const { return fd_; }
  int release();
  void reset();
  explicit operator bool() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

// A non-blocking listening socket; `bound` receives the address really bound (port 0 picks one).
Fd listen_tcp(const Endpoint& at, Endpoint& bound);
// A blocking connected socket with TCP_NODELAY; throws stride::Error naming the endpoint.
Fd connect_tcp(const Endpoint& to, double timeout_seconds);
void set_nonblocking(int fd);
void set_no_delay(int fd);
std::string address_text(const sockaddr_in& a);

}  // namespace stride::debug
