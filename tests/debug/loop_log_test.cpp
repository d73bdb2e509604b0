// A client's log is the loop side's own: it records every frame of the runtime it was started on,
// and when that runtime goes (a console's reset or load while serving) the log stops with a note
// to its client instead of reading the blackboard of a runtime that is gone: on the loop side
// alone, and through a console's `serve` with a real client over loopback.
#include <filesystem>
#include <memory>
#include <thread>

#include <gtest/gtest.h>

#include "console/target/local_target.hpp"
#include "robot/debug/debug_client.hpp"
#include "robot/debug/loop_side.hpp"
#include "tests/debug/served_process.hpp"
#include "tests/framework/fake_link.hpp"
#include "tests/lola/child_process.hpp"

namespace stride::test {
namespace {

// The notes the loop side passed to the server thread (other messages are dropped).
std::vector<std::string> notes(debug::Exchange& x) {
  std::vector<std::string> out;
  debug::LoopMessage m;
  while (x.to_server.try_pop(m))
    if (m.kind == debug::LoopMessage::Kind::Note) out.push_back(m.reply.text);
  return out;
}

TEST(DebugLoopLog, ALogStopsWithANoteWhenItsRuntimeIsReplaced) {
  const std::string path = ChildProcess::scratch("replaced.log");
  std::filesystem::remove(path);
  debug::Exchange x;
  debug::LoopSide loop(x, "testbot");
  const ModuleRegistry registry = test_registry();
  FakeLink link;
  auto first = std::make_unique<Runtime>(registry, test_config(), link);
  first->set_frame_boundary(&loop);
  debug::LoopRequest start;
  start.client = 7;
  start.request = debug::request(debug::Op::LogStart, "replaced.log");
  start.path = path;
  ASSERT_TRUE(x.requests.try_push(start));
  for (int i = 0; i < 4; ++i) first->step();  // the log starts after frame 0, then 3 frames
  EXPECT_TRUE(notes(x).empty());
  first->set_frame_boundary(nullptr);  // what a console serving it does before a reset or load
  first.reset();
  EXPECT_EQ(notes(x).size(), 0u);  // told at the next boundary, on the loop's side of the ring
  Runtime second(registry, test_config(), link);
  second.set_frame_boundary(&loop);
  for (int i = 0; i < 3; ++i) second.step();
  const auto said = notes(x);
  ASSERT_EQ(said.size(), 1u);
  EXPECT_EQ(said[0],
            "log 'replaced.log' stopped after 3 frames: the robot's controller was replaced (reset "
            "or load)");
  EXPECT_EQ(LogReader(path).frame_count(), 3u);  // nothing written from the second runtime
  second.set_frame_boundary(nullptr);
}

// Steps `target` (bounded) until the log at `path` holds a frame.
bool frames_appear(console::LocalTarget& target, const std::string& path) {
  for (int i = 0; i < 1000; ++i) {
    target.advance(1, {});
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    try {
      if (std::filesystem::exists(path) && LogReader(path).frame_count() > 0) return true;
    } catch (const Error&) {  // created, its header not written yet
    }
  }
  return false;
}

TEST(DebugLoopLog, AServingConsolesResetAndLoadStopAClientsLog) {
  const std::string dir = fresh_dir("serve_reset");
  console::LocalTarget target(kStandScene);
  debug::ServerOptions options;
  options.listen = {"127.0.0.1", 0};
  options.log_dir = dir;
  options.log = [](const std::string&) {};
  const debug::Endpoint at = target.serve(options);
  debug::DebugClient client(at, "");
  for (const std::string name : {"before_reset.log", "before_load.log"}) {
    // The loop runs only inside advance(): the request is sent, then the loop stepped until the
    // log has frames.
    client.send_only(debug::request(debug::Op::LogStart, name));
    ASSERT_TRUE(frames_appear(target, dir + "/" + name)) << name;
    if (name == "before_reset.log")
      target.reset();
    else
      target.load(kStandScene);
    target.advance(100, {});  // simulation steps: a few control frames of the new controller
    std::vector<std::string> said;
    for (int i = 0; i < 200 && said.empty(); ++i) {
      client.keep_alive();
      said = client.take_notes();
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ASSERT_EQ(said.size(), 1u) << name;
    EXPECT_NE(said[0].find("log '" + name + "' stopped after "), std::string::npos) << said[0];
    EXPECT_NE(said[0].find("replaced (reset or load)"), std::string::npos) << said[0];
    EXPECT_GT(LogReader(dir + "/" + name).frame_count(), 0u);
  }
  client.call(debug::request(debug::Op::Ping));  // still served, by the new scene's controller
}

}  // namespace
}  // namespace stride::test
