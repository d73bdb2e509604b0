#include "robot/debug/log_directory.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include <openssl/evp.h>

#include "robot/core/error.hpp"
#include "robot/core/one_line.hpp"
#include "robot/debug/socket_io.hpp"

namespace stride::debug {

namespace {
using Digest = std::unique_ptr<EVP_MD_CTX, void (*)(EVP_MD_CTX*)>;

Digest sha256_context() {
  Digest ctx(EVP_MD_CTX_new(), EVP_MD_CTX_free);
  if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1)
    throw Error("SHA-256 unavailable (OpenSSL)");
  return ctx;
}

std::string finish(const Digest& ctx) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  EVP_DigestFinal_ex(ctx.get(), digest, &length);
  return std::string(reinterpret_cast<const char*>(digest), length);
}

// SHA-256 of the first `limit` bytes of an open file.
std::string sha256_of(int fd, std::uint64_t limit, const std::string& name) {
  const Digest ctx = sha256_context();
  char buffer[65536];
  for (std::uint64_t at = 0; at < limit;) {
    const ssize_t n = ::pread(fd, buffer, std::min<std::uint64_t>(sizeof buffer, limit - at),
                              static_cast<off_t>(at));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw Error("log '" + name + "': " + std::strerror(errno));
    if (n == 0) break;
    EVP_DigestUpdate(ctx.get(), buffer, static_cast<std::size_t>(n));
    at += static_cast<std::uint64_t>(n);
  }
  return finish(ctx);
}

std::uint64_t size_of(int fd, const std::string& name) {
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw Error("log '" + name + "': " + std::strerror(errno));
  return static_cast<std::uint64_t>(st.st_size);
}
}  // namespace

std::string LogDirectory::path_of(const std::string& name) const {
  bool ok = !name.empty() && name.size() <= 100 && name[0] != '.' && name.ends_with(".log") &&
            name.size() > 4;
  for (char c : name)
    ok = ok && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                c == '.' || c == '_' || c == '-');
  if (!ok)
    throw Error("log file '" + one_line(name) +
                "': expected a plain name of letters, digits, '.', '_', '-' ending in '.log' (the "
                "robot keeps its logs in its log directory)");
  return dir_ + "/" + name;
}

std::string LogDirectory::create(const std::string& name) {
  const std::string path = path_of(name);
  Fd fd(::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644));
  if (!fd && errno == EEXIST)
    throw Error("log '" + name +
                "' already exists in the robot's log directory: logs are never overwritten "
                "(choose another name)");
  if (!fd) throw Error("log '" + name + "': cannot create it: " + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) throw Error("log '" + name + "': " + std::strerror(errno));
  created_[name] = {st.st_dev, st.st_ino};
  return path;
}

void LogDirectory::discard(const std::string& name) {
  if (created_.erase(name) > 0) ::unlink(path_of(name).c_str());
}

int LogDirectory::open_served(const std::string& name) const {
  const std::string path = path_of(name);
  const auto it = created_.find(name);
  // O_NONBLOCK: a FIFO put in its place must not stall the server thread in open().
  const int flags = O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC;
  Fd fd(it == created_.end() ? -1 : ::open(path.c_str(), flags));
  struct stat st {};
  // Replaced since (removed, renamed over, a link put there): not ours any more.
  if (!fd || ::fstat(fd.get(), &st) != 0 || st.st_dev != it->second.device ||
      st.st_ino != it->second.inode || !S_ISREG(st.st_mode))
    throw Error("log '" + name +
                "': not a log this robot recorded since it started (only those are served)");
  return fd.release();
}

LogDirectory::Info LogDirectory::info(const std::string& name) const {
  const Fd fd(open_served(name));
  Info i;
  i.size = size_of(fd.get(), name);
  i.sha256 = sha256_of(fd.get(), i.size, name);  // a log being recorded grows: its first `size`
  return i;
}

std::string LogDirectory::read(const std::string& name, std::uint64_t offset, std::uint64_t length,
                               std::uint64_t& size) const {
  const Fd fd(open_served(name));
  size = size_of(fd.get(), name);
  if (offset > size)
    throw Error("log '" + name + "': offset " + std::to_string(offset) + " is past its end (" +
                std::to_string(size) + " bytes)");
  std::string out(std::min(length, size - offset), '\0');
  std::size_t got = 0;
  while (got < out.size()) {
    const ssize_t n =
        ::pread(fd.get(), out.data() + got, out.size() - got, static_cast<off_t>(offset + got));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw Error("log '" + name + "': " + std::strerror(errno));
    if (n == 0) break;
    got += static_cast<std::size_t>(n);
  }
  out.resize(got);
  return out;
}

std::string file_sha256(const std::string& path, std::uint64_t limit) {
  const Fd fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (!fd) throw Error("log '" + path + "': " + std::strerror(errno));
  return sha256_of(fd.get(), limit, path);
}

}  // namespace stride::debug
