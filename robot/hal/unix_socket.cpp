#include "robot/hal/unix_socket.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "robot/core/error.hpp"

namespace stride::hal {
namespace {

sockaddr_un address(const std::string& path) {
  sockaddr_un a{};
  a.sun_family = AF_UNIX;
  if (path.empty() || path.size() >= sizeof a.sun_path)
    throw Error("socket '" + path + "': expected a path of 1 to " +
                std::to_string(sizeof a.sun_path - 1) + " characters");
  std::memcpy(a.sun_path, path.c_str(), path.size() + 1);
  return a;
}

int milliseconds_until(Deadline deadline) {
  const auto left =
      std::chrono::ceil<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
  return static_cast<int>(std::max<long long>(0, left.count()));
}

std::string reason() {
  return std::strerror(errno);
}

// A server at `a` takes connections, or has as many waiting as it allows (EAGAIN).
bool someone_listens(const sockaddr_un& a) {
  const int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (fd < 0) return false;
  const bool live =
      ::connect(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a) == 0 || errno == EAGAIN;
  ::close(fd);
  return live;
}

}  // namespace

UnixSocket::UnixSocket(UnixSocket&& o) noexcept : fd_(o.fd_), path_(std::move(o.path_)) {
  o.fd_ = -1;
}

UnixSocket& UnixSocket::operator=(UnixSocket&& o) noexcept {
  if (this != &o) {
    close();
    fd_ = o.fd_;
    path_ = std::move(o.path_);
    o.fd_ = -1;
  }
  return *this;
}

void UnixSocket::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

UnixSocket UnixSocket::connect(const std::string& path) {
  const sockaddr_un a = address(path);
  // Non-blocking while connecting: a server that stopped accepting must not hold the caller.
  const int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (fd < 0) throw Error("socket '" + path + "': " + reason());
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0) {
    const std::string why = errno == EAGAIN ? "the server accepts no more clients" : reason();
    ::close(fd);
    throw Error("socket '" + path + "': cannot connect (" + why + ")");
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  return UnixSocket(fd, path);
}

bool UnixSocket::send_all(std::span<const char> bytes) {
  std::size_t sent = 0;
  while (fd_ >= 0 && sent < bytes.size()) {
    const ssize_t n = ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n > 0)
      sent += static_cast<std::size_t>(n);
    else if (n < 0 && errno == EINTR)
      continue;
    else
      return false;
  }
  return fd_ >= 0;
}

UnixSocket::Send UnixSocket::send_until(std::span<const char> bytes, Deadline deadline) {
  std::size_t sent = 0;
  while (fd_ >= 0 && sent < bytes.size()) {
    const ssize_t n =
        ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n > 0) {
      sent += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK)) return Send::Closed;
    pollfd p{fd_, POLLOUT, 0};  // the peer's buffer is full: wait for room, not past the deadline
    const int ready = ::poll(&p, 1, milliseconds_until(deadline));
    if (ready == 0) return Send::Timeout;
    if (ready < 0 && errno != EINTR) return Send::Closed;
  }
  return fd_ >= 0 ? Send::Sent : Send::Closed;
}

UnixSocket::Wait UnixSocket::wait_readable(Deadline deadline) const {
  pollfd p{fd_, POLLIN, 0};
  const int n = ::poll(&p, 1, milliseconds_until(deadline));
  if (n > 0) return Wait::Readable;  // data, or the peer's close / an error that read reports
  if (n < 0 && errno == EINTR) return Wait::Interrupted;
  return Wait::Timeout;
}

long UnixSocket::receive(std::span<char> into) {
  const ssize_t n = ::recv(fd_, into.data(), into.size(), 0);
  if (n < 0 && errno == EINTR) return -2;
  return n;
}

UnixListener::UnixListener(std::string path) : path_(std::move(path)) {
  const sockaddr_un a = address(path_);
  struct stat st {};
  if (::lstat(path_.c_str(), &st) == 0) {
    if (!S_ISSOCK(st.st_mode))
      throw Error("socket '" + path_ + "': a file that is not a socket is in the way");
    if (someone_listens(a)) throw Error("socket '" + path_ + "': another server listens there");
    ::unlink(path_.c_str());  // left behind by a server that did not stop cleanly
  }
  fd_ = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throw Error("socket '" + path_ + "': " + reason());
  if (::bind(fd_, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0 || ::listen(fd_, 1) != 0) {
    const std::string why = reason();
    ::close(fd_);
    fd_ = -1;
    throw Error("socket '" + path_ + "': cannot listen (" + why + ")");
  }
}

UnixListener::~UnixListener() {
  if (fd_ < 0) return;
  ::close(fd_);
  ::unlink(path_.c_str());
}

std::optional<UnixSocket> UnixListener::accept(Deadline deadline) {
  for (;;) {
    pollfd p{fd_, POLLIN, 0};
    const int n = ::poll(&p, 1, milliseconds_until(deadline));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return std::nullopt;
    const int fd = ::accept4(fd_, nullptr, nullptr, SOCK_CLOEXEC);
    if (fd >= 0) return UnixSocket(fd, path_);
    if (errno != EINTR && errno != ECONNABORTED) return std::nullopt;
  }
}

}  // namespace stride::hal
