#include "robot/app/stop_signals.hpp"

#include <ctime>

namespace stride {

StopSignals::StopSignals() {
  sigemptyset(&set_);
  sigaddset(&set_, SIGINT);
  sigaddset(&set_, SIGTERM);
  sigprocmask(SIG_BLOCK, &set_, &previous_);
}

StopSignals::~StopSignals() {
  sigprocmask(SIG_SETMASK, &previous_, nullptr);
}

bool StopSignals::requested() {
  if (signal_ != 0) return true;
  const timespec now{0, 0};
  const int s = sigtimedwait(&set_, nullptr, &now);
  if (s > 0) signal_ = s;
  return signal_ != 0;
}

}  // namespace stride
