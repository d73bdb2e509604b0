#pragma once
// One sweep at a time in an output folder: an exclusive flock on <dir>/.lock, held while the
// sweep writes there. A second sweep (a second --resume) on the folder is refused in one line
// instead of running the same walks again; the kernel drops the lock when the holder ends,
// however it ends, so a killed sweep never leaves the folder locked.
#include <string>

namespace stride::sweep {

class OutputLock {
 public:
  // Takes the lock without waiting; throws stride::Error naming the folder and the holder's pid.
  explicit OutputLock(const std::string& dir);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace stride::sweep
