#include "console/view/view_options.hpp"

#include "robot/core/error.hpp"
#include "robot/debug/socket_io.hpp"

namespace stride::view {

WebServerOptions view_server_options(const std::string& listen, const std::string& token_file,
                                     const std::string& what) {
  const debug::Endpoint at = debug::parse_endpoint(listen, what);
  WebServerOptions o;
  o.address = at.host == "localhost" ? "127.0.0.1" : at.host;
  o.port = at.port;
  o.tokens = debug::tokens_from(token_file);
  if (token_file.empty() && loopback_address(o.address)) o.tokens.clear();
  if (o.tokens.empty() && !loopback_address(o.address))
    throw Error(what + ": " + o.address +
                " is not a loopback address: give a token file (or STRIDE_TOKEN)");
  o.roots = default_web_roots();
  return o;
}

}  // namespace stride::view
