#include "robot/debug/server_message.hpp"

#include "robot/core/error.hpp"
#include "robot/core/one_line.hpp"

namespace stride::debug {

ServerMessage::ServerMessage(std::string_view payload) {
  DecodeLimits limits;
  limits.str = limits.bin = kMaxServerMessage;
  limits.array = 1 << 16;
  limits.map = 256;
  handle_ = std::make_unique<msgpack::object_handle>(decode_msgpack(payload, limits));
  view_ = std::make_unique<MapView>(handle_->get(), "server message");
  type_ = view_->text("t");
  view_ = std::make_unique<MapView>(handle_->get(), "server '" + one_line(type_, 20) + "'");
}

Hello hello_of(const MapView& m) {
  Hello h;
  h.protocol = m.unsigned_integer("protocol", UINT32_MAX);
  h.robot = m.text("robot");
  h.auth = m.boolean("auth");
  h.nonce = m.bytes("nonce");
  if (h.auth && h.nonce.size() != kNonceBytes)
    throw Error("server 'hello': field 'nonce': expected " + std::to_string(kNonceBytes) +
                " bytes, got " + std::to_string(h.nonce.size()));
  return h;
}

Welcome welcome_of(const MapView& m) {
  Welcome w;
  const std::string rights = m.text("rights");
  if (rights != "full" && rights != "read-only")
    throw Error("server 'welcome': field 'rights': expected full or read-only, got '" +
                one_line(rights, 20) + "'");
  w.read_only = rights == "read-only";
  w.mac = m.bytes("mac");
  w.period = m.number("period");
  return w;
}

Sample sample_of(const MapView& m) {
  Sample s;
  s.frame = m.integer("frame");
  s.time = m.number("time");
  s.values = m.byte_list("values");
  s.dropped = m.unsigned_integer("dropped", UINT64_MAX);
  if (m.has("lines")) s.lines = m.texts("lines");
  s.stop = m.text_or("stop", "");
  if (m.has("debug_keys")) {
    s.debug_keys = m.texts("debug_keys");
    s.debug_values = m.numbers("debug_values");
    if (s.debug_values.size() != s.debug_keys.size())
      throw Error("sample: " + std::to_string(s.debug_keys.size()) + " debug keys but " +
                  std::to_string(s.debug_values.size()) + " values");
  }
  return s;
}

}  // namespace stride::debug
