#pragma once
// Unix stream sockets, as LoLA uses them: a listening server (the simulator's LoLA) and connected
// ends. Every error is a stride::Error naming the socket path.
#include <chrono>
#include <cstddef>
#include <optional>
#include <span>
#include <string>

namespace stride::hal {

using Deadline = std::chrono::steady_clock::time_point;

class UnixSocket {
 public:
  UnixSocket() = default;
  explicit UnixSocket(int fd, std::string path) : fd_(fd), path_(std::move(path)) {}
  ~UnixSocket() { close(); }
  UnixSocket(UnixSocket&& o) noexcept;
  UnixSocket& operator=(UnixSocket&& o) noexcept;
  UnixSocket(const UnixSocket&) = delete;
  UnixSocket& operator=(const UnixSocket&) = delete;

  // Connects to a listening socket without waiting (a server whose queue is full refuses);
  // throws naming the path and the reason.
  static UnixSocket connect(const std::string& path);

  bool open() const { return fd_ >= 0; }
  const std::string& path() const { return path_; }
  void close();

  // Writes every byte, waiting as long as it takes; false when the peer is gone (no SIGPIPE).
  bool send_all(std::span<const char> bytes);
  enum class Send { Sent, Closed, Timeout };
  // Writes every byte before `deadline` and never blocks past it: Closed when the peer is gone,
  // Timeout when it did not take the bytes in time (some may have gone: the stream is cut).
  Send send_until(std::span<const char> bytes, Deadline deadline);
  enum class Wait { Readable, Timeout, Interrupted };
  // Waits until bytes (or the peer's close) can be read, or the deadline passes.
  Wait wait_readable(Deadline deadline) const;
  // Reads what is there (blocking only if nothing is): > 0 bytes, 0 when the peer closed,
  // -1 on an error (errno kept), -2 when interrupted by a signal.
  long receive(std::span<char> into);

 private:
  int fd_ = -1;
  std::string path_;
};

class UnixListener {
 public:
  // Listens at `path`. A stale socket file nobody listens on is replaced; a live one is an error
  // (another server runs there), as is any other file.
  explicit UnixListener(std::string path);
  ~UnixListener();
  UnixListener(const UnixListener&) = delete;
  UnixListener& operator=(const UnixListener&) = delete;

  // A client if one connects before the deadline.
  std::optional<UnixSocket> accept(Deadline deadline);
  const std::string& path() const { return path_; }

 private:
  int fd_ = -1;
  std::string path_;
};

}  // namespace stride::hal
