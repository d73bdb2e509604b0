#include "robot/debug/debug_client.hpp"

#include "robot/core/one_line.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <sys/time.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <utility>

#include "robot/debug/auth.hpp"

namespace stride::debug {

namespace {
constexpr std::size_t kMaxNotes = 100;  // a robot cannot fill a client that never asks

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

DebugClient::DebugClient(const Endpoint& to, const std::string& token, ClientOptions options)
    : to_(to), options_(options) {
  fd_ = connect_tcp(to, options_.timeout);
  timeval tv{
      static_cast<time_t>(options_.timeout),
      static_cast<suseconds_t>((options_.timeout - static_cast<time_t>(options_.timeout)) * 1e6)};
  ::setsockopt(fd_.get(), SOL_SOCKET, SO_SNDTIMEO, &tv, sizeof tv);
  handshake(token);
}

void DebugClient::lost(const std::string& why) {
  fd_.reset();
  throw ConnectionLost("lost the connection to " + to_.text() + ": " + why);
}

void DebugClient::send_payload(const std::string& payload) {
  if (!fd_) throw ConnectionLost("not connected to " + to_.text());
  std::string framed;
  append_frame(framed, payload);
  std::size_t sent = 0;
  while (sent < framed.size()) {
    const ssize_t n = ::send(fd_.get(), framed.data() + sent, framed.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) lost(n < 0 && errno == EAGAIN ? "the robot does not read" : std::strerror(errno));
    sent += static_cast<std::size_t>(n);
  }
  last_sent_ = now_seconds();
}

bool DebugClient::receive(double timeout) {
  if (!fd_) throw ConnectionLost("not connected to " + to_.text());
  pollfd p{fd_.get(), POLLIN, 0};
  const int ready = ::poll(&p, 1, static_cast<int>(std::max(0.0, timeout) * 1000));
  if (ready == 0) return false;
  if (ready < 0) {
    if (errno == EINTR) return false;
    lost(std::strerror(errno));
  }
  char buffer[65536];
  const ssize_t n = ::recv(fd_.get(), buffer, sizeof buffer, 0);
  if (n == 0) lost("the robot closed the connection");
  if (n < 0) {
    if (errno == EAGAIN || errno == EINTR) return false;
    lost(std::strerror(errno));
  }
  in_.feed(std::string_view(buffer, static_cast<std::size_t>(n)));
  try {
    while (auto payload = in_.next()) dispatch(*payload);
  } catch (const ConnectionLost&) {
    throw;
  } catch (const Error& e) {
    lost(std::string("bad message from the robot: ") + e.what());
  }
  return true;
}

void DebugClient::dispatch(const std::string& payload) {
  auto m = std::make_unique<ServerMessage>(payload);
  const std::string& type = m->type();
  if (handshaking_) {
    handshake_messages_.push_back(std::move(m));
  } else if (type == "sample") {
    samples_.push_back(sample_of(m->fields()));
    if (samples_.size() > options_.max_samples) {
      samples_.pop_front();
      ++discarded_;
    }
  } else if (type == "reply") {
    const auto id = m->fields().unsigned_integer("id", UINT64_MAX);
    if (discard_.erase(id) == 0) replies_[id] = std::move(m);
  } else if (type == "note") {
    if (notes_.size() < kMaxNotes) notes_.push_back(one_line(m->fields().text("text"), 2000));
  } else if (type == "bye" || type == "denied") {
    lost("the robot said: " + one_line(m->fields().text("why"), 400));
  }  // other types: a newer robot's; ignored
}

std::vector<std::string> DebugClient::take_notes() {
  return std::exchange(notes_, {});
}

std::unique_ptr<ServerMessage> DebugClient::next_message(double timeout) {
  const double until = now_seconds() + timeout;
  while (handshake_messages_.empty()) {
    const double left = until - now_seconds();
    if (left <= 0) lost("no answer within " + std::to_string(timeout).substr(0, 4) + " s");
    receive(left);
  }
  auto m = std::move(handshake_messages_.front());
  handshake_messages_.pop_front();
  if (m->type() == "denied") lost("the robot refused: " + one_line(m->fields().text("why"), 400));
  return m;
}

void DebugClient::handshake(const std::string& token) {
  auto m = next_message(options_.timeout);
  if (m->type() != "hello") lost("expected hello, got '" + m->type() + "'");
  hello_ = hello_of(m->fields());
  if (hello_.protocol != kProtocolVersion)
    lost("the robot speaks debug protocol " + std::to_string(hello_.protocol) + ", this build " +
         std::to_string(kProtocolVersion));
  std::string client_nonce;
  if (hello_.auth) {
    if (token.empty())
      lost("the robot asks for a token (connect <host:port> <token>, or STRIDE_TOKEN)");
    client_nonce = random_nonce();
    send_payload(encode_auth({client_proof(token, hello_.nonce, client_nonce), client_nonce}));
  }
  m = next_message(options_.timeout);
  if (m->type() != "welcome") lost("expected welcome, got '" + m->type() + "'");
  welcome_ = welcome_of(m->fields());
  if (hello_.auth && !same_proof(welcome_.mac, server_proof(token, hello_.nonce, client_nonce)))
    lost("the robot did not prove it knows the token (another robot at this address?)");
  handshaking_ = false;
  handshake_messages_.clear();  // nothing else comes before the first request
}

std::uint64_t DebugClient::send_request(Request& r) {
  r.id = next_id_++;
  send_payload(encode_request(r));
  return r.id;
}

std::unique_ptr<ServerMessage> DebugClient::call(Request r) {
  const std::uint64_t id = send_request(r);
  const double until = now_seconds() + options_.timeout;
  for (;;) {
    if (auto it = replies_.find(id); it != replies_.end()) {
      auto m = std::move(it->second);
      replies_.erase(it);
      if (!m->fields().boolean("ok")) throw Error(one_line(m->fields().text("error"), 2000));
      return m;
    }
    const double left = until - now_seconds();
    if (left <= 0) {
      discard_.insert(id);
      throw Error("the robot at " + to_.text() + " did not answer '" + std::string(op_name(r.op)) +
                  "' within " + std::to_string(options_.timeout).substr(0, 4) + " s");
    }
    receive(left);
  }
}

void DebugClient::send_only(Request r) {
  discard_.insert(send_request(r));
}

std::optional<Sample> DebugClient::next_sample(double timeout) {
  const double until = now_seconds() + timeout;
  while (samples_.empty()) {
    if (now_seconds() - last_sent_ > options_.ping_every) send_only(Request{0, Op::Ping});
    const double left = until - now_seconds();
    if (left <= 0) return std::nullopt;
    receive(std::min(left, options_.ping_every));
  }
  Sample s = std::move(samples_.front());
  samples_.pop_front();
  return s;
}

void DebugClient::keep_alive() {
  while (receive(0)) {
  }
  if (now_seconds() - last_sent_ > options_.ping_every) send_only(Request{0, Op::Ping});
}

}  // namespace stride::debug
