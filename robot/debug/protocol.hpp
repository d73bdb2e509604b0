#pragma once
// The debug protocol (version 1), see robot/debug/README.md. Messages are msgpack maps, framed by
// wire.hpp. A connection starts with the server's hello; a client that must authenticate answers
// with auth; after welcome it sends requests and receives replies (same id) and stream samples.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "robot/core/error.hpp"

namespace stride::debug {

inline constexpr std::uint64_t kProtocolVersion = 1;
inline constexpr std::size_t kMaxClientMessage = 64 * 1024;    // requests are short
inline constexpr std::size_t kMaxServerMessage = 1024 * 1024;  // log chunks, large replies
inline constexpr std::size_t kNonceBytes = 32;
inline constexpr std::size_t kMaxSubscribedKeys = 256;
inline constexpr std::uint64_t kMaxLogChunk = 256 * 1024;

enum class Op {
  List,         // representations, providers, parameter modules, debug requests
  Get,          // key: representation:X or module:X (whole value + type description)
  Set,          // key, text: as the console's set
  Mr,           // key: representation, text: module | default
  Dr,           // key: debug request, text: off | on | quiet
  Subscribe,    // keys, every: sampled every `every`-th frame and streamed
  Unsubscribe,  //
  LogStart,     // key: file name in the robot's log directory
  LogStop,      //
  LogInfo,      // key: file name -> size, sha256
  LogFetch,     // key, offset, length -> bytes
  Report,       // on: JSON instead of text
  Ping,         //
  Value,        // key: provider:X, override:X or debug:X.y -> text, as the console prints it
  Restart,      // the scenario from its start: a simulation resets and runs, a robot rebuilds its
                // controller from its configuration (where the server's owner does restarts)
};
std::string_view op_name(Op op);
// Refused on a read-only token: everything that changes the robot.
bool op_writes(Op op);

struct AuthMessage {
  std::string mac;    // HMAC of the server's nonce (auth.hpp)
  std::string nonce;  // the client's nonce, for the server's proof
};

struct Request {
  std::uint64_t id = 0;
  Op op = Op::Ping;
  std::string key;
  std::string text;
  bool on = false;
  std::vector<std::string> keys;
  std::uint64_t every = 1;
  std::uint64_t offset = 0;
  std::uint64_t length = 0;
};

// A request of the common shape: an op with a key and a text.
Request request(Op op, std::string key = {}, std::string text = {});

using ClientMessage = std::variant<AuthMessage, Request>;

// A request whose envelope (type and id) was fine but whose op or fields were not: answered with
// an error reply, where a message that is no request at all ends the connection.
class RequestError : public Error {
 public:
  RequestError(std::uint64_t id, const std::string& message) : Error(message), id(id) {}
  std::uint64_t id;
};

// Decodes and checks one client payload; throws RequestError or stride::Error (one line).
ClientMessage decode_client_message(std::string_view payload);
std::string encode_auth(const AuthMessage& m);
std::string encode_request(const Request& r);

// Server -> client.
struct Hello {
  std::uint64_t protocol = 0;
  std::string robot;
  bool auth = false;
  std::string nonce;
};
struct Welcome {
  bool read_only = false;
  std::string mac;  // the server's proof (empty without auth)
  double period = 0;
};
struct Sample {
  std::int64_t frame = 0;
  double time = 0;
  std::vector<std::string> values;  // encoded sub-values, in subscription order
  std::uint64_t dropped = 0;        // samples this client lost so far (slow reader)
  // Debug output since the previous sample: the lines the debug requests printed, the first
  // request to pause ("" none), and the subscribed debug:X.y values the frame has.
  std::vector<std::string> lines;
  std::string stop;
  std::vector<std::string> debug_keys;
  std::vector<double> debug_values;
};

std::string encode_hello(const Hello& h);
std::string encode_welcome(const Welcome& w);
std::string encode_denied(std::string_view why);
std::string encode_bye(std::string_view why);
std::string encode_sample(const Sample& s);
std::string encode_error_reply(std::uint64_t id, std::string_view error);

}  // namespace stride::debug
