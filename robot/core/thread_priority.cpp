#include "robot/core/thread_priority.hpp"

#include <pthread.h>
#include <sched.h>

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

void set_normal_priority() {
  sched_param p{};
  p.sched_priority = 0;
  pthread_setschedparam(pthread_self(), SCHED_OTHER, &p);  // already normal unless inherited
}

}  // namespace stride
