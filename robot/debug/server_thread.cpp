// ServerThread, connections: accept, handshake, reading, writing, timeouts, closing, logging.
#include "robot/debug/server_thread.hpp"

#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "robot/core/one_line.hpp"

namespace stride::debug {

namespace {
constexpr std::size_t kReadChunk = 64 * 1024;  // per client per wake: a flood cannot starve others
constexpr auto kCloseGrace = std::chrono::milliseconds(500);
constexpr auto kLogWindow = std::chrono::seconds(10);
constexpr int kLogLinesPerWindow = 20;
constexpr int kAcceptsPerWake = 8;
constexpr std::size_t kMaxClosing = 64;  // sessions saying goodbye (their last bytes) at a time

double seconds(Clock::duration d) {
  return std::chrono::duration<double>(d).count();
}
}  // namespace

ServerThread::ServerThread(ServerOptions& options, Exchange& exchange, Fd listener, Fd wake)
    : options_(options),
      x_(exchange),
      listener_(std::move(listener)),
      wake_(std::move(wake)),
      logs_(options.log_dir) {}

ServerThread::~ServerThread() = default;

ServerStats ServerThread::stats() const {
  ServerStats s;
  s.clients = admitted_now_.load();
  s.accepted = accepted_.load();
  s.rejected = rejected_.load();
  s.requests = requests_.load();
  s.samples_sent = sent_.load();
  s.samples_dropped = dropped_.load();
  s.snapshots_lost = x_.snapshots_lost.load();
  s.loop_allocations = x_.loop_allocations.load();
  return s;
}

void ServerThread::log(const std::string& line, Clock::time_point now) {
  if (now - log_window_ > kLogWindow) {
    if (log_suppressed_ > 0)
      options_.log("debug server: " + std::to_string(log_suppressed_) +
                   " more event(s) not listed in the last 10 s");
    log_window_ = now;
    log_lines_ = 0;
    log_suppressed_ = 0;
  }
  if (log_lines_++ < kLogLinesPerWindow)
    options_.log("debug server: " + one_line(line, 400));
  else
    ++log_suppressed_;
}

void ServerThread::send(ClientSession& c, const std::string& payload) {
  std::string framed;
  append_frame(framed, payload);
  c.out_bytes += framed.size();
  c.out.push_back(std::move(framed));
}

bool ServerThread::send_sample(ClientSession& c, const std::string& payload) {
  if (c.out_bytes + payload.size() > options_.stream_queue) return false;
  send(c, payload);
  return true;
}

void ServerThread::evict(ClientSession& c, const std::string& why, Clock::time_point now) {
  rejected_.fetch_add(1);
  log("rejected " + c.address + ": " + why, now);
  c.fd.reset();  // at once: its slot is wanted now
  c.state = ClientSession::State::Closing;
}

void ServerThread::make_pending_room(std::uint32_t peer, Clock::time_point now) {
  // What pending peers sent is read first: an authentication that arrived is admitted and a peer
  // that closed is dropped, so only those still silent compete for the slots.
  for (auto& [id, c] : clients_)
    if (c->fd && c->state == ClientSession::State::Greeting) read_client(*c, now);
  std::map<std::uint32_t, std::vector<ClientSession*>> pending;  // per address, oldest first
  std::size_t all = 0;
  for (auto& [id, c] : clients_)
    if (c->fd && c->state == ClientSession::State::Greeting) {
      pending[c->peer].push_back(c.get());
      ++all;
    }
  const std::vector<ClientSession*>* from = nullptr;
  if (pending[peer].size() >= options_.max_pending_per_address)
    from = &pending[peer];
  else if (all >= options_.max_pending)
    for (const auto& [address, list] : pending)
      if (!from || list.size() > from->size()) from = &list;
  if (from && !from->empty())
    evict(*from->front(),
          "no authentication yet while the pre-authentication slots (" +
              std::to_string(options_.max_pending) + ", " +
              std::to_string(options_.max_pending_per_address) +
              " per address) were wanted by a newer connection",
          now);
}

void ServerThread::accept_clients(Clock::time_point now) {
  const bool auth = !options_.tokens.empty();
  // A few per wake: the clients already connected are read between batches of new ones, so a
  // storm of connections does not starve them.
  for (int taken = 0; taken < kAcceptsPerWake; ++taken) {
    sockaddr_in peer{};
    socklen_t n = sizeof peer;
    Fd fd(::accept4(listener_.get(), reinterpret_cast<sockaddr*>(&peer), &n,
                    SOCK_NONBLOCK | SOCK_CLOEXEC));
    if (!fd) return;  // EAGAIN, or a transient error: the next wake retries
    accepted_.fetch_add(1);
    if (clients_.size() >= options_.max_clients + options_.max_pending + kMaxClosing) {
      rejected_.fetch_add(1);  // closed without a word: those before are still being closed
      continue;
    }
    if (auth) make_pending_room(peer.sin_addr.s_addr, now);
    auto c = std::make_unique<ClientSession>();
    c->id = next_id_++;
    c->fd = std::move(fd);
    c->peer = peer.sin_addr.s_addr;
    c->address = address_text(peer);
    c->last_heard = c->bucket_time = now;
    c->bucket = options_.request_rate;
    c->deadline = now + std::chrono::duration_cast<Clock::duration>(
                            std::chrono::duration<double>(options_.handshake_timeout));
    set_no_delay(c->fd.get());
    int one = 1;  // a peer that vanished is noticed even on an idle connection
    ::setsockopt(c->fd.get(), SOL_SOCKET, SO_KEEPALIVE, &one, sizeof one);
    ClientSession& ref = *c;
    clients_.emplace(c->id, std::move(c));
    if (!auth && admitted_now_.load() >= options_.max_clients) {
      reject(ref, too_many(), now);
      continue;
    }
    ref.nonce = random_nonce();
    send(ref, encode_hello({kProtocolVersion, options_.robot, auth, auth ? ref.nonce : ""}));
    if (!auth) admit(ref, false, "");
  }
}

std::string ServerThread::too_many() const {
  return "too many clients (limit " + std::to_string(options_.max_clients) + ")";
}

void ServerThread::admit(ClientSession& c, bool read_only, const std::string& proof) {
  if (admitted_now_.load() >= options_.max_clients) return reject(c, too_many(), Clock::now());
  c.state = ClientSession::State::Ready;
  c.read_only = read_only;
  Welcome w;
  w.read_only = read_only;
  w.mac = proof;
  w.period = x_.period.load(std::memory_order_relaxed);
  send(c, encode_welcome(w));
  admitted_now_.fetch_add(1);
  log("client " + c.address + " connected" + (read_only ? " (read-only)" : ""), Clock::now());
}

void ServerThread::reject(ClientSession& c, const std::string& why, Clock::time_point now) {
  if (c.state == ClientSession::State::Closing) return;
  if (!c.logged_rejection) {
    c.logged_rejection = true;
    rejected_.fetch_add(1);
    log("rejected " + c.address + ": " + why, now);
  }
  if (c.state == ClientSession::State::Ready) admitted_now_.fetch_sub(1);
  send(c, encode_denied(why));
  c.state = ClientSession::State::Closing;
  c.sub.reset();
  c.deadline = now + kCloseGrace;
}

void ServerThread::say_goodbye(ClientSession& c, const std::string& why, Clock::time_point now) {
  if (c.state == ClientSession::State::Ready) {
    admitted_now_.fetch_sub(1);
    log("client " + c.address + " disconnected: " + why, now);
  }
  send(c, encode_bye(why));
  c.state = ClientSession::State::Closing;
  c.sub.reset();
  c.deadline = now + kCloseGrace;
}

void ServerThread::drop(ClientSession& c, const std::string& why) {
  if (!c.fd) return;
  if (c.state == ClientSession::State::Ready) {
    admitted_now_.fetch_sub(1);
    log("client " + c.address + " disconnected: " + why, Clock::now());
  }
  c.fd.reset();
  c.state = ClientSession::State::Closing;
}

void ServerThread::read_client(ClientSession& c, Clock::time_point now) {
  char buffer[16384];
  std::size_t taken = 0;
  while (c.fd && c.state != ClientSession::State::Closing && taken < kReadChunk) {
    const ssize_t n = ::recv(c.fd.get(), buffer, sizeof buffer, 0);
    if (n == 0) {
      const std::size_t partial = c.in.buffered();
      return drop(c, partial ? "closed in the middle of a message (" + std::to_string(partial) +
                                   " bytes unread)"
                             : "closed the connection");
    }
    if (n < 0) {
      if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) break;
      return drop(c, std::strerror(errno));
    }
    taken += static_cast<std::size_t>(n);
    c.in.feed(std::string_view(buffer, static_cast<std::size_t>(n)));
    try {
      while (c.state != ClientSession::State::Closing) {
        auto message = c.in.next();
        if (!message) break;
        on_message(c, *message, now);
      }
    } catch (const Error& e) {
      return reject(c, e.what(), now);
    }
  }
}

