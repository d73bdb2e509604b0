// The restart side channel beside LoLA (robot/hal/lola/simulator_restart.hpp): a robot asks, the
// simulator's listener takes the request once and answers done; no listener (a NAO) is no ask;
// a hostile or vanishing peer never makes the listener block or take a request.
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "robot/hal/lola/simulator_restart.hpp"
#include "simulator/lola/lola_restart_listener.hpp"
#include "tests/lola/child_process.hpp"

namespace stride {
namespace {

using hal::lola::SimulatorRestart;

TEST(RestartChannel, NothingListeningIsNoAsk) {
  const std::string lola = test::ChildProcess::scratch("none.sock");
  EXPECT_FALSE(SimulatorRestart::ask(lola).has_value());
  std::ofstream(hal::lola::simulator_restart_path(lola)) << "a file, not a socket";
  EXPECT_FALSE(SimulatorRestart::ask(lola).has_value());
}

TEST(RestartChannel, AskedOnceAnsweredDone) {
  const std::string lola = test::ChildProcess::scratch("asked.sock");
  sim::LolaRestartListener listener(lola);
  EXPECT_FALSE(listener.take_request());
  auto ask = SimulatorRestart::ask(lola);
  ASSERT_TRUE(ask.has_value());
  EXPECT_FALSE(ask->done());
  bool taken = false;
  for (int i = 0; i < 1000 && !taken; ++i) taken = listener.take_request();
  ASSERT_TRUE(taken);
  listener.answer_done();
  bool done = false;
  for (int i = 0; i < 1000 && !done; ++i) done = ask->done();
  EXPECT_TRUE(done);
  EXPECT_TRUE(ask->done());               // stays said
  EXPECT_FALSE(listener.take_request());  // taken once
}

TEST(RestartChannel, HostilePeersTakeNoRequestAndBlockNothing) {
  const std::string lola = test::ChildProcess::scratch("hostile.sock");
  sim::LolaRestartListener listener(lola);
  const std::string path = hal::lola::simulator_restart_path(lola);
  {
    auto garbage = hal::UnixSocket::connect(path);
    ASSERT_TRUE(garbage.send_all(std::string(200, 'x')));
    for (int i = 0; i < 100; ++i) EXPECT_FALSE(listener.take_request());
  }
  {
    auto silent = hal::UnixSocket::connect(path);
    for (int i = 0; i < 100; ++i) EXPECT_FALSE(listener.take_request());
  }  // and gone
  for (int i = 0; i < 100; ++i) EXPECT_FALSE(listener.take_request());
  auto ask = SimulatorRestart::ask(lola);  // a real ask after them still works
  ASSERT_TRUE(ask.has_value());
  bool taken = false;
  for (int i = 0; i < 1000 && !taken; ++i) taken = listener.take_request();
  EXPECT_TRUE(taken);
}

}  // namespace
}  // namespace stride
