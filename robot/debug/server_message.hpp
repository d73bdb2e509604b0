#pragma once
// A message from the debug server as the client sees it: its type ("hello", "welcome", "denied",
// "reply", "sample", "bye") and its fields, with typed readers for the fixed kinds.
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "robot/debug/msgpack_map.hpp"
#include "robot/debug/protocol.hpp"
#include "robot/framework/plan.hpp"

namespace stride::debug {

class ServerMessage {
 public:
  // Throws stride::Error on anything that is not a map with a string "t".
  explicit ServerMessage(std::string_view payload);
  const std::string& type() const { return type_; }
  const MapView& fields() const { return *view_; }

 private:
  std::unique_ptr<msgpack::object_handle> handle_;  // the fields point into its zone
  std::unique_ptr<MapView> view_;
  std::string type_;
};

Hello hello_of(const MapView& m);
Welcome welcome_of(const MapView& m);
Sample sample_of(const MapView& m);

// A `list` reply's module graph: every registered module with what it requires and provides, as
// graph_modules, graph_requires and graph_provides (parallel lists). Servers from before it sent
// none: nullopt. Lists of different lengths throw (one line).
void write_module_graph(MapWriter& w, const std::vector<ModuleDeclaration>& modules);
std::optional<std::vector<ModuleDeclaration>> module_graph_of(const MapView& m);

}  // namespace stride::debug
