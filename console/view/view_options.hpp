#pragma once
// The server options of `stride view` and the console's `view`, by one rule (PROTOCOL.md "Who
// may connect"): a token file always asks pages for a token; beyond loopback one is required.
#include <string>

#include "console/view/web_server.hpp"

namespace stride::view {

// `listen` is "[host:]port"; `token_file` may be empty (then STRIDE_TOKEN counts beyond
// loopback only). Throws stride::Error naming `what` on a bad address or a missing token.
WebServerOptions view_server_options(const std::string& listen, const std::string& token_file,
                                     const std::string& what);

}  // namespace stride::view
