#pragma once
// A page's WebSocket message (console/view/PROTOCOL.md, "Page -> bridge") decoded into a typed
// request; anything else is a one-line error saying what was expected.
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace stride::view {

inline constexpr std::size_t kMaxWatchKeys = 64;

struct CmdRequest {
  std::int64_t id = 0;
  std::string line;
};
struct WatchRequest {
  std::vector<std::string> keys;
};
struct TreeRequest {};
struct GetRequest {
  std::int64_t id = 0;
  std::string key;
};
struct TimesRequest {  // the page shows module times (its module graph): frames carry them
  bool on = false;
};
struct AuthRequest {
  std::string nonce;  // hex, as sent
  std::string proof;  // hex
};

using ViewRequest =
    std::variant<CmdRequest, WatchRequest, TreeRequest, GetRequest, TimesRequest, AuthRequest>;

// Throws stride::Error("ws message: ...") naming what was expected; never anything else.
ViewRequest decode_view_message(std::string_view text);

}  // namespace stride::view
