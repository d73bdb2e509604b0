// `stride robot --rt-priority`: the control loop under SCHED_FIFO as on the NAO, every other
// thread (the debug server's) time-shared; a bad priority is a one-line error before anything runs.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "tests/lola/lola_test_support.hpp"

namespace stride {
namespace {

using test::ChildProcess;

struct ThreadPolicy {
  int policy = -1;       // 0 SCHED_OTHER, 1 SCHED_FIFO
  int rt_priority = -1;  // 1..99 under SCHED_FIFO
};

// Fields 40 and 41 of /proc/<pid>/task/<tid>/stat (proc(5)), counted after the command name.
ThreadPolicy policy_of(int pid, const std::string& tid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/task/" + tid + "/stat");
  std::string stat((std::istreambuf_iterator<char>(in)), {});
  std::istringstream rest(stat.substr(stat.rfind(')') + 2));
  std::vector<std::string> fields{"pid", "comm"};
  for (std::string f; rest >> f;) fields.push_back(f);
  if (fields.size() < 41) return {};
  return {std::stoi(fields[40]), std::stoi(fields[39])};
}

TEST(RtPriority, RobotLoopRunsUnderFifoAndTheDebugServerThreadDoesNot) {
  const std::string socket = ChildProcess::scratch("rt.sock");
  ChildProcess sim({test::kStride, "run", test::kHipScene, "--seconds", "60", "--lola", socket},
                   "rt_sim");
  ASSERT_TRUE(test::wait_for_file(socket, 60)) << sim.err();
  ChildProcess robot({test::kStrideRobot, "--config", test::kHipConfig, "--lola", socket, "--debug",
                      "127.0.0.1:0", "--rt-priority", "10"},
                     "rt_robot");
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  int threads = 0;
  for (const auto& t :
       std::filesystem::directory_iterator("/proc/" + std::to_string(robot.pid()) + "/task")) {
    const std::string tid = t.path().filename();
    const ThreadPolicy p = policy_of(robot.pid(), tid);
    ++threads;
    if (tid == std::to_string(robot.pid())) {
      EXPECT_EQ(p.policy, 1) << "the loop thread";
      EXPECT_EQ(p.rt_priority, 10);
    } else {
      EXPECT_EQ(p.policy, 0) << "thread " << tid;
    }
  }
  EXPECT_GE(threads, 2) << "the loop and the debug server's thread";
  robot.signal(SIGTERM);
  ASSERT_EQ(robot.wait_for(20), 0) << robot.err();
  sim.signal(SIGKILL);
}

TEST(RtPriority, OutOfRangeIsOneLineAndNothingRuns) {
  for (const std::string bad : {"0", "100", "high"}) {
    ChildProcess robot({test::kStrideRobot, "--config", test::kHipConfig, "--lola",
                        ChildProcess::scratch("none.sock"), "--rt-priority", bad},
                       "rt_bad");
    ASSERT_EQ(robot.wait_for(20), 1) << robot.err();
    const std::string err = robot.err();
    EXPECT_NE(err.find("stride robot: --rt-priority (a SCHED_FIFO priority)"), std::string::npos)
        << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  }
}

}  // namespace
}  // namespace stride
