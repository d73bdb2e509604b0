#include "robot/core/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <new>

#include "robot/core/error.hpp"

namespace stride {
namespace {

const char* kind_of(mode_t m) {
  if (S_ISDIR(m)) return "a directory";
  if (S_ISCHR(m)) return "a character device";
  if (S_ISBLK(m)) return "a block device";
  if (S_ISFIFO(m)) return "a FIFO";
  if (S_ISSOCK(m)) return "a socket";
  return "not a plain file";
}

std::string size_text(std::uint64_t bytes) {
  if (bytes >= (1ull << 30) && bytes % (1ull << 30) == 0)
    return std::to_string(bytes >> 30) + " GiB";
  if (bytes >= (1ull << 20) && bytes % (1ull << 20) == 0)
    return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

std::string stat_problem(const struct stat& st, std::uint64_t max_bytes) {
  if (!S_ISREG(st.st_mode)) return std::string("not a regular file (") + kind_of(st.st_mode) + ")";
  if (static_cast<std::uint64_t>(st.st_size) > max_bytes)
    return std::to_string(st.st_size) + " bytes, over the limit of " + size_text(max_bytes);
  return "";
}

// Closes the descriptor on every way out.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string input_file_problem(const std::string& path, std::uint64_t max_bytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::strerror(errno);
  return stat_problem(st, max_bytes);
}

std::string read_input_file(const std::string& path, std::uint64_t max_bytes,
                            const std::string& what) {
  const auto fail = [&](const std::string& reason) {
    return InputError(what + " '" + path + "': " + reason);
  };
  // O_NONBLOCK: opening a FIFO must not wait for a writer before fstat can refuse it.
  Fd f{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (f.fd < 0) throw fail(std::string("cannot open: ") + std::strerror(errno));
  struct stat st {};
  if (::fstat(f.fd, &st) != 0) throw fail(std::strerror(errno));
  if (const std::string problem = stat_problem(st, max_bytes); !problem.empty())
    throw fail(problem);
  std::string data;
  try {
    data.resize(static_cast<std::size_t>(st.st_size));
  } catch (const std::bad_alloc&) {
    throw fail("out of memory reading " + std::to_string(st.st_size) + " bytes");
  }
  std::size_t got = 0;
  while (got < data.size()) {
    const ssize_t n = ::read(f.fd, data.data() + got, data.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw fail(std::string("read failed: ") + std::strerror(errno));
    if (n == 0) break;  // shrank while reading: what is there is the file
    got += static_cast<std::size_t>(n);
  }
  data.resize(got);
  return data;
}

}  // namespace stride
