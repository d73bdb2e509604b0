// `kill -9` during a logged run, with the real process: every frame written before the kill loads
// with its checksum verified (at most the frame being written is cut short), and a replay of all
// of them through the scene's controller matches bit for bit.
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <thread>

#include "console/session/sim_session.hpp"
#include "robot/runtime/replay.hpp"
#include "tests/hostile/hostile_support.hpp"

extern char** environ;

namespace stride::hostile {
namespace {

TEST(KillNine, EveryFrameBeforeTheKillLoadsAndReplaysWithChecksums) {
  Scratch s;
  const std::string scene = source_path("scenes/nao_stand_controlled.xml");
  const std::string log = s.path("killed.log");
  std::vector<std::string> args = {stride_binary(), "run", scene, "--seconds", "600", "--log", log};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  ASSERT_EQ(posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ), 0);
  // Until at least 40 frames are on disk (bounded: 120 s), then SIGKILL mid-run.
  std::size_t seen = 0;
  for (int i = 0; i < 1200 && seen < 40; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    try {
      seen = LogReader(log).integrity().complete;
    } catch (const Error&) {  // the header may not be there yet
    }
  }
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
  ASSERT_GE(seen, 40u) << "the run did not log 40 frames in time";

  const LogReader r(log);
  EXPECT_EQ(r.integrity().version, 2);
  EXPECT_GE(r.integrity().complete, seen);
  EXPECT_EQ(r.integrity().damaged, 0u) << r.summary();
  EXPECT_LE(r.integrity().truncated, 1u);
  EXPECT_EQ(r.readable_prefix(), r.frame_count());
  console::SimSession session(scene);
  const ReplayResult replay = replay_and_compare(r, session.registry(), session.runtime_config(0));
  EXPECT_EQ(replay.frames, r.frame_count());
  EXPECT_FALSE(replay.stopped_before_damaged);
  EXPECT_TRUE(replay.mismatches.empty())
      << replay.mismatches.size() << " mismatches, first in "
      << (replay.mismatches.empty() ? "" : replay.mismatches[0].representation);
  // The console says the same.
  const auto load = run_stride({"-c", "log load " + log + "; log replay", scene});
  EXPECT_EQ(load.exit_status, 0) << load.err;
  EXPECT_NE(load.out.find(std::to_string(r.frame_count()) +
                          " frames: " + std::to_string(r.frame_count()) + " complete, 0 damaged"),
            std::string::npos)
      << load.out;
  EXPECT_NE(load.out.find(" 0 mismatch(es)"), std::string::npos) << load.out;
}

}  // namespace
}  // namespace stride::hostile
