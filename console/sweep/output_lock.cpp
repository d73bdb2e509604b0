#include "console/sweep/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "robot/core/error.hpp"

namespace stride::sweep {

OutputLock::OutputLock(const std::string& dir) {
  const std::string path = dir + "/.lock";
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw Error("cannot write '" + path + "': " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int why = errno;
    char pid[32] = {};
    const ssize_t n = ::pread(fd_, pid, sizeof pid - 1, 0);
    ::close(fd_);
    fd_ = -1;
    if (why != EWOULDBLOCK) throw Error("cannot lock '" + path + "': " + std::strerror(why));
    throw Error("--out: '" + dir + "' is in use by another sweep (pid " +
                (n > 0 ? std::string(pid, static_cast<std::size_t>(n)) : std::string("unknown")) +
                ", holding " + path + "): wait for it to end, or choose another --out");
  }
  const std::string mine = std::to_string(::getpid());  // for the message of the one refused
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, mine.data(), mine.size(), 0) < 0) {
    // the pid is a courtesy: the lock itself is held
  }
}

OutputLock::~OutputLock() {
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace stride::sweep