void ServerThread::write_client(ClientSession& c) {
  while (c.fd && !c.out.empty()) {
    const std::string& front = c.out.front();
    const ssize_t n = ::send(c.fd.get(), front.data() + c.out_offset, front.size() - c.out_offset,
                             MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0) {
      if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR) return;
      return drop(c, std::strerror(errno));
    }
    c.out_offset += static_cast<std::size_t>(n);
    if (c.out_offset < front.size()) return;
    c.out_bytes -= front.size();
    c.out_offset = 0;
    c.out.pop_front();
  }
}

void ServerThread::check_timeouts(ClientSession& c, Clock::time_point now) {
  if (!c.fd) return;
  switch (c.state) {
    case ClientSession::State::Greeting:
      if (now > c.deadline)
        reject(c,
               "no authentication within " +
                   std::to_string(options_.handshake_timeout).substr(0, 4) + " s",
               now);
      break;
    case ClientSession::State::Ready:
      if (seconds(now - c.last_heard) > options_.idle_timeout)
        say_goodbye(c, "idle for " + std::to_string(options_.idle_timeout).substr(0, 4) + " s",
                    now);
      break;
    case ClientSession::State::Closing:
      if (c.out.empty() || now > c.deadline) c.fd.reset();
      break;
  }
}

void ServerThread::on_message(ClientSession& c, const std::string& payload, Clock::time_point now) {
  c.last_heard = now;
  ClientMessage m;
  try {
    m = decode_client_message(payload);
  } catch (const RequestError& e) {
    if (c.state != ClientSession::State::Ready)
      return reject(c, std::string("request before authentication: ") + e.what(), now);
    send(c, encode_error_reply(e.id, e.what()));
    return;
  }  // any other Error: not our protocol, the caller rejects the client
  if (auto* a = std::get_if<AuthMessage>(&m)) {
    if (c.state != ClientSession::State::Greeting || options_.tokens.empty())
      return reject(c, "authentication it was not asked for", now);
    return on_auth(c, *a, now);
  }
  if (c.state != ClientSession::State::Ready)
    return reject(c, "request before authentication", now);
  on_request(c, std::get<Request>(m), now);
}

