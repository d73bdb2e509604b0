// The debug server over real TCP on loopback against a robot loop running in real time: every
// request answers as the same console command answers locally, streams carry every frame in
// order, and the server's security and limits hold.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "robot/debug/debug_client.hpp"
#include "robot/debug/log_directory.hpp"
#include "tests/debug/robot_loop.hpp"

namespace stride::test {
namespace {

namespace fs = std::filesystem;
using debug::DebugClient;
using debug::Op;
using debug::Request;
using debug::request;

// The text of `key` in a get reply, decoded from the type description that came with it.
std::string text_of(const debug::ServerMessage& reply, const std::string& path,
                    const std::string& name) {
  const std::string desc_bytes = reply.fields().bytes("desc");
  const std::string value_bytes = reply.fields().bytes("value");
  ByteReader d(desc_bytes);
  const TypeDescPtr desc = read_type_desc(d);
  ByteReader v(value_bytes);
  const Value value = read_value(*desc, v);
  const auto [sub_desc, sub] = value_at(*desc, value, path, name);
  return print_value(*sub_desc, *sub);
}

std::string error_of(DebugClient& c, Request r) {
  try {
    c.call(std::move(r));
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// What a local Runtime answers to the same set: the remote error must be this very line.
std::string local_set_error(const std::string& key, const std::string& text) {
  auto registry = test_registry();
  FakeLink link;
  Runtime rt(registry, test_config(), link);
  try {
    rt.set(key, text);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(DebugServer, GetSetMrAndDrAnswerAsTheLocalConsoleDoes) {
  RobotLoop loop(loopback_options());
  DebugClient c(loop.endpoint(), "");
  EXPECT_EQ(c.hello().robot, "testbot");
  EXPECT_FALSE(c.hello().auth);
  EXPECT_FALSE(c.welcome().read_only);

  c.call(request(Op::Set, "module:Stand", "knee_pitch=0.5 hip_pitch=-0.2"));
  auto got = c.call(request(Op::Get, "module:Stand"));
  EXPECT_EQ(text_of(*got, "knee_pitch", "Stand"), "0.5");
  EXPECT_EQ(text_of(*got, "hip_pitch", "Stand"), "-0.2");
  // A bad second field leaves every field as it was, with the local console's own message.
  const std::string bad = "knee_pitch=0.7 hip_pitch=9";
  EXPECT_EQ(error_of(c, request(Op::Set, "module:Stand", bad)),
            local_set_error("module:Stand", bad));
  EXPECT_EQ(text_of(*c.call(request(Op::Get, "module:Stand")), "knee_pitch", "Stand"), "0.5");
  EXPECT_EQ(error_of(c, request(Op::Get, "representation:NoSuch")),
            "no representation 'NoSuch' on the blackboard");

  // Counter = frame number; after mr it is -1000 - frame, in the very frame the reply names.
  got = c.call(request(Op::Get, "representation:Counter"));
  EXPECT_EQ(text_of(*got, "n", "Counter"), std::to_string(got->fields().integer("frame")));
  EXPECT_EQ(c.call(request(Op::Mr, "Counter", "CounterAfterStand"))->fields().text("provider"),
            "CounterAfterStand");
  got = c.call(request(Op::Get, "representation:Counter"));
  EXPECT_EQ(text_of(*got, "n", "Counter"), std::to_string(-1000 - got->fields().integer("frame")));
  EXPECT_NE(error_of(c, request(Op::Mr, "Counter", "NoSuchModule")), "");

  c.call(request(Op::Dr, "test:negate", "on"));
  got = c.call(request(Op::Get, "representation:Doubled"));
  EXPECT_EQ(text_of(*got, "n", "Doubled"),
            std::to_string(-2 * (-1000 - got->fields().integer("frame"))));
  loop.stop();
  EXPECT_EQ(loop.runtime().debug_requests()[0].second, DebugSwitch::On);
  EXPECT_EQ(loop.runtime().provider_of("Counter"), "CounterAfterStand");
}

TEST(DebugServer, ListNamesRepresentationsProvidersModulesAndDebugRequests) {
  RobotLoop loop(loopback_options());
  DebugClient c(loop.endpoint(), "");
  const auto m = c.call(request(Op::List));
  const auto& f = m->fields();
  const auto reps = f.texts("representations");
  const auto providers = f.texts("providers");
  ASSERT_EQ(reps.size(), providers.size());
  const auto at = std::find(reps.begin(), reps.end(), "Counter") - reps.begin();
  ASSERT_LT(at, static_cast<long>(reps.size()));
  EXPECT_EQ(providers[at], "CounterFromFrame");
  EXPECT_EQ(f.text_lists("available")[at],
            (std::vector<std::string>{"CounterAfterStand", "CounterFromFrame"}));
  EXPECT_EQ(f.texts("modules"), (std::vector<std::string>{"SensorConversion", "Stand"}));
  EXPECT_EQ(f.texts("debug"), (std::vector<std::string>{"test:negate", "robot:stop_on_fall"}));
  EXPECT_EQ(f.texts("debug_state"), (std::vector<std::string>{"off", "off"}));
  EXPECT_DOUBLE_EQ(f.number("period"), 0.01);
  const std::string report = c.call(request(Op::Report))->fields().text("text");
  EXPECT_NE(report.find("robot testbot: frame "), std::string::npos) << report;
  EXPECT_NE(report.find("Counter <- CounterFromFrame"), std::string::npos) << report;
}

// A list builds the robot's whole state on the loop: a burst of them (a view opening, several
// consoles at once) is answered one a frame, so no single boundary does them all; a list right
// after an mr names the new provider.
TEST(DebugServer, ListsInABurstAreAnsweredOneAFrame) {
  RobotLoop loop(loopback_options(), 0.02);
  std::vector<std::unique_ptr<DebugClient>> clients;
  for (int i = 0; i < 4; ++i) clients.push_back(std::make_unique<DebugClient>(loop.endpoint(), ""));
  std::vector<std::int64_t> frames(clients.size());
  std::atomic<int> ready{0};
  std::vector<std::thread> asking;
  for (std::size_t i = 0; i < clients.size(); ++i)
    asking.emplace_back([&, i] {
      ++ready;
      while (ready < static_cast<int>(clients.size())) std::this_thread::yield();
      frames[i] = clients[i]->call(request(Op::List))->fields().integer("frame");
    });
  for (auto& t : asking) t.join();
  std::sort(frames.begin(), frames.end());
  EXPECT_EQ(std::adjacent_find(frames.begin(), frames.end()), frames.end())
      << "two lists answered at one boundary";
  DebugClient& c = *clients[0];
  Request mr = request(Op::Mr, "Counter");
  mr.text = "CounterAfterStand";
  c.send_only(std::move(mr));
  const auto m = c.call(request(Op::List));
  const auto reps = m->fields().texts("representations");
  const auto at = std::find(reps.begin(), reps.end(), "Counter") - reps.begin();
  ASSERT_LT(at, static_cast<long>(reps.size()));
  EXPECT_EQ(m->fields().texts("providers")[at], "CounterAfterStand");
}

TEST(DebugServer, StreamsEveryFrameInOrderAndEveryKth) {
  RobotLoop loop(loopback_options(), 0.005);
  DebugClient c(loop.endpoint(), "");
  Request sub = request(Op::Subscribe);
  sub.keys = {"representation:Counter.n", "representation:FrameInfo.frame",
              "representation:JointRequest.position[10]"};
  const auto reply = c.call(sub);
  const std::int64_t from = reply->fields().integer("from");
  const auto descs = reply->fields().byte_list("descs");
  ASSERT_EQ(descs.size(), 3u);
  ByteReader dr(descs[0]);
  const TypeDescPtr n_desc = read_type_desc(dr);
  EXPECT_EQ(n_desc->kind, Kind::Int64);
  for (std::int64_t expected = from; expected < from + 100; ++expected) {
    auto s = c.next_sample(2);
    ASSERT_TRUE(s);
    ASSERT_EQ(s->dropped, 0u);
    ASSERT_EQ(s->frame, expected);
    ByteReader v(s->values[0]);
    EXPECT_EQ(std::get<std::int64_t>(read_value(*n_desc, v).data), expected);
  }
  sub.every = 7;
  const std::int64_t from7 = c.call(sub)->fields().integer("from");
  c.drop_samples();
  for (int i = 0; i < 10; ++i) {
    auto s = c.next_sample(2);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->frame, from7 + 7 * i);
  }
  sub.keys = {"representation:Counter.nope"};
  EXPECT_EQ(error_of(c, sub), "Counter: no field 'nope' (fields: n)");
}

TEST(DebugServer, TokensProveBothWaysAndReadOnlyTokensCannotWrite) {
  debug::ServerOptions open_to_all = loopback_options();
  open_to_all.listen = {"0.0.0.0", 0};
  try {
    debug::DebugServer refused(open_to_all);
    FAIL() << "a server off loopback without a token started";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("needs a token"), std::string::npos) << e.what();
  }
  debug::ServerOptions o = loopback_options();
  o.tokens = {{"full-token-0123456789", false}, {"read-token-0123456789", true}};
  RobotLoop loop(o);
  try {
    DebugClient none(loop.endpoint(), "");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("asks for a token"), std::string::npos) << e.what();
  }
  try {
    DebugClient wrong(loop.endpoint(), "guessed-token-0123456");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("wrong token"), std::string::npos) << e.what();
  }
  DebugClient full(loop.endpoint(), "full-token-0123456789");
  EXPECT_FALSE(full.welcome().read_only);
  full.call(request(Op::Set, "module:Stand", "stiffness=0.5"));
  DebugClient reader(loop.endpoint(), "read-token-0123456789");
  EXPECT_TRUE(reader.welcome().read_only);
  EXPECT_EQ(text_of(*reader.call(request(Op::Get, "module:Stand")), "stiffness", "Stand"), "0.5");
  for (Op op : {Op::Set, Op::Mr, Op::Dr, Op::LogStart})
    EXPECT_NE(error_of(reader, request(op, "module:Stand", op == Op::Dr ? "on" : "stiffness=0.1"))
                  .find("read-only"),
              std::string::npos)
        << op_name(op);
  EXPECT_EQ(loop.log_count("wrong token"), 1u);
  EXPECT_EQ(loop.log_count("asks for a token"), 0u);  // the client gave up before answering
}

TEST(DebugServer, LogsStartStopAndDownloadByteForByteOnlyInsideTheLogDirectory) {
  const fs::path dir =
      fs::temp_directory_path() / ("stride_debug_logs_" + std::to_string(getpid()));
  fs::create_directories(dir);
  debug::ServerOptions o = loopback_options();
  o.log_dir = dir.string();
  RobotLoop loop(o);
  DebugClient c(loop.endpoint(), "");
  EXPECT_EQ(c.call(request(Op::LogStart, "run1.log"))->fields().text("file"), "run1.log");
  EXPECT_NE(error_of(c, request(Op::LogStart, "run2.log")).find("already"), std::string::npos);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const auto stopped = c.call(request(Op::LogStop));
  const std::uint64_t frames = stopped->fields().unsigned_integer("frames", UINT64_MAX);
  EXPECT_GT(frames, 5u);
  EXPECT_EQ(LogReader((dir / "run1.log").string()).frame_count(), frames);

  const auto info = c.call(request(Op::LogInfo, "run1.log"));
  const std::uint64_t size = info->fields().unsigned_integer("size", UINT64_MAX);
  EXPECT_EQ(size, fs::file_size(dir / "run1.log"));
  EXPECT_EQ(info->fields().bytes("sha256"), debug::file_sha256((dir / "run1.log").string()));
  std::string downloaded;
  for (std::uint64_t offset = 0; offset < size;) {
    Request r = request(Op::LogFetch, "run1.log");
    r.offset = offset;
    r.length = 1000;  // several chunks
    const std::string data = c.call(r)->fields().bytes("data");
    ASSERT_FALSE(data.empty());
    downloaded += data;
    offset += data.size();
  }
  std::ifstream in(dir / "run1.log", std::ios::binary);
  std::stringstream file;
  file << in.rdbuf();
  EXPECT_EQ(downloaded, file.str());
  for (const char* name : {"../run1.log", "/etc/passwd", ".hidden", "a/b.log"}) {
    EXPECT_NE(error_of(c, request(Op::LogInfo, name)).find("expected a plain name"),
              std::string::npos)
        << name;
    EXPECT_NE(error_of(c, request(Op::LogStart, name)).find("expected a plain name"),
              std::string::npos)
        << name;
  }
  fs::remove_all(dir);
}

TEST(DebugServer, LimitsOnClientsRequestRateIdleAndHandshake) {
  debug::ServerOptions o = loopback_options();
  o.max_clients = 2;
  o.request_rate = 20;
  o.idle_timeout = 0.5;
  RobotLoop loop(o);
  DebugClient a(loop.endpoint(), ""), b(loop.endpoint(), "");
  try {
    DebugClient third(loop.endpoint(), "");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("too many clients (limit 2)"), std::string::npos)
        << e.what();
  }
  int refused = 0;
  for (int i = 0; i < 50; ++i)
    refused += error_of(a, request(Op::Ping)).find("requests per second") != std::string::npos;
  EXPECT_GE(refused, 20);  // a burst of 20 passes, then about one in 20 ms
  EXPECT_LE(refused, 30);
  std::this_thread::sleep_for(std::chrono::milliseconds(1200));  // b says nothing for too long
  EXPECT_THROW(b.call(request(Op::Ping)), debug::ConnectionLost);
  EXPECT_EQ(loop.log_count("disconnected: idle for 0.50 s"), 2u);  // a too, after its burst

  debug::ServerOptions t = loopback_options();
  t.tokens = {{"full-token-0123456789", false}};
  t.handshake_timeout = 0.3;
  RobotLoop guarded(t);
  debug::Fd silent = debug::connect_tcp(guarded.endpoint(), 1);  // never authenticates
  std::this_thread::sleep_for(std::chrono::milliseconds(800));
  EXPECT_EQ(guarded.log_count("no authentication within 0.30 s"), 1u);
  EXPECT_EQ(guarded.server().stats().rejected, 1u);
}

}  // namespace
}  // namespace stride::test
