#pragma once
// Ctrl-C (SIGINT) and SIGTERM as a request to stop a long command cleanly, so that it can still
// write the report of what it did. While a flag is alive the signals set it instead of ending
// the process; a second Ctrl-C ends the process as usual.
namespace stride::console {

class InterruptFlag {
 public:
  InterruptFlag();   // installs the handlers
  ~InterruptFlag();  // restores the previous ones
  InterruptFlag(const InterruptFlag&) = delete;
  InterruptFlag& operator=(const InterruptFlag&) = delete;

  bool raised() const;
  // The signal that raised it (SIGINT or SIGTERM), 0 if none.
  int signal() const;
};

}  // namespace stride::console
