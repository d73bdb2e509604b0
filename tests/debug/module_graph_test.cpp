// The module graph in the debug protocol's `list` reply: every registered module with what it
// requires and provides round-trips through the encoder and decoder, a server from before it
// reads as "not said", and over real TCP the console's RemoteTarget gets the robot's declarations.
#include <gtest/gtest.h>

#include "console/target/remote_target.hpp"
#include "robot/debug/msgpack_map.hpp"
#include "robot/debug/server_message.hpp"
#include "tests/debug/robot_loop.hpp"
#include "tests/error_text.hpp"

namespace stride::test {
namespace {

using debug::MapWriter;
using debug::ServerMessage;

bool same(const ModuleDeclaration& a, const ModuleDeclaration& b) {
  return a.name == b.name && a.requires_ == b.requires_ && a.provides == b.provides;
}

std::string reply_with_graph(const std::vector<ModuleDeclaration>& modules) {
  MapWriter w;
  w.text("t", "reply").unsigned_integer("id", 7).boolean("ok", true);
  debug::write_module_graph(w, modules);
  return w.finish();
}

TEST(DebugModuleGraph, RequiresAndProvidesRoundTripInOrder) {
  const std::vector<ModuleDeclaration> modules = {
      {"PatternWalk", {"FrameInfo", "WalkCommand"}, {"WalkingPattern", "WalkPlan"}},
      {"Stand", {"FrameInfo"}, {"JointRequest"}},
      {"Quiet", {}, {}}};
  const ServerMessage m(reply_with_graph(modules));
  const auto back = debug::module_graph_of(m.fields());
  ASSERT_TRUE(back.has_value());
  ASSERT_EQ(back->size(), 3u);
  for (std::size_t i = 0; i < modules.size(); ++i)
    EXPECT_TRUE(same((*back)[i], modules[i])) << modules[i].name;
  EXPECT_EQ((*back)[0].requires_, (std::vector<std::string>{"FrameInfo", "WalkCommand"}));
  EXPECT_TRUE((*back)[2].provides.empty());
}

TEST(DebugModuleGraph, AnOlderServersListSaysNothingAndBadListsAreOneLine) {
  MapWriter old;
  old.text("t", "reply").unsigned_integer("id", 7).boolean("ok", true).texts("order", {"Stand"});
  EXPECT_FALSE(debug::module_graph_of(ServerMessage(old.finish()).fields()).has_value());

  MapWriter bad;
  bad.text("t", "reply")
      .texts("graph_modules", {"A", "B"})
      .text_lists("graph_requires", {{"X"}})
      .text_lists("graph_provides", {{}, {"Y"}});
  EXPECT_EQ(
      test_support::error_of([&] { debug::module_graph_of(ServerMessage(bad.finish()).fields()); }),
      "reply 'list': 2 graph_modules but 1 graph_requires and 2 graph_provides");

  MapWriter wrong;
  wrong.text("t", "reply").texts("graph_modules", {"A"}).texts("graph_requires", {"X"});
  const std::string e = test_support::error_of(
      [&] { debug::module_graph_of(ServerMessage(wrong.finish()).fields()); });
  EXPECT_NE(e.find("graph_requires"), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

TEST(DebugModuleGraph, RemoteTargetGetsEveryModulesDeclarationsOverTcp) {
  RobotLoop loop(loopback_options());
  console::RemoteTarget remote(loop.endpoint(), "");
  const auto got = remote.module_declarations();
  ASSERT_TRUE(got.has_value());
  const std::vector<ModuleDeclaration>& local = loop.runtime().module_declarations();
  ASSERT_EQ(got->size(), local.size());
  for (std::size_t i = 0; i < local.size(); ++i)
    EXPECT_TRUE(same((*got)[i], local[i])) << local[i].name;
  // What the test modules declare, as written in tests/framework/fake_link.hpp.
  auto find = [&](const std::string& name) {
    for (const auto& d : *got)
      if (d.name == name) return d;
    ADD_FAILURE() << name << " not in the graph";
    return ModuleDeclaration{};
  };
  EXPECT_EQ(find("CounterAfterStand").requires_,
            (std::vector<std::string>{"FrameInfo", "JointRequest"}));
  EXPECT_EQ(find("CounterAfterStand").provides, (std::vector<std::string>{"Counter"}));
  EXPECT_EQ(find("Doubler").requires_, (std::vector<std::string>{"Counter"}));
  EXPECT_EQ(find("Doubler").provides, (std::vector<std::string>{"Doubled"}));
}

}  // namespace
}  // namespace stride::test
