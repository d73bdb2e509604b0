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

void write_module_graph(MapWriter& w, const std::vector<ModuleDeclaration>& modules) {
  std::vector<std::string> names;
  std::vector<std::vector<std::string>> requires_, provides;
  for (const ModuleDeclaration& d : modules) {
    names.push_back(d.name);
    requires_.push_back(d.requires_);
    provides.push_back(d.provides);
  }
  w.texts("graph_modules", names)
      .text_lists("graph_requires", requires_)
      .text_lists("graph_provides", provides);
}

std::optional<std::vector<ModuleDeclaration>> module_graph_of(const MapView& m) {
  if (!m.has("graph_modules")) return std::nullopt;
  const std::vector<std::string> names = m.texts("graph_modules");
  auto requires_ = m.text_lists("graph_requires");
  auto provides = m.text_lists("graph_provides");
  if (requires_.size() != names.size() || provides.size() != names.size())
    throw Error("reply 'list': " + std::to_string(names.size()) + " graph_modules but " +
                std::to_string(requires_.size()) + " graph_requires and " +
                std::to_string(provides.size()) + " graph_provides");
  std::vector<ModuleDeclaration> out(names.size());
  for (std::size_t i = 0; i < names.size(); ++i)
    out[i] = {names[i], std::move(requires_[i]), std::move(provides[i])};
  return out;
}

}  // namespace stride::debug
