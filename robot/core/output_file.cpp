#include "robot/core/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "robot/core/error.hpp"

namespace stride {
namespace {

namespace fs = std::filesystem;

// Distinct temporaries for outputs written at once by threads of one process.
std::atomic<unsigned> temp_counter{0};

std::string temp_name_for(const std::string& path) {
  const fs::path p(path);
  const std::string name = "." + p.filename().string() + ".part-" + std::to_string(getpid()) + "-" +
                           std::to_string(temp_counter++);
  return (p.parent_path() / name).string();
}

}  // namespace

OutputFile::OutputFile(std::string path, Mode mode) : path_(std::move(path)) {
  if (path_.empty()) throw Error("cannot write '': expected a file name");
  struct stat st {};
  const bool exists = ::stat(path_.c_str(), &st) == 0;
  if (exists && S_ISDIR(st.st_mode)) throw Error("cannot write '" + path_ + "': is a directory");
  // A device or FIFO cannot be replaced by renaming; it is written as it stands.
  const bool direct = mode == Mode::Stream || (exists && !S_ISREG(st.st_mode));
  if (!direct) temp_ = temp_name_for(path_);
  const std::string& target = direct ? path_ : temp_;
  const int flags = O_WRONLY | O_CREAT | O_CLOEXEC | (direct ? O_TRUNC : O_EXCL);
  const int fd = ::open(target.c_str(), flags, 0666);
  if (fd < 0) fail("", errno);
  file_ = ::fdopen(fd, "wb");
  if (!file_) {
    const int err = errno;
    ::close(fd);
    fail("", err);
  }
}

OutputFile::~OutputFile() {
  discard();
}

void OutputFile::discard() noexcept {
  if (file_) std::fclose(file_);
  file_ = nullptr;
  if (!temp_.empty()) ::unlink(temp_.c_str());
  temp_.clear();
}

void OutputFile::fail(const std::string& what, int err) {
  failed_ = true;
  discard();
  throw Error("cannot write '" + path_ + "'" + what + ": " + std::strerror(err));
}

void OutputFile::write(std::string_view bytes) {
  if (!file_) throw Error("cannot write '" + path_ + "': the file is closed");
  errno = 0;
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size())
    fail("", errno ? errno : EIO);
}

void OutputFile::flush() {
  if (!file_) throw Error("cannot write '" + path_ + "': the file is closed");
  errno = 0;
  if (std::fflush(file_) != 0) fail("", errno ? errno : EIO);
}

void OutputFile::commit() {
  flush();
  std::FILE* f = file_;
  file_ = nullptr;
  errno = 0;
  if (std::fclose(f) != 0) fail(" (on close)", errno ? errno : EIO);
  if (temp_.empty()) return;
  if (std::rename(temp_.c_str(), path_.c_str()) != 0) fail("", errno);
  temp_.clear();
}

void write_file(const std::string& path, std::string_view contents) {
  OutputFile f(path);
  f.write(contents);
  f.commit();
}

void copy_file_checked(const std::string& from, const std::string& to) {
  std::FILE* in = std::fopen(from.c_str(), "rb");
  if (!in) throw Error("cannot read '" + from + "': " + std::strerror(errno));
  struct Closer {
    std::FILE* f;
    ~Closer() { std::fclose(f); }
  } closer{in};
  OutputFile out(to);
  std::string buf(1 << 16, '\0');
  while (const std::size_t n = std::fread(buf.data(), 1, buf.size(), in))
    out.write(std::string_view(buf.data(), n));
  if (std::ferror(in)) throw Error("cannot read '" + from + "': read failed");
  out.commit();
}

}  // namespace stride
