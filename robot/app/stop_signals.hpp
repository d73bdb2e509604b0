#pragma once
// SIGINT and SIGTERM as a request to stop between frames: they are blocked while the object
// lives and looked for (without waiting) when asked, so no handler or global flag is needed and
// the frame in progress always completes.
#include <csignal>

namespace stride {

class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // True once SIGINT or SIGTERM arrived (the first one is remembered).
  bool requested();
  int signal() const { return signal_; }

 private:
  sigset_t set_{}, previous_{};
  int signal_ = 0;
};

}  // namespace stride
