#include "robot/core/thread_priority.hpp"

#include <pthread.h>
#include <sched.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "robot/core/error.hpp"
#include "robot/core/number_text.hpp"

namespace stride {

int parse_realtime_priority(const std::string& text, const std::string& flag) {
  const int low = sched_get_priority_min(SCHED_FIFO), high = sched_get_priority_max(SCHED_FIFO);
  return static_cast<int>(parse_integer(text, flag + " (a SCHED_FIFO priority)", low, high));
}

void set_realtime_priority(int priority, const std::string& who) {
  sched_param p{};
  p.sched_priority = priority;
  // Reset on fork: threads and processes it starts come up time-shared, not at the loop's level.
  if (sched_setscheduler(0, SCHED_FIFO | SCHED_RESET_ON_FORK, &p) != 0)  // 0: this thread
    throw Error(who + ": cannot run the control loop under SCHED_FIFO priority " +
                std::to_string(priority) + " (" + std::strerror(errno) +
                "; it needs root, CAP_SYS_NICE or an rtprio limit in limits.conf)");
}

void set_cpu_affinity(const std::vector<int>& cpus, const std::string& who) {
  const int n = static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN));
  cpu_set_t set;
  CPU_ZERO(&set);
  for (int c : cpus) {
    if (c < 0 || c >= n)
      throw Error(who + ": CPU " + std::to_string(c) + " does not exist (this machine has 0.." +
                  std::to_string(n - 1) + ")");
    CPU_SET(c, &set);
  }
  if (const int e = pthread_setaffinity_np(pthread_self(), sizeof set, &set); e != 0)
    throw Error(who + ": cannot run on the CPUs asked (" + std::strerror(e) + ")");
}

std::vector<int> cpus_except(int cpu) {
  std::vector<int> rest;
  for (int c = 0; c < static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN)); ++c)
    if (c != cpu) rest.push_back(c);
  return rest.empty() ? std::vector<int>{cpu} : rest;  // one CPU: nowhere else to go
}

void set_normal_priority() {
  sched_param p{};
  p.sched_priority = 0;
  pthread_setschedparam(pthread_self(), SCHED_OTHER, &p);  // already normal unless inherited
}

}  // namespace stride
