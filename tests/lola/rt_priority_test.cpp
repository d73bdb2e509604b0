// `stride robot --rt-priority --cpu`: the control loop under SCHED_FIFO on one CPU as on the NAO,
// every other thread (the debug server's) time-shared on any CPU; a bad priority or CPU is a
// one-line error before anything runs.
#include <sched.h>
#include <unistd.h>

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

// The CPUs thread `tid` may run on.
std::vector<int> cpus_of(int tid) {
  cpu_set_t set;
  CPU_ZERO(&set);
  std::vector<int> cpus;
  if (sched_getaffinity(tid, sizeof set, &set) != 0) return cpus;
  for (int c = 0; c < CPU_SETSIZE; ++c)
    if (CPU_ISSET(c, &set)) cpus.push_back(c);
  return cpus;
}

TEST(RtPriority, RobotLoopRunsUnderFifoOnItsCpuAndTheDebugServerThreadDoesNot) {
  const int cpus = static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN));
  const int loop_cpu = cpus - 1;
  const std::string socket = ChildProcess::scratch("rt.sock");
  ChildProcess sim({test::kStride, "run", test::kHipScene, "--seconds", "60", "--lola", socket},
                   "rt_sim");
  ASSERT_TRUE(test::wait_for_file(socket, 60)) << sim.err();
  ChildProcess robot({test::kStrideRobot, "--config", test::kHipConfig, "--lola", socket, "--debug",
                      "127.0.0.1:0", "--rt-priority", "10", "--cpu", std::to_string(loop_cpu)},
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
      EXPECT_EQ(cpus_of(std::stoi(tid)), std::vector<int>{loop_cpu});
    } else {
      EXPECT_EQ(p.policy, 0) << "thread " << tid;
      EXPECT_EQ(cpus_of(std::stoi(tid)).size(), static_cast<std::size_t>(cpus)) << tid;
    }
  }
  EXPECT_GE(threads, 2) << "the loop and the debug server's thread";
  robot.signal(SIGTERM);
  ASSERT_EQ(robot.wait_for(20), 0) << robot.err();
  sim.signal(SIGKILL);
}

TEST(RtPriority, OutOfRangeIsOneLineAndNothingRuns) {
  const std::string no_cpu = std::to_string(sysconf(_SC_NPROCESSORS_ONLN));
  const std::pair<std::vector<std::string>, std::string> cases[] = {
      {{"--rt-priority", "0"}, "stride robot: --rt-priority (a SCHED_FIFO priority)"},
      {{"--rt-priority", "100"}, "stride robot: --rt-priority (a SCHED_FIFO priority)"},
      {{"--rt-priority", "high"}, "stride robot: --rt-priority (a SCHED_FIFO priority)"},
      {{"--cpu", "-1"}, "stride robot: --cpu"},
      {{"--cpu", no_cpu}, "stride robot: --cpu: CPU " + no_cpu + " does not exist"}};
  for (const auto& [flags, message] : cases) {
    const std::string socket = ChildProcess::scratch("bad.sock");
    ChildProcess sim({test::kStride, "run", test::kHipScene, "--seconds", "60", "--lola", socket},
                     "rt_bad_sim");
    ASSERT_TRUE(test::wait_for_file(socket, 60)) << sim.err();
    std::vector<std::string> argv{test::kStrideRobot, "--config", test::kHipConfig, "--lola",
                                  socket};
    argv.insert(argv.end(), flags.begin(), flags.end());
    ChildProcess robot(argv, "rt_bad");
    ASSERT_EQ(robot.wait_for(20), 1) << robot.err();
    const std::string err = robot.err();
    EXPECT_NE(err.find(message), std::string::npos) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    sim.signal(SIGKILL);
  }
}

}  // namespace
}  // namespace stride