void ServerThread::on_auth(ClientSession& c, const AuthMessage& a, Clock::time_point now) {
  for (const Token& t : options_.tokens)
    if (same_proof(a.mac, client_proof(t.secret, c.nonce, a.nonce)))
      return admit(c, t.read_only, server_proof(t.secret, c.nonce, a.nonce));
  reject(c, "wrong token", now);
}

void ServerThread::shutdown() {
  for (auto& [id, c] : clients_) {
    if (!c->fd) continue;
    if (c->state == ClientSession::State::Ready) send(*c, encode_bye("the robot is shutting down"));
    write_client(*c);  // one try; a client that does not read just loses the goodbye
    drop(*c, "server stopped");
  }
  clients_.clear();
}

void ServerThread::run(const std::atomic<bool>& stop) {
  std::vector<pollfd> fds;
  std::vector<ClientSession*> order;
  while (!stop.load(std::memory_order_acquire)) {
    fds.assign({{wake_.get(), POLLIN, 0}, {listener_.get(), POLLIN, 0}});
    order.clear();
    bool streaming = false;  // or a reply awaited from the loop, which never wakes this thread
    for (auto& [id, c] : clients_) {
      short events = 0;
      if (c->state != ClientSession::State::Closing && c->out_bytes < options_.reply_queue)
        events |= POLLIN;
      if (c->out_bytes > 0) events |= POLLOUT;
      fds.push_back({c->fd.get(), events, 0});
      order.push_back(c.get());
      streaming |= c->sub.has_value() || c->in_flight > 0;
    }
    // Neither snapshots nor replies wake this thread (that would cost the loop a system call and
    // another core's wake-up): while streaming or awaiting the loop it looks every 2 ms.
    ::poll(fds.data(), fds.size(), streaming || !parked_.empty() ? 2 : 50);
    if (fds[0].revents & POLLIN) {
      std::uint64_t count;
      [[maybe_unused]] const auto n = ::read(wake_.get(), &count, sizeof count);
    }
    const auto now = Clock::now();
    take_from_loop();
    if (fds[1].revents & POLLIN) accept_clients(now);
    for (std::size_t i = 0; i < order.size(); ++i) {
      ClientSession& c = *order[i];
      if (fds[i + 2].revents & (POLLIN | POLLHUP | POLLERR)) read_client(c, now);
      if (c.fd && c.out_bytes > 0) write_client(c);
      check_timeouts(c, now);
    }
    std::erase_if(clients_, [](const auto& kv) { return !kv.second->fd; });
    retry_parked(now);
    publish_wanted(now);
    bool any = false;
    for (const auto& [id, c] : clients_) any |= c->state == ClientSession::State::Ready;
    // Stored only on a change: a store takes the line from the loop's core, which reads it each
    // frame.
    if (x_.clients.load(std::memory_order_relaxed) != any)
      x_.clients.store(any, std::memory_order_relaxed);
  }
  shutdown();
}

}  // namespace stride::debug
