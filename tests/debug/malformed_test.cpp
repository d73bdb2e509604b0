// Malformed messages from a client over real TCP: a request whose envelope holds gets an error
// reply naming the field and the connection stays; anything else ends that client's connection
// with one log line naming its address and the field. Neither changes the robot, and the other
// clients go on being served.
#include <sys/socket.h>

#include <thread>

#include <gtest/gtest.h>

#include "robot/debug/debug_client.hpp"
#include "robot/debug/msgpack_map.hpp"
#include "robot/debug/wire.hpp"
#include "tests/debug/robot_loop.hpp"

namespace stride::test {
namespace {

using debug::DebugClient;
using debug::Op;
using debug::Request;

void send_framed(const debug::Fd& fd, const std::string& payload) {
  std::string framed;
  debug::append_frame(framed, payload);
  ASSERT_EQ(::send(fd.get(), framed.data(), framed.size(), MSG_NOSIGNAL),
            static_cast<ssize_t>(framed.size()));
}

// Reads framed server messages until one of type `type` (bounded by the socket's timeout).
std::unique_ptr<debug::ServerMessage> read_until(const debug::Fd& fd, const std::string& type) {
  debug::FrameReader in(debug::kMaxServerMessage);
  char buffer[4096];
  for (int i = 0; i < 100; ++i) {
    while (auto payload = in.next()) {
      auto m = std::make_unique<debug::ServerMessage>(*payload);
      if (m->type() == type) return m;
    }
    const ssize_t n = ::recv(fd.get(), buffer, sizeof buffer, 0);
    if (n <= 0) return nullptr;
    in.feed(std::string_view(buffer, static_cast<std::size_t>(n)));
  }
  return nullptr;
}

std::string knee_text(DebugClient& c) {
  Request r;
  r.op = Op::Get;
  r.key = "module:Stand";
  return c.call(r)->fields().bytes("value");
}

TEST(DebugMalformed, BadFieldsAreOneLineNamingPeerAndFieldAndChangeNothing) {
  RobotLoop loop(loopback_options());
  DebugClient honest(loop.endpoint(), "");
  const std::string before = knee_text(honest);

  // The envelope holds (type, id), the op's field does not: an error reply, the connection stays.
  debug::Fd raw = debug::connect_tcp(loop.endpoint(), 2);
  ASSERT_TRUE(read_until(raw, "welcome"));
  debug::MapWriter bad_key;
  bad_key.text("t", "req").unsigned_integer("id", 7).text("op", "set").unsigned_integer("key", 3);
  send_framed(raw, bad_key.finish());
  const auto reply = read_until(raw, "reply");
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->fields().unsigned_integer("id", UINT64_MAX), 7u);
  const std::string error = reply->fields().text("error");
  EXPECT_NE(error.find("field 'key'"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;

  // No request at all (an id that is text): the server ends this client, logging it once.
  debug::MapWriter bad_id;
  bad_id.text("t", "req").text("id", "seven").text("op", "get");
  send_framed(raw, bad_id.finish());
  EXPECT_TRUE(read_until(raw, "denied"));
  for (int i = 0; i < 200 && loop.log_count("rejected 127.0.0.1:") == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_EQ(loop.log_count("rejected 127.0.0.1:"), 1u);
  EXPECT_EQ(loop.log_count("field 'id'"), 1u);

  // A set with an invalid value: the local console's error, and nothing changed.
  Request set;
  set.op = Op::Set;
  set.key = "module:Stand";
  set.text = "knee_pitch=99";
  EXPECT_THROW(honest.call(set), Error);
  EXPECT_EQ(knee_text(honest), before);
  EXPECT_EQ(loop.server().stats().clients, 1u);
  const std::int64_t frames = loop.frames();
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_GT(loop.frames(), frames);  // the loop went on (its timing is the load run's to judge)
  loop.stop();
}

}  // namespace
}  // namespace stride::test
