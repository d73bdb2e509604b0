#include "robot/debug/protocol.hpp"

#include <array>

#include "robot/core/error.hpp"
#include "robot/core/one_line.hpp"
#include "robot/debug/msgpack_map.hpp"
#include "robot/runtime/controller_keys.hpp"

namespace stride::debug {

namespace {

struct OpName {
  Op op;
  std::string_view name;
  bool writes;
};
constexpr std::array<OpName, 15> kOps = {{{Op::List, "list", false},
                                          {Op::Get, "get", false},
                                          {Op::Set, "set", true},
                                          {Op::Mr, "mr", true},
                                          {Op::Dr, "dr", true},
                                          {Op::Subscribe, "subscribe", false},
                                          {Op::Unsubscribe, "unsubscribe", false},
                                          {Op::LogStart, "log_start", true},
                                          {Op::LogStop, "log_stop", true},
                                          {Op::LogInfo, "log_info", false},
                                          {Op::LogFetch, "log_fetch", false},
                                          {Op::Report, "report", false},
                                          {Op::Ping, "ping", false},
                                          {Op::Value, "value", false},
                                          {Op::Restart, "restart", true}}};

Op op_from(const std::string& name) {
  for (const auto& o : kOps)
    if (o.name == name) return o.op;
  std::string known;
  for (const auto& o : kOps) known += (known.empty() ? "" : ", ") + std::string(o.name);
  throw Error("request: unknown op '" + one_line(name, 40) + "' (" + known + ")");
}

constexpr std::uint64_t kMaxId = (std::uint64_t{1} << 53);
constexpr std::size_t kMaxKey = 512;

std::string short_text(const MapView& m, std::string_view field) {
  std::string s = m.text(field);
  if (s.size() > kMaxKey)
    throw Error("request: field '" + std::string(field) + "' longer than " +
                std::to_string(kMaxKey) + " characters");
  return s;
}

void fill_request(Request& r, const msgpack::object& o, const MapView& head) {
  r.op = op_from(head.text("op"));
  const MapView m(o, "request '" + std::string(op_name(r.op)) + "'");
  switch (r.op) {
    case Op::Get:
    case Op::LogStart:
    case Op::LogInfo:
    case Op::Value:
      r.key = short_text(m, "key");
      break;
    case Op::Set:
      r.key = short_text(m, "key");
      r.text = m.text("text");
      break;
    case Op::Mr:
      r.key = short_text(m, "key");
      r.text = short_text(m, "text");
      break;
    case Op::Dr:
      r.key = short_text(m, "key");
      r.text = short_text(m, "text");
      if (!debug_switch_named(r.text))
        throw Error("request 'dr': field 'text': expected off, on or quiet, got '" +
                    one_line(r.text, 40) + "'");
      break;
    case Op::Subscribe:
      r.keys = m.texts("keys");
      if (r.keys.empty() || r.keys.size() > kMaxSubscribedKeys)
        throw Error("request 'subscribe': give 1 to " + std::to_string(kMaxSubscribedKeys) +
                    " keys, got " + std::to_string(r.keys.size()));
      for (const auto& k : r.keys)
        if (k.size() > kMaxKey) throw Error("request 'subscribe': a key is too long");
      r.every = m.unsigned_or("every", 1, 1000000);
      if (r.every == 0) throw Error("request 'subscribe': field 'every': expected >= 1, got 0");
      break;
    case Op::LogFetch:
      r.key = short_text(m, "key");
      r.offset = m.unsigned_integer("offset", kMaxId);
      r.length = m.unsigned_integer("length", kMaxLogChunk);
      break;
    case Op::Report:
      r.on = m.boolean_or("json", false);
      break;
    default:
      break;
  }
}

Request decode_request(const msgpack::object& o) {
  const MapView head(o, "request");
  Request r;
  r.id = head.unsigned_integer("id", kMaxId);
  try {
    fill_request(r, o, head);
  } catch (const RequestError&) {
    throw;
  } catch (const Error& e) {
    throw RequestError(r.id, e.what());
  }
  return r;
}

}  // namespace

std::string_view op_name(Op op) {
  for (const auto& o : kOps)
    if (o.op == op) return o.name;
  return "?";
}

Request request(Op op, std::string key, std::string text) {
  Request r;
  r.op = op;
  r.key = std::move(key);
  r.text = std::move(text);
  return r;
}

bool op_writes(Op op) {
  for (const auto& o : kOps)
    if (o.op == op) return o.writes;
  return true;
}

ClientMessage decode_client_message(std::string_view payload) {
  DecodeLimits limits;
  limits.str = limits.bin = kMaxClientMessage;
  limits.array = kMaxSubscribedKeys + 1;
  const auto h = decode_msgpack(payload, limits);
  const MapView m(h.get(), "message");
  const std::string type = m.text("t");
  if (type == "auth") {
    AuthMessage a{m.bytes("mac"), m.bytes("nonce")};
    if (a.nonce.size() != kNonceBytes)
      throw Error("auth: field 'nonce': expected " + std::to_string(kNonceBytes) + " bytes, got " +
                  std::to_string(a.nonce.size()));
    return a;
  }
  if (type == "req") return decode_request(h.get());
  throw Error("message: unknown type '" + one_line(type, 40) + "' (auth, req)");
}

std::string encode_auth(const AuthMessage& a) {
  MapWriter w;
  w.text("t", "auth").bytes("mac", a.mac).bytes("nonce", a.nonce);
  return w.finish();
}

std::string encode_request(const Request& r) {
  MapWriter w;
  w.text("t", "req").unsigned_integer("id", r.id).text("op", op_name(r.op));
  switch (r.op) {
    case Op::Get:
    case Op::LogStart:
    case Op::LogInfo:
    case Op::Value:
      w.text("key", r.key);
      break;
    case Op::Set:
    case Op::Mr:
    case Op::Dr:
      w.text("key", r.key).text("text", r.text);
      break;
    case Op::Subscribe:
      w.texts("keys", r.keys).unsigned_integer("every", r.every);
      break;
    case Op::LogFetch:
      w.text("key", r.key)
          .unsigned_integer("offset", r.offset)
          .unsigned_integer("length", r.length);
      break;
    case Op::Report:
      w.boolean("json", r.on);
      break;
    default:
      break;
  }
  return w.finish();
}

std::string encode_hello(const Hello& h) {
  MapWriter w;
  w.text("t", "hello")
      .unsigned_integer("protocol", h.protocol)
      .text("robot", h.robot)
      .boolean("auth", h.auth)
      .bytes("nonce", h.nonce);
  return w.finish();
}

std::string encode_welcome(const Welcome& wm) {
  MapWriter w;
  w.text("t", "welcome")
      .text("rights", wm.read_only ? "read-only" : "full")
      .bytes("mac", wm.mac)
      .number("period", wm.period);
  return w.finish();
}

std::string encode_denied(std::string_view why) {
  MapWriter w;
  w.text("t", "denied").text("why", why);
  return w.finish();
}

std::string encode_bye(std::string_view why) {
  MapWriter w;
  w.text("t", "bye").text("why", why);
  return w.finish();
}

std::string encode_sample(const Sample& s) {
  MapWriter w;
  w.text("t", "sample")
      .integer("frame", s.frame)
      .number("time", s.time)
      .byte_list("values", s.values)
      .unsigned_integer("dropped", s.dropped);
  // Debug output only when there is some: most samples of most streams have none.
  if (!s.lines.empty()) w.texts("lines", s.lines);
  if (!s.stop.empty()) w.text("stop", s.stop);
  if (!s.debug_keys.empty())
    w.texts("debug_keys", s.debug_keys).numbers("debug_values", s.debug_values);
  return w.finish();
}

std::string encode_error_reply(std::uint64_t id, std::string_view error) {
  MapWriter w;
  w.text("t", "reply")
      .unsigned_integer("id", id)
      .boolean("ok", false)
      .text("error", one_line(error, 2000));
  return w.finish();
}

}  // namespace stride::debug
